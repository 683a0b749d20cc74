#!/usr/bin/env bash
# `rts check` and `rts eval` end to end: output, -D and -I flags, limits, exit codes.
# Usage: cli_check_eval.sh RTS_BINARY SOURCE_DIR
set -uo pipefail
rts="$1"
src="$2"
golden="$src/tests/golden/eval"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# expect CODE CMD...: runs CMD, output in $tmp/out and $tmp/err, checks the exit code.
expect() {
  local want="$1"; shift
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  [[ $got -eq $want ]] || fail "exit $got (wanted $want): $*; stderr: $(head -3 "$tmp/err")"
}
contains() { grep -qF -- "$2" "$1" || fail "$1 lacks '$2': $(head -5 "$1")"; }

# rts eval prints exactly the golden dump (the in-process golden test compares the same).
expect 0 "$rts" eval "$golden/loops.rts"
diff -u "$golden/loops.dump" "$tmp/out" >/dev/null || fail "rts eval loops.rts differs from loops.dump"

# rts check summarises.
expect 0 "$rts" check "$golden/language_example.rts" -D quality=2
contains "$tmp/out" "triangles:  8 (in 1 mesh)"
contains "$tmp/out" "camera:     perspective at <0, 6, -14>"
contains "$tmp/out" "image:      800x600, 4 samples per pixel, max depth 6"
contains "$tmp/out" "evaluated in"
expect 0 "$rts" check "$golden/language_example.rts"
contains "$tmp/out" "triangles:  0 (in 0 meshes)"   # quality stays 1: no mesh

# A scene modelled at 1e-13 units shows its bounds and camera (zeroed as rounding noise before).
printf 'camera { position = <0, 1e-13, -4e-13>  look_at = <0, 0, 0> }\nsphere { radius = 1e-13 }\n' >"$tmp/tiny.rts"
expect 0 "$rts" check "$tmp/tiny.rts"
contains "$tmp/out" "bounds:     <-1e-13, -1e-13, -1e-13> .. <1e-13, 1e-13, 1e-13>"
contains "$tmp/out" "camera:     perspective at <0, 1e-13, -4e-13> looking at <0, 0, 0>"
printf 'sphere { center = <0, 1e-13, 2e-13>  radius = 1 }\n' >"$tmp/tiny_eval.rts"
expect 0 "$rts" eval "$tmp/tiny_eval.rts"
contains "$tmp/out" "sphere center <0, 1e-13, 2e-13> radius 1"
printf 'sphere { radius = 3e-13 }\nsphere { radius = 1 } scale 1e-13 translate <0, 2e-13, 0>\n' >"$tmp/tiny_len.rts"
expect 0 "$rts" eval "$tmp/tiny_len.rts"
contains "$tmp/out" "sphere center <0, 0, 0> radius 3e-13"
contains "$tmp/out" "transform [1e-13 0 0 0; 0 1e-13 0 2e-13; 0 0 1e-13 0]"

# -D: a define that matches nothing warns; a malformed one is a usage error.
expect 0 "$rts" check "$golden/loops.rts" -D nothing=1
contains "$tmp/err" "warning: define 'nothing=1' matches no top-level 'let nothing'"
expect 2 "$rts" check "$golden/loops.rts" -D novalue
expect 2 "$rts" eval "$golden/loops.rts" -D 1x=2
# A define whose value is not an expression is a language error pointing into the define.
expect 1 "$rts" check "$golden/defines.rts" -D 'quality=('
contains "$tmp/err" "<define quality>:1:"

# -I: searched after the including file's folder.
mkdir -p "$tmp/lib"
echo 'let from_lib = 3' >"$tmp/lib/lib.rts"
printf 'include "lib.rts"\nsphere { radius = from_lib }\n' >"$tmp/main.rts"
expect 1 "$rts" eval "$tmp/main.rts"
contains "$tmp/err" "cannot find include file 'lib.rts'"
expect 0 "$rts" eval "$tmp/main.rts" -I "$tmp/lib"
contains "$tmp/out" "sphere center <0, 0, 0> radius 3"

# print() writes located lines to stderr; string defines need their quotes.
printf 'let who = "nobody"\nprint("hello", who, 1 + 1, <1, 2, 3>)\n' >"$tmp/print.rts"
expect 0 "$rts" check "$tmp/print.rts" -D 'who="world"'
contains "$tmp/err" "print.rts:2:1: print: hello world 2 <1, 2, 3>"

# Limits and their flags.
printf 'let n = 0\nwhile n < 5000 { n += 1 }\n' >"$tmp/loop.rts"
expect 1 "$rts" check "$tmp/loop.rts" --max-iterations 100
contains "$tmp/err" "--max-iterations"
expect 0 "$rts" check "$tmp/loop.rts" --max-iterations 5000
expect 2 "$rts" check "$tmp/loop.rts" --max-recursion 0
expect 2 "$rts" check "$tmp/loop.rts" --no-such-flag

# Errors: exit 1 with a located, clang-style message; missing files too.
expect 1 "$rts" check "$src/tests/golden/eval-errors/unknown_property.rts"
contains "$tmp/err" "unknown_property.rts:3:24: error: unknown property 'centre' for sphere; did you mean 'center'?"
contains "$tmp/err" "unknown_property.rts:5:1: note: in call to macro 'ball' from here"
expect 1 "$rts" eval "$tmp/does_not_exist.rts"
expect 2 "$rts" check

# The standard library: found by the rts binary of the build tree without a path, under its
# own and POV-Ray's names, and every library picture renders (tiny, one sample).
printf 'include "colors.inc"\ninclude "std/shapes.rts"\nprint(Gray50)\n' > "$tmp/lib.rts"
expect 0 "$rts" check "$tmp/lib.rts"
contains "$tmp/err" "print: rgb(0.5, 0.5, 0.5)"
for scene in "$src"/docs/images/library_*.rts; do
  expect 0 "$rts" render "$scene" -o "$tmp/lib.png" --width 48 --height 24 --samples 1 --no-progress
done
# Installed elsewhere, RTS_STDLIB points at it, and it is the library searched.
mkdir -p "$tmp/elsewhere" && printf 'let Gray50 = rgb(0.25)\n' > "$tmp/elsewhere/colors.rts"
printf 'include "colors.inc"\nprint(Gray50)\n' > "$tmp/lib2.rts"
expect 0 env RTS_STDLIB="$tmp/elsewhere" "$rts" check "$tmp/lib2.rts"
contains "$tmp/err" "print: rgb(0.25, 0.25, 0.25)"
expect 1 env RTS_STDLIB="$tmp/elsewhere" "$rts" check "$tmp/lib.rts"   # no shapes.rts there
contains "$tmp/err" "cannot find include file 'std/shapes.rts' in the standard library $tmp/elsewhere"

# rts check warns as rts render does (runtime/scene_warnings.hpp): the same lines, in order.
cat > "$tmp/warn.rts" <<'SCENE'
camera { position = <0, 1, 0>  look_at = <0, 0, 5> }
point_light { position = <0, 5, -5> }
sphere { radius = 3 }
triangle { v0 = <0, 0, 0>  v1 = <1, 1, 1>  v2 = <2, 2, 2> }
SCENE
expect 0 "$rts" check "$tmp/warn.rts"
contains "$tmp/err" "warn.rts:4:1: warning: triangle has zero area"
contains "$tmp/err" "warn.rts:1:1: warning: the camera is inside a sphere"
contains "$tmp/err" "warn.rts:3:1: note: the sphere is placed here"
grep "warning:\|note:" "$tmp/err" > "$tmp/check.warnings"
expect 0 "$rts" render "$tmp/warn.rts" -o "$tmp/warn.png" --width 4 --height 4 --no-progress
grep "warning:\|note:" "$tmp/err" > "$tmp/render.warnings"
diff "$tmp/check.warnings" "$tmp/render.warnings" >/dev/null || fail "rts check and rts render warn differently: $(diff "$tmp/check.warnings" "$tmp/render.warnings")"

if [[ $failures -gt 0 ]]; then
  echo "$failures check(s) failed" >&2
  exit 1
fi
echo "all rts check/eval command-line checks passed"
