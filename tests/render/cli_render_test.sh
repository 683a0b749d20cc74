#!/usr/bin/env bash
# `rts render` end to end: exit codes, nothing written on failure (an existing output stays
# byte-identical), AOV files, determinism across --threads, --seed.
#   tests/render/cli_render_test.sh path/to/rts
set -uo pipefail
rts="$(realpath "$1")"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
expect_rc() {  # expected-code description command...
  local want="$1" what="$2"; shift 2
  "$@" >"$tmp/out.log" 2>"$tmp/err.log"
  local rc=$?
  [[ $rc -eq $want ]] || { fail "$what: exit $rc, expected $want"; cat "$tmp/err.log" >&2; }
}

cat >"$tmp/ok.rts" <<'SCENE'
settings { width = 24  height = 16  samples = 4 }
camera { position = <0, 1, -4>  look_at = <0, 0.5, 0>  aperture = 0.1 }
area_light { position = <0, 5, -2>  u = <1, 0, 0>  v = <0, 0, 1>  samples = 4 }
plane { normal = <0, 1, 0>  material = material { reflect = 0.3  roughness = 0.2 } }
sphere { center = <0, 0.6, 0>  radius = 0.6 }
SCENE
cat >"$tmp/syntax.rts" <<'SCENE'
sphere { radius = 1
SCENE
cat >"$tmp/texture.rts" <<'SCENE'
settings { width = 8  height = 8 }
sphere { radius = 1  material = material { color = image_texture("missing-texture.png") } }
SCENE

# Success: writes the image (default name: the scene's, in the current directory).
expect_rc 0 "render ok" "$rts" render "$tmp/ok.rts" -o "$tmp/a.png" --threads 1 --no-progress
[[ -s "$tmp/a.png" ]] || fail "no image written"
grep -q "24x16, 4 spp" "$tmp/err.log" || fail "summary line missing: $(cat "$tmp/err.log")"
(cd "$tmp" && "$rts" render ok.rts --no-progress 2>/dev/null) && [[ -s "$tmp/ok.png" ]] || fail "default output name"

# Determinism: the same bytes whatever the thread count; another seed changes them.
expect_rc 0 "render 2 threads" "$rts" render "$tmp/ok.rts" -o "$tmp/b.png" --threads 2 --no-progress
cmp -s "$tmp/a.png" "$tmp/b.png" || fail "1 and 2 threads differ"
expect_rc 0 "render seed" "$rts" render "$tmp/ok.rts" -o "$tmp/c.png" --seed 99 --no-progress
cmp -s "$tmp/a.png" "$tmp/c.png" && fail "--seed did not change the image"

# AOVs beside the output, 16-bit output.
expect_rc 0 "aov" "$rts" render "$tmp/ok.rts" -o "$tmp/d.png" --aov normal,depth,albedo --bits 16 --no-progress
for n in normal depth albedo; do [[ -s "$tmp/d.$n.png" ]] || fail "missing d.$n.png"; done

# Failures leave an existing output untouched.
cp "$tmp/a.png" "$tmp/keep.png"
expect_rc 1 "syntax error" "$rts" render "$tmp/syntax.rts" -o "$tmp/keep.png" --no-progress
cmp -s "$tmp/a.png" "$tmp/keep.png" || fail "syntax error modified the output"
expect_rc 3 "missing texture" "$rts" render "$tmp/texture.rts" -o "$tmp/keep.png" --no-progress
cmp -s "$tmp/a.png" "$tmp/keep.png" || fail "render error modified the output"
grep -q "texture.rts:2:" "$tmp/err.log" || fail "texture error not located: $(cat "$tmp/err.log")"
expect_rc 3 "oversize image" "$rts" render "$tmp/ok.rts" -o "$tmp/keep.png" --width 100000 --height 100000 --no-progress
cmp -s "$tmp/a.png" "$tmp/keep.png" || fail "oversize render modified the output"
expect_rc 1 "missing scene" "$rts" render "$tmp/nope.rts" -o "$tmp/keep.png" --no-progress
expect_rc 3 "missing output dir" "$rts" render "$tmp/ok.rts" -o "$tmp/no/such/dir/x.png" --no-progress
[[ -e "$tmp/no" ]] && fail "created the missing output directory"

# Usage errors are exit 2.
expect_rc 2 "bad --bits" "$rts" render "$tmp/ok.rts" --bits 12
expect_rc 2 "bad --aov" "$rts" render "$tmp/ok.rts" --aov bogus
expect_rc 2 "bad --samples" "$rts" render "$tmp/ok.rts" --samples 0

[[ $failures -eq 0 ]] && echo "cli_render_test: all passed"
exit $((failures > 0))
