#!/usr/bin/env bash
# Cost traps and feedback (issue 24): an area light without `samples` spends 16 light samples
# per pixel, not 16 per pixel sample; --stats says what the shadow rays cost; an output that
# cannot be written fails before any work; --progress=lines reports each phase as plain lines.
source "$(dirname "$0")/lib.sh"
# expect_no_grep FILE PATTERN DESCRIPTION
expect_no_grep() {
  if grep -qE -- "$2" "$1"; then echo "FAIL: $3: /$2/ found in:"; cat "$1"; FAILS=$((FAILS + 1)); fi
}

scene() {  # scene SPP LIGHT-SAMPLES-PROPERTY
  cat <<SCENE
settings { width = 16  height = 12  samples = $1 }
camera { position = <0, 2, -6>  look_at = <0, 0.6, 0> }
area_light { position = <-1.5, 5, -1.5>  u = <3, 0, 0>  v = <0, 0, 3>  $2 }
plane { normal = <0, 1, 0>  offset = 0 }
sphere { center = <0, 1.2, 0>  radius = 0.6 }
SCENE
}
# stat JSON KEY: one figure from a --stats-json file ("rays.shadow_per_pixel").
stat() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); s,k=sys.argv[2].split("."); print(d[s][k])' "$1" "$2"; }
check() {  # check DESCRIPTION ACTUAL EXPECTED
  if [[ "$2" != "$3" ]]; then echo "FAIL: $1: got $2, expected $3"; FAILS=$((FAILS + 1)); else echo "ok: $1 ($2)"; fi
}

# ---- area light samples: the default follows the pixel samples --------------------------------
for case in "1 16" "4 4" "16 1" "5 4"; do
  set -- $case
  scene "$1" "" > "$TMP/auto$1.rts"
  expect_exit 0 "auto light samples at $1 spp" -- "$RTS" render "$TMP/auto$1.rts" -o "$TMP/a.png" --stats-json "$TMP/a.json"
  check "light samples per shading point at $1 spp" "$(stat "$TMP/a.json" scene.area_light_samples)" "$2"
  check "auto samples reported" "$(stat "$TMP/a.json" scene.area_samples_auto)" "True"
done
# Written samples are kept as they are, whatever the pixel samples.
scene 4 "samples = 16" > "$TMP/given.rts"
expect_exit 0 "given light samples" -- "$RTS" render "$TMP/given.rts" -o "$TMP/g.png" --stats-json "$TMP/g.json"
check "given samples kept" "$(stat "$TMP/g.json" scene.area_light_samples)" "16"
check "given samples are not auto" "$(stat "$TMP/g.json" scene.area_samples_auto)" "False"
# What shadow rays cost: per pixel (at most samples x light samples) and their share of rays.
auto=$(stat "$TMP/a.json" rays.shadow_per_pixel); given=$(stat "$TMP/g.json" rays.shadow_per_pixel)
python3 -c "import sys; a, g = $auto, $given; sys.exit(0 if 0 < a <= 20 and 2 * a < g <= 64 else 1)" \
  && echo "ok: shadow rays per pixel, auto $auto against 4 x 16 given $given" \
  || { echo "FAIL: shadow rays per pixel: auto $auto, given $given"; FAILS=$((FAILS + 1)); }
expect_exit 0 "--stats prints the shadow cost" -- "$RTS" render "$TMP/given.rts" -o "$TMP/g.png" --stats
expect_grep "$TMP/err" "shadow_per_pixel [0-9.]+, shadow_share 0\.[0-9]+" "--stats names shadow rays per pixel and share"
expect_grep "$TMP/err" "area_light_samples 16, area_samples_auto false" "--stats names the light samples"

# ---- outputs that cannot be written fail before evaluating ------------------------------------
# The scene has an evaluation error: reaching it would mean the output was not checked first.
printf 'settings { width = 8  height = 8 }\nlet x = undefined_name\n' > "$TMP/broken.rts"
expect_exit 3 "-o in /proc" -- "$RTS" render "$TMP/broken.rts" -o /proc/rts-test.png
expect_grep "$TMP/err" "cannot write '/proc/rts-test.png': directory '/proc': it does not accept new files" \
  "/proc is named as refusing files, not as missing"
expect_no_grep "$TMP/err" "undefined_name|does not exist" "nothing was evaluated, no wrong reason"
expect_exit 3 "-o in a missing folder" -- "$RTS" render "$TMP/broken.rts" -o "$TMP/no/such/x.png"
expect_grep "$TMP/err" "directory '.*/no/such' does not exist" "a missing folder is named"
if [[ $(id -u) != 0 ]]; then  # root may write anywhere
  mkdir "$TMP/ro" && chmod 555 "$TMP/ro"
  expect_exit 3 "-o in a read-only folder" -- "$RTS" render "$TMP/broken.rts" -o "$TMP/ro/x.png"
  expect_grep "$TMP/err" "not writable" "a read-only folder is named"
fi
[[ -z "$(ls -A "$TMP" | grep rts-write-probe)" ]] || { echo "FAIL: a write probe was left"; FAILS=$((FAILS + 1)); }

# ---- --progress=lines: plain lines for logs ----------------------------------------------------
expect_exit 0 "--progress=lines" -- "$RTS" render "$TMP/given.rts" -o "$TMP/p.png" --progress=lines
expect_grep "$TMP/err" "^rts: evaluating .*given.rts: [0-9.]+s, 3 objects placed \(done\)$" "an evaluation line"
expect_grep "$TMP/err" "^rts: building the scene .*\(done\)$" "a build line"
expect_grep "$TMP/err" "^rts: rendering: done \(1 of 1\) in [0-9.]+s$" "a render line"
expect_no_grep "$TMP/err" $'\r' "no carriage returns in lines mode"
expect_exit 0 "no progress when stderr is not a terminal" -- "$RTS" render "$TMP/given.rts" -o "$TMP/p.png"
expect_no_grep "$TMP/err" "evaluating|building|rendering:" "auto mode stays quiet in a log"
expect_exit 2 "unknown --progress mode" -- "$RTS" render "$TMP/given.rts" -o "$TMP/p.png" --progress=fancy

finish
