#!/usr/bin/env bash
# `rts render --watch`: a change to the scene or to a file it includes re-renders (one sample
# per pixel first, then the full render), and a change that breaks the scene reports its
# error and keeps the last good image. Every wait is bounded (10 s), and so is rts (timeout).
source "$(dirname "$0")/lib.sh"

cat > "$TMP/lamp.rts" <<'SCENE'
point_light { position = <3, 5, -4> }
SCENE
cat > "$TMP/s.rts" <<'SCENE'
include "lamp.rts"
settings { width = 24  height = 18  samples = 4 }
camera { position = <0, 1, -4>  look_at = <0, 0.5, 0> }
sphere { center = <0, 0.5, 0>  radius = 0.5 }
SCENE

# wait_for DESCRIPTION COMMAND...: retries COMMAND for up to 10 s.
wait_for() {
  local what="$1"; shift
  for _ in $(seq 100); do "$@" && return 0; sleep 0.1; done
  echo "FAIL: $what (waited 10 s); log:"; cat "$TMP/log"; FAILS=$((FAILS + 1)); return 1
}
rounds() { grep -c "watching" "$TMP/log"; }
rounds_at_least() { [[ "$(rounds)" -ge "$1" ]]; }

timeout 60 "$RTS" render --watch "$TMP/s.rts" -o "$TMP/out.png" --no-progress >"$TMP/log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null; rm -rf "$TMP"' EXIT

wait_for "the first render" rounds_at_least 1
expect_grep "$TMP/log" "out.png: 24x18, 1 spp" "a quick pass of one sample per pixel comes first"
expect_grep "$TMP/log" "out.png: 24x18, 4 spp" "then the full render"
first=$(md5sum < "$TMP/out.png")

sed -i 's/radius = 0.5/radius = 0.9/' "$TMP/s.rts"
wait_for "a render after editing the scene" rounds_at_least 2
second=$(md5sum < "$TMP/out.png")
[[ "$second" != "$first" ]] || { echo "FAIL: the image did not change with the scene"; FAILS=$((FAILS + 1)); }

# An included file is watched too (an editor's save: a new file renamed over the old one).
printf 'point_light { position = <-3, 5, -4>  color = rgb(1, 0.3, 0.3) }\n' > "$TMP/lamp.new"
mv "$TMP/lamp.new" "$TMP/lamp.rts"
wait_for "a render after editing the included file" rounds_at_least 3
third=$(md5sum < "$TMP/out.png")
[[ "$third" != "$second" ]] || { echo "FAIL: the image did not change with the included file"; FAILS=$((FAILS + 1)); }

# A change that breaks the scene: its located error, and the last good image stays.
echo 'sphere { radius = }' >> "$TMP/s.rts"
wait_for "the error of a broken edit" grep -q "s.rts:5:19: error: expected an expression" "$TMP/log"
wait_for "watching again after the error" rounds_at_least 4
[[ "$(md5sum < "$TMP/out.png")" == "$third" ]] || { echo "FAIL: a failing edit changed the image"; FAILS=$((FAILS + 1)); }
kill -0 $pid 2>/dev/null || { echo "FAIL: --watch stopped after an error"; FAILS=$((FAILS + 1)); }

# Fixing it renders again.
sed -i '$d' "$TMP/s.rts"
wait_for "a render after the fix" rounds_at_least 5
kill $pid 2>/dev/null; wait $pid 2>/dev/null

expect_exit 2 "--watch with --frames" -- "$RTS" render --watch "$TMP/s.rts" --frames 0..2 -o "$TMP/f_##.png"
expect_grep "$TMP/err" "watch" "the usage error names --watch"
finish
