#!/usr/bin/env bash
# Two-level instancing end to end: a group of 65 shapes (spheres, rotated boxes, a nested
# group) placed three times is instanced; the same three placements written as three separate
# group literals (each placed once) are copied. The images must agree (mean absolute difference
# below 0.05 of a code; today they are identical), --stats-json must name `instancing` for the
# first only, count its placements as `group` primitives and its shapes once. `rts check`
# summarizes a million placed spheres from the group's totals.
source "$(dirname "$0")/lib.sh"
cd "$TMP"
size=(--width 64 --height 48 --threads 2 --no-progress)
body='for i in 0 .. 8 { for j in 0 .. 8 {
        if (i + j) % 5 == 0 { box { min = <i - 0.3, 0, j - 0.3>  max = <i + 0.3, 0.6, j + 0.3>  material = m } rotate <0, i * 10, 0> }
        else { sphere { center = <i, 0.35, j>  radius = 0.35  material = m } }
    } }
    group { sphere { center = <3.5, 1.5, 3.5>  radius = 0.8  material = m } } scale 1.1'
head='settings { width = 64  height = 48  max_depth = 1 }
camera { position = <0, 14, -16>  look_at = <0, 0, 4>  fov = 60 }
point_light { position = <-8, 20, -10> }
plane { normal = <0, 1, 0>  material = material { color = rgb(0.6) } }
let m = material { color = rgb(0.9, 0.6, 0.3)  specular = 0.4  reflect = 0.2 }'
places=('translate <-12, 0, 0>' 'rotate <0, 30, 0> translate <0, 0, 2>' 'scale 0.7 rotate <0, -20, 0> translate <6, 0, 6>')
{ echo "$head"; echo "let tile = group { $body }"; for p in "${places[@]}"; do echo "tile $p"; done; } > shared.rts
{ echo "$head"; for p in "${places[@]}"; do echo "group { $body } $p"; done; } > copied.rts

for v in shared copied; do
  expect_exit 0 "render ($v)" -- "$RTS" render "$v.rts" -o "$v.png" "${size[@]}" --stats-json "$v.json"
done
python3 - shared.json copied.json <<'PY' || FAILS=$((FAILS + 1))
import json, sys
shared, copied = (json.load(open(p)) for p in sys.argv[1:])
assert "instancing" in shared["features"]["used"], shared["features"]
assert "instancing" in copied["features"]["left_out"], copied["features"]
ps, pc = shared["scene"]["primitives"], copied["scene"]["primitives"]
assert ps.get("group") == 3 and "group" not in pc, (ps, pc)
assert pc["sphere"] == 3 * ps["sphere"] and pc["box"] == 3 * ps["box"], (ps, pc)
assert ps["sphere"] + ps["box"] >= 64, ps
assert shared["rays"]["camera"] == copied["rays"]["camera"], (shared["rays"], copied["rays"])
PY
read -r mad block < <(python3 "$SRC/bench/png_compare.py" shared.png copied.png)
# The two differ at most in the last bits of a hit (composed transforms): a pixel on an edge
# may flip, nothing more.
python3 -c "import sys; sys.exit(0 if float('$mad') < 0.05 else 1)" \
  || { echo "FAIL: instanced and copied images differ: MAD $mad"; FAILS=$((FAILS + 1)); }
echo "instanced vs copied: MAD $mad codes"

# `rts check` of a group placed many times (16,384 placements of 64 spheres: past the exact
# walk's million instances) counts every sphere from the group's totals, without visiting
# each (it took longer than the render did), and says its bounds are the placed groups' boxes.
expect_exit 0 "check of many placements" -- "$RTS" check "$SRC/bench/instancing/copies.rts" -D m=8 -D c=128
cp "$TMP/out" check.txt
expect_grep check.txt "sphere +1048576$" "every placed sphere counted"
expect_grep check.txt "of the placed groups' boxes" "the bounds say what they enclose"
finish
