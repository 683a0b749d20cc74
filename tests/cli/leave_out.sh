#!/usr/bin/env bash
# Leaving out what a scene does not need, end to end on bench/leave_out_{a,b,c}.rts (small):
# (b)'s unused declarations and (c)'s zero-strength features change neither the rays nor the
# image; --no-specialize gives the same image; an unused missing OBJ / PNG is never opened
# (render succeeds, check warns with the location); --stats and --stats-json report it.
source "$(dirname "$0")/lib.sh"
cp "$SRC"/bench/leave_out_{a,b,c}.rts "$TMP/"   # leave_out_big.obj / leave_out_tile.png: absent
cd "$TMP"
size=(--width 48 --height 36 --threads 1 --no-progress)

for v in a b c; do
  expect_exit 0 "render ($v)" -- "$RTS" render "leave_out_$v.rts" -o "$v.png" "${size[@]}" --stats-json "$v.json"
done
expect_exit 0 "render (d) --no-specialize" -- "$RTS" render leave_out_a.rts -o d.png "${size[@]}" --no-specialize --stats
expect_grep "$TMP/err" "features: +specialized false" "--stats shows the generic path"
for v in b c d; do
  cmp -s a.png "$v.png" || { echo "FAIL: image ($v) differs from (a)"; FAILS=$((FAILS + 1)); }
done

# The JSON is valid and (a), (b), (c) cast the same rays, none of them secondary.
rays() { python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))["rays"]; print(r["camera"], r["shadow"], r["reflection"], r["refraction"])' "$1"; }
ra="$(rays a.json)" || { echo "FAIL: a.json is not valid JSON"; cat a.json; FAILS=$((FAILS + 1)); }
[[ "$ra" == "1728 "*" 0 0" ]] || { echo "FAIL: (a) rays: $ra"; FAILS=$((FAILS + 1)); }
for v in b c; do
  [[ "$(rays "$v.json")" == "$ra" ]] || { echo "FAIL: ($v) rays $(rays "$v.json") != (a) $ra"; FAILS=$((FAILS + 1)); }
done
python3 - a.json c.json <<'PY' || FAILS=$((FAILS + 1))
import json, sys
for path in sys.argv[1:]:
    s = json.load(open(path))
    assert s["version"] == 1, path
    f = s["features"]
    assert f["specialized"] is True, path
    assert "reflection" in f["left_out"] and "area_light" in f["left_out"], (path, f)
    assert "sky_sphere" in f["left_out"], (path, f)
    assert set(f["used"]) >= {"sphere", "plane", "point_light", "shadows"}, (path, f)
    assert s["scene"]["primitives"] == {"sphere": 144, "plane": 1}, (path, s["scene"])
    assert all(k in s["seconds"] for k in ("parse", "evaluate", "build", "render", "write")), path
    assert s["memory_bytes"]["meshes"] == 0 and s["memory_bytes"]["textures"] == 0, path
PY

# check: each unused declaration is a warning with its location; the missing files are named
# but are not errors, since nothing places them.
expect_exit 0 "check (b) with a missing unused OBJ" -- "$RTS" check leave_out_b.rts
expect_grep "$TMP/err" "leave_out_b.rts:[0-9]+:[0-9]+: warning: mesh 'big' is declared but never used.*'leave_out_big.obj' does not exist" "unused mesh warning"
expect_grep "$TMP/err" "warning: texture 'tile' is declared but never used.*'leave_out_tile.png' does not exist" "unused image warning"
expect_grep "$TMP/err" "warning: macro 'ring' is declared but never used" "unused macro warning"
expect_grep "$TMP/err" "warning: material 'glass' is declared but never used|warning: material 'mirror'" "unused material warning"
# Placed, the same missing OBJ is an error.
{ cat leave_out_b.rts; echo "big"; } > placed.rts
expect_exit 1 "check with the missing OBJ placed" -- "$RTS" check placed.rts
expect_grep "$TMP/err" "leave_out_big.obj" "missing OBJ error names the file"

# A sky_sphere environment is reported as used (docs/library.md#sky_sphere).
cat > sky.rts <<'RTS'
settings { environment = sky_sphere { layers = [gradient { axis = "y"  color_map = [[0, rgb(1)], [1, rgb(0, 0, 1)]] }] } }
sphere { radius = 1  material = material { reflect = 0.5 } }
RTS
expect_exit 0 "render a sky_sphere" -- "$RTS" render sky.rts -o sky.png "${size[@]}" --stats
expect_grep "$TMP/err" "features: .*used .*sky_sphere.*left_out" "--stats lists sky_sphere as used"

# Procedural patterns (docs/textures.md#determinism-cost-and-leave-out): (a) has none, so
# `pattern` is left out; a marble texture or a bumps bump map puts it among the used. The sky
# above is a pattern on the environment, which counts as sky_sphere, not as pattern.
expect_grep "$TMP/err" "features: .*left_out .*pattern" "--stats lists pattern as left out for a sky_sphere only"
cat > marble.rts <<'RTS'
sphere { radius = 1  material = material { texture = marble { turbulence = 0.5 } scale 0.3 } }
RTS
cat > bumpy.rts <<'RTS'
sphere { radius = 1  material = material { color = rgb(0.8)  bump = bumps { } scale 0.2  bump_scale = 0.1 } }
RTS
for v in marble bumpy; do
  expect_exit 0 "render ($v)" -- "$RTS" render "$v.rts" -o "$v.png" "${size[@]}" --stats-json "$v.json"
done
python3 - a.json marble.json bumpy.json <<'PY' || FAILS=$((FAILS + 1))
import json, sys
none, *patterned = [json.load(open(p))["features"] for p in sys.argv[1:]]
assert "pattern" in none["left_out"] and "pattern" not in none["used"], none
for path, f in zip(sys.argv[2:], patterned):
    assert "pattern" in f["used"] and "pattern" not in f["left_out"], (path, f)
PY
finish
