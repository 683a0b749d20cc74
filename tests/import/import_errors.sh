#!/usr/bin/env bash
# Malformed course files are located errors (file:line:col, the line, a caret; exit 1), never
# crashes, and never replace an existing output; a missing input or an unknown format is a
# usage error (exit 2).
source "$(dirname "$0")/../cli/lib.sh"
cd "$TMP"

printf 'SBT-raytracer 1.0\nsphere { material = { diffuse = (1, 0); }; }\n' > bad_tuple.ray
expect_exit 1 "UW: a color with two components" -- "$RTS" import bad_tuple.ray
expect_grep "$TMP/err" "^bad_tuple.ray:2:33: error: expected \(x, y, z\)" "located message"
expect_grep "$TMP/err" "^ +\^" "caret line"

printf 'SBT-raytracer 1.0\nblob { }\n' > unknown.ray
expect_exit 1 "UW: an unknown object" -- "$RTS" import unknown.ray
expect_grep "$TMP/err" "unknown object 'blob'" "names the object"

printf 'SBT-raytracer 1.0\npolymesh { points = ((0,0,0),(1,0,0)); faces = ((0,1,5)); }\n' > bad_face.ray
expect_exit 1 "UW: a face index out of range" -- "$RTS" import bad_face.ray
expect_grep "$TMP/err" "face index 5 out of range \(2 points\)" "names the index"

printf 'SBT-raytracer 1.0\nsphere { material = { diffuse = (1, 0, 0); }\n' > open.ray
expect_exit 1 "UW: an unclosed block" -- "$RTS" import open.ray
expect_grep "$TMP/err" "unexpected end of file" "says where the file ended"

printf 'PerspectiveCamera {\n    center 0 0 10\n    angle thirty\n}\n' > bad_number.txt
expect_exit 1 "MIT: a word where a number belongs" -- "$RTS" import bad_number.txt
expect_grep "$TMP/err" "^bad_number.txt:3:11: error: expected a number, got 'thirty'" "located message"

printf 'Group {\n  numObjects 1\n  MaterialIndex 3\n  Sphere { center 0 0 0 radius 1 }\n}\n' > bad_index.txt
expect_exit 1 "MIT: a material index without materials" -- "$RTS" import bad_index.txt
expect_grep "$TMP/err" "MaterialIndex 3 but only 0 materials" "names the index"

printf '2\namb: 0 0 0\nlight\npos: 0 0 0\ncol: 1 1 1\n' > short.scene
expect_exit 1 "CSCI 420: fewer objects than announced" -- "$RTS" import short.scene
expect_grep "$TMP/err" "unexpected end of file" "says the file ended"

printf '1\namb: 0 0 0\ncube\n' > unknown.scene
expect_exit 1 "CSCI 420: an unknown object" -- "$RTS" import unknown.scene
expect_grep "$TMP/err" "^unknown.scene:3:1: error: unknown object 'cube'" "located message"

{ printf 'SBT-raytracer 1.0\n'; for i in $(seq 5000); do printf 'translate(0, 0, 0, '; done; printf 'sphere {}'; } > deep.ray
expect_exit 1 "UW: nesting deeper than the limit is an error, not a stack overflow" -- "$RTS" import deep.ray
expect_grep "$TMP/err" "nested more than 256 levels deep" "names the limit"
{ for i in $(seq 5000); do printf 'Group { '; done; } > deep.txt
expect_exit 1 "MIT: deeply nested groups" -- "$RTS" import deep.txt
expect_grep "$TMP/err" "nested more than 256 levels deep" "names the limit"

echo "keep me" > existing.rts
expect_exit 1 "a failed import keeps an existing output" -- "$RTS" import unknown.scene -o existing.rts
expect_grep existing.rts "keep me" "the output is untouched"

printf 'hello world\n' > mystery.dat
expect_exit 1 "an unrecognisable format" -- "$RTS" import mystery.dat
expect_grep "$TMP/err" "cannot tell the format" "says so"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > tri.obj
expect_exit 1 "an OBJ mesh handed to rts import" -- "$RTS" import tri.obj
expect_grep "$TMP/err" "'tri.obj' is a Wavefront OBJ mesh, not a scene: .*mesh \\{ file = \"tri.obj\" \\}" "says what it read and what to do"
printf 'sphere { radius = 1 }\n' > already.rts
expect_exit 1 "an rts scene handed to rts import" -- "$RTS" import already.rts -o out.rts
expect_grep "$TMP/err" "already an rts scene: render it with rts render" "says so"
expect_exit 2 "a missing input" -- "$RTS" import no_such_file.ray
expect_exit 2 "an unknown --format" -- "$RTS" import short.scene --format vrml
finish
