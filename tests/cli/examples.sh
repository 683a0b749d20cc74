#!/usr/bin/env bash
# Every example scene parses, evaluates and renders (at a thumbnail size, so the suite stays
# fast), the convergence scenes included; the include-only file materials.rts is evaluated
# through showcase.rts.
source "$(dirname "$0")/lib.sh"

for scene in "$SRC"/examples/*.rts "$SRC"/examples/convergence/*.rts; do
  name=$(basename "$scene" .rts)
  expect_exit 0 "parse $name" -- "$RTS" parse --quiet "$scene"
  expect_exit 0 "check $name" -- "$RTS" check "$scene"
  [[ "$name" == materials ]] && continue
  expect_exit 0 "render $name" -- "$RTS" render "$scene" -o "$TMP/$name.png" --width 48 --height 36 \
      --samples 1 --no-progress
  [[ -s "$TMP/$name.png" ]] || { echo "FAIL: $name.png was not written"; FAILS=$((FAILS + 1)); }
done
# The animation example: two of its frames (the whole animation is docs/scale-out.md's).
expect_exit 0 "parse bounce" -- "$RTS" parse --quiet "$SRC/examples/cluster/bounce.rts"
expect_exit 0 "render bounce, frames 10..11" -- "$RTS" render "$SRC/examples/cluster/bounce.rts" --frames 10..11 \
    -o "$TMP/bounce_##.png" --width 48 --height 36 --samples 1 --no-progress
[[ -s "$TMP/bounce_10.png" && -s "$TMP/bounce_11.png" ]] || { echo "FAIL: bounce frames were not written"; FAILS=$((FAILS + 1)); }
expect_exit 0 "showcase with a define" -- "$RTS" check "$SRC/examples/showcase.rts" -D quality=2
expect_grep "$TMP/out" "mesh" "quality=2 adds the torus mesh"
finish
