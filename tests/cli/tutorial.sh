#!/usr/bin/env bash
# docs/tutorial.md's steps: every examples/tutorial scene renders (at a thumbnail size) without
# a warning, is laid out as `rts fmt` lays it out, and the tutorial shows each one's source
# file and picture.
source "$(dirname "$0")/lib.sh"

doc="$SRC/docs/tutorial.md"
count=0
for scene in "$SRC"/examples/tutorial/*.rts; do
  name=$(basename "$scene" .rts)
  count=$((count + 1))
  read -r -a extra <<< "$(sed -n 's|^[[:space:]]*// args:||p' "$scene" | tr '\n' ' ')"
  expect_exit 0 "render $name" -- "$RTS" render "$scene" -o "$TMP/$name.png" --width 40 --height 30 \
      --samples 1 --no-progress "${extra[@]}"
  [[ -s "$TMP/$name.png" ]] || { echo "FAIL: $name.png was not written"; FAILS=$((FAILS + 1)); }
  if grep -q "warning:" "$TMP/err"; then echo "FAIL: $name warns:"; cat "$TMP/err"; FAILS=$((FAILS + 1)); fi
  expect_grep "$doc" "examples/tutorial/$name.rts" "the tutorial names $name.rts"
  expect_grep "$doc" "images/tutorial/$name.png" "the tutorial shows $name.png"
  [[ -s "$SRC/docs/images/tutorial/$name.png" ]] || { echo "FAIL: docs/images/tutorial/$name.png is missing"; FAILS=$((FAILS + 1)); }
done
# The steps are laid out as `rts fmt` lays them out (they are what a newcomer copies).
expect_exit 0 "the tutorial scenes are formatted" -- "$RTS" fmt --check "$SRC"/examples/tutorial/*.rts
[[ $count -ge 9 ]] || { echo "FAIL: only $count tutorial scenes"; FAILS=$((FAILS + 1)); }
finish
