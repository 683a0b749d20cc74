#!/usr/bin/env bash
# `rts fmt`: rewrites files in place keeping the syntax tree, --check lists what would change,
# '-' filters standard input, and a file that does not parse is left byte for byte as it was.
# (The sweep over every scene in the repository is tests/parser/test_format.cpp.)
source "$(dirname "$0")/lib.sh"

cat > "$TMP/messy.rts" <<'SCENE'
// a comment that stays
let  r=0.5   // radius
camera{position=<0,1,-4>  look_at=<0,0.5,0>}
  sphere {center=<0, r,0>
radius = r }
SCENE
cat > "$TMP/tidy.rts" <<'SCENE'
// a comment that stays
let r = 0.5  // radius
camera { position = <0, 1, -4>  look_at = <0, 0.5, 0> }
sphere { center = <0, r, 0>
    radius = r }
SCENE
printf 'sphere { radius = 1\n' > "$TMP/broken.rts"
cp "$TMP/messy.rts" "$TMP/messy.orig"; cp "$TMP/broken.rts" "$TMP/broken.orig"
"$RTS" parse "$TMP/messy.rts" > "$TMP/tree.before"

expect_exit 1 "--check on a file that would change" -- "$RTS" fmt --check "$TMP/messy.rts" "$TMP/tidy.rts"
expect_grep "$TMP/out" "messy.rts" "--check lists the file that would change"
if grep -q "tidy.rts" "$TMP/out"; then echo "FAIL: --check listed a tidy file"; FAILS=$((FAILS + 1)); fi
cmp -s "$TMP/messy.rts" "$TMP/messy.orig" || { echo "FAIL: --check changed the file"; FAILS=$((FAILS + 1)); }

expect_exit 0 "stdin to stdout" -- bash -c "\"$RTS\" fmt - < \"$TMP/messy.rts\""
cmp -s "$TMP/out" "$TMP/tidy.rts" || { echo "FAIL: fmt - output:"; cat "$TMP/out"; FAILS=$((FAILS + 1)); }

expect_exit 1 "a good file and a broken one" -- "$RTS" fmt "$TMP/messy.rts" "$TMP/broken.rts"
expect_grep "$TMP/err" "broken.rts:1:[0-9]+: error: " "the syntax error is located"
cmp -s "$TMP/broken.rts" "$TMP/broken.orig" || { echo "FAIL: the broken file was touched"; FAILS=$((FAILS + 1)); }
cmp -s "$TMP/messy.rts" "$TMP/tidy.rts" || { echo "FAIL: in place:"; cat "$TMP/messy.rts"; FAILS=$((FAILS + 1)); }
"$RTS" parse "$TMP/messy.rts" > "$TMP/tree.after"
cmp -s "$TMP/tree.before" "$TMP/tree.after" || { echo "FAIL: the syntax tree changed"; FAILS=$((FAILS + 1)); }
ls "$TMP" | grep -q tmp && { echo "FAIL: a temporary file was left behind"; FAILS=$((FAILS + 1)); }

expect_exit 0 "--check on formatted files" -- "$RTS" fmt --check "$TMP/messy.rts" "$TMP/tidy.rts"
expect_exit 1 "--check on stdin that would change" -- bash -c "\"$RTS\" fmt --check - < \"$TMP/messy.orig\""
expect_exit 1 "broken stdin" -- bash -c "\"$RTS\" fmt - < \"$TMP/broken.rts\""
[[ -s "$TMP/out" ]] && { echo "FAIL: broken stdin wrote output"; FAILS=$((FAILS + 1)); }
expect_exit 1 "a missing file" -- "$RTS" fmt "$TMP/nope.rts"
expect_grep "$TMP/err" "nope.rts" "the missing file is named"
expect_exit 2 "no file" -- "$RTS" fmt

# Through the program too: every example and library file keeps its `rts parse` output.
for f in "$SRC"/examples/*.rts "$SRC"/stdlib/*.rts; do
  "$RTS" parse "$f" > "$TMP/a" 2>&1
  "$RTS" fmt - < "$f" > "$TMP/f.rts" && "$RTS" parse "$TMP/f.rts" > "$TMP/b" 2>&1
  cmp -s "$TMP/a" "$TMP/b" || { echo "FAIL: rts parse differs after fmt: $f"; FAILS=$((FAILS + 1)); }
done
# And a generated scene (the parser benchmark's: materials, transforms, `with`, comments).
python3 "$SRC/bench/gen_scene.py" --objects 3000 --rts "$TMP/gen.rts" >/dev/null
"$RTS" parse "$TMP/gen.rts" > "$TMP/a" 2>&1
"$RTS" fmt - < "$TMP/gen.rts" > "$TMP/gen_f.rts" && "$RTS" parse "$TMP/gen_f.rts" > "$TMP/b" 2>&1
cmp -s "$TMP/a" "$TMP/b" || { echo "FAIL: rts parse differs after fmt: the generated scene"; FAILS=$((FAILS + 1)); }
cmp -s "$TMP/gen.rts" "$TMP/gen_f.rts" && { echo "FAIL: the generated scene needed no formatting (the test checks nothing)"; FAILS=$((FAILS + 1)); }
expect_exit 0 "formatting the formatted generated scene changes nothing" -- "$RTS" fmt --check "$TMP/gen_f.rts"
finish
