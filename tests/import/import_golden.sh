#!/usr/bin/env bash
# Each course scene in tests/golden/import translates to exactly NAME.rts (and its
# NAME_meshN.obj files) beside it; each expected scene evaluates and renders. The inputs are
# translated in a copy of the folder so relative paths come out as in the goldens.
# Update on purpose with scripts/update-golden-import.
source "$(dirname "$0")/../cli/lib.sh"
golden="$SRC/tests/golden/import"
cp -r "$golden" "$TMP/work"
count=0
for input in "$golden"/*.txt "$golden"/*.scene "$golden"/*.ray; do
  [[ -f "$input" ]] || continue
  name="$(basename "${input%.*}")"
  count=$((count + 1))
  rm -f "$TMP/work/$name.rts" "$TMP/work/${name}"_mesh*.obj
  expect_exit 0 "import $name" -- "$RTS" import "$TMP/work/$(basename "$input")" -o "$TMP/work/$name.rts"
  if ! diff -u "$golden/$name.rts" "$TMP/work/$name.rts"; then
    echo "FAIL: $name.rts differs from the golden (scripts/update-golden-import $name updates it on purpose)"
    FAILS=$((FAILS + 1))
  fi
  for obj in "$golden/${name}"_mesh*.obj; do
    [[ -f "$obj" ]] || continue
    diff -u "$obj" "$TMP/work/$(basename "$obj")" || { echo "FAIL: $(basename "$obj") differs"; FAILS=$((FAILS + 1)); }
  done
  expect_exit 0 "check $name.rts" -- "$RTS" check "$golden/$name.rts"
  expect_exit 0 "render $name.rts" -- "$RTS" render "$golden/$name.rts" -o "$TMP/$name.png" --width 48 \
      --height 36 --no-progress
done
[[ $count -ge 3 ]] || { echo "FAIL: expected the three course formats, found $count scenes"; FAILS=$((FAILS + 1)); }
# Without -o the scene goes to standard output, the same text.
expect_exit 0 "import to stdout" -- "$RTS" import "$TMP/work/csci_scene.scene"
diff -q "$TMP/out" "$golden/csci_scene.rts" >/dev/null || { echo "FAIL: stdout differs from csci_scene.rts"; FAILS=$((FAILS + 1)); }
finish
