#!/usr/bin/env bash
# The course programs' flags and conventions, end to end: scenes written here in each course's
# grammar (ours, not the courses' published ones) are imported with the flags, rendered with a
# plain `rts render` (the flags became settings), and pixels are checked against closed-form
# values (8-bit linear codes, within 1 code of round(255 · value)).
source "$(dirname "$0")/../cli/lib.sh"
PIXEL="$SRC/tests/import/png_pixel.py"
if ! command -v python3 >/dev/null; then echo "python3 is needed to read pixels: skipped"; exit 77; fi
cd "$TMP"

# expect_pixels DESCRIPTION FILE X Y "R G B" [X Y "R G B" ...]: each code within 1 of
# round(255 · value) (values linear, 0..1). One python3 start per image: starts are slow.
expect_pixels() {
  local what="$1" file="$2"; shift 2
  local args=() out
  while [[ $# -gt 0 ]]; do args+=("$1" "$2" $3); shift 3; done
  if out="$(python3 "$PIXEL" --check "$file" "${args[@]}" 2>&1)"; then
    echo "ok: $what"; echo "$out" | sed 's/^/    /'
  else
    echo "FAIL: $what"; echo "$out" | sed 's/^/    /'; FAILS=$((FAILS + 1))
  fi
}
import_render() {  # import_render NAME IMPORT-ARGS... : NAME.txt/.scene -> NAME.rts -> NAME.png
  local name="$1"; shift
  expect_exit 0 "import $name" -- "$RTS" import "$@" -o "$name.rts"
  expect_exit 0 "render $name" -- "$RTS" render "$name.rts" -o "$name.png" --threads 2 --no-progress
}

# ---- MIT 6.837 a2 -------------------------------------------------------------------------
# A diffuse sphere seen head-on under a light along the view: its centre is kd · (ambient + 0.8).
cat > diffuse.txt <<'SCENE'
PerspectiveCamera { center 0 0 10  direction 0 0 -1  up 0 1 0  angle 30 }
Lights { numLights 1  DirectionalLight { direction 0 0 -1  color 0.8 0.8 0.8 } }
Background { color 0.1 0.2 0.3  ambientLight 0.2 0.2 0.2 }
Materials { numMaterials 1  PhongMaterial { diffuseColor 0.5 0.25 1 } }
Group { numObjects 1  MaterialIndex 0  Sphere { center 0 0 0  radius 2 } }
SCENE
import_render diffuse diffuse.txt --size 9 9 --aov normal,depth --depth-range 6,10
expect_grep diffuse.rts "width = 9  height = 9" "--size is the image size"
expect_pixels "MIT: diffuse sphere centre = kd · (ambient + light); the background where nothing is hit" \
  diffuse.png 4 4 "0.5 0.25 1" 0 0 "0.1 0.2 0.3"
# Depth: the sphere's front is 8 from the eye, halfway through 6..10; misses are black.
expect_pixels "MIT: depth (t - dmin) / (dmax - dmin), misses black" diffuse.depth.png 4 4 "0.5 0.5 0.5" 0 0 "0 0 0"
# Normals: (n + 1) / 2, the background gray 127.
expect_pixels "MIT: normal (n + 1) / 2, misses gray 127" diffuse.normal.png 4 4 "0.5 0.5 1" 0 0 "0.498 0.498 0.498"

# A point light with falloff beside a blocker: the plane's centre sees it at d² = 32 with
# N·L = 1/√2 unless --shadows casts the blocker's shadow (then only the ambient term is left).
cat > falloff.txt <<'SCENE'
PerspectiveCamera { center 0 0 10  direction 0 0 -1  up 0 1 0  angle 30 }
Lights { numLights 1  PointLight { position 4 0 4  color 4 4 4  falloff 0.5 } }
Background { color 0 0 0  ambientLight 0.1 0.1 0.1 }
Materials { numMaterials 1  PhongMaterial { diffuseColor 1 1 1 } }
Group { numObjects 2  MaterialIndex 0  Plane { normal 0 0 1  offset 0 }  Sphere { center 2 0 2  radius 0.5 } }
SCENE
import_render falloff falloff.txt --size 9 9
expect_grep falloff.rts "attenuation = <0, 0, 0.5>" "falloff becomes attenuation <0, 0, falloff>"
expect_grep falloff.rts "shadows = false" "no shadow rays without --shadows"
v="$(awk 'BEGIN { v = 0.1 + 4 / (0.5 * 32) / sqrt(2); print v, v, v }')"
expect_pixels "MIT: falloff light color / (falloff · d²), no shadow without --shadows" falloff.png 4 4 "$v"
import_render falloff_shadows falloff.txt --size 9 9 --shadows
expect_pixels "MIT: --shadows leaves the ambient term in the shadow" falloff_shadows.png 4 4 "0.1 0.1 0.1"

# A mirror (black diffuse, specularColor 0.5) facing the camera reflects the environment: a
# cube map of one colour. --bounces adds ks · I_reflected; without it the mirror is black.
printf 'settings { width = 2  height = 2  background = rgb(0.2, 0.4, 0.6) }\n' > face.rts
expect_exit 0 "cube map face" -- "$RTS" render face.rts -o face.png --linear --no-progress
mkdir -p cube && for f in right left up down front back; do cp face.png "cube/$f.png"; done
cat > mirror.txt <<'SCENE'
PerspectiveCamera { center 0 0 10  direction 0 0 -1  up 0 1 0  angle 30 }
Lights { numLights 1  DirectionalLight { direction 0 0 1  color 1 1 1 } }
Background { color 0 0 0  ambientLight 0 0 0  cubeMap cube }
Materials { numMaterials 1  PhongMaterial { diffuseColor 0 0 0  specularColor 0.5 0.5 0.5  shininess 10 } }
Group { numObjects 1  MaterialIndex 0  Plane { normal 0 0 1  offset 0 } }
SCENE
import_render mirror mirror.txt --size 9 9 --bounces 4
expect_grep mirror.rts "max_depth = 4" "--bounces is the recursion depth"
expect_pixels "MIT: mirror = ks · the cube map it reflects" mirror.png 4 4 "0.1 0.2 0.3"
import_render matte mirror.txt --size 9 9
expect_pixels "MIT: no reflection without --bounces" matte.png 4 4 "0 0 0"

# scene05's kind of camera: an up that leans towards the direction shears the view. On the
# plane z = 0 seen from z = 10, pixel row y (a2's y in [-1, 1]) looks along
# w / tan(15°) + y·up with up = (0, 1, 0.5), reaching the plane at distance 10·|dir| / (D - 0.5y):
# 10.36 at the top, 10.22 at the bottom (an orthogonalised up gives 10.28 at both).
cat > sheared.txt <<'SCENE'
PerspectiveCamera { center 0 0 10  direction 0 0 -1  up 0 1 0.5  angle 30 }
Lights { numLights 1  DirectionalLight { direction 0 0 -1  color 1 1 1 } }
Background { color 0 0 0  ambientLight 0 0 0 }
Materials { numMaterials 1  PhongMaterial { diffuseColor 1 1 1 } }
Group { numObjects 1  MaterialIndex 0  Plane { normal 0 0 1  offset 0 } }
SCENE
import_render sheared sheared.txt --size 9 9 --aov depth --depth-range 10,10.5
expect_grep sheared.rts "direction = <0, 0, -1>  right = " "a sheared camera keeps its vectors as given"
checks=()
for row in 0 4 8; do
  checks+=(4 "$row" "$(awk -v r="$row" 'BEGIN {
    D = cos(15 * 3.14159265358979 / 180) / sin(15 * 3.14159265358979 / 180); y = 2 * (0.5 - (r + 0.5) / 9)
    t = 10 * sqrt(y * y + (0.5 * y - D) ^ 2) / (D - 0.5 * y); v = (t - 10) / 0.5
    if (v < 0) v = 0; if (v > 1) v = 1; print v, v, v }')")
done
expect_pixels "MIT: sheared camera, the depth of rows 0, 4, 8" sheared.depth.png "${checks[@]}"

# TriangleMesh: smooth, vertex normals the mean of the faces' unit normals.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > tri.obj
printf 'Materials { numMaterials 1  PhongMaterial { diffuseColor 1 1 1 } }\nGroup { numObjects 1  MaterialIndex 0  TriangleMesh { obj_file tri.obj } }\n' > mesh.txt
expect_exit 0 "import a TriangleMesh" -- "$RTS" import mesh.txt -o mesh.rts
expect_grep mesh.rts 'smooth_weights = "equal"' "TriangleMesh normals: equal weights"

# ---- USC CSCI 420 assignment 3 --------------------------------------------------------------
# The fixed camera (origin, -z, 60° vertical); rendered at 65x49 so one pixel is the centre.
csci_render() {  # csci_render NAME IMPORT-ARGS...
  local name="$1"; shift
  expect_exit 0 "import $name" -- "$RTS" import "$name.scene" "$@" -o "$name.rts"
  expect_exit 0 "render $name" -- "$RTS" render "$name.rts" -o "$name.png" --width 65 --height 49 --threads 2 --no-progress
}
# A sphere lit from the eye: centre = amb + light · dif, clamped per channel (red > 1).
cat > sphere.scene <<'SCENE'
2
amb: 0.1 0.1 0.1
sphere
pos: 0 0 -5
rad: 1
dif: 0.7 0.2 0.3
spe: 0 0 0
shi: 1
light
pos: 0 0 0
col: 2 2 2
SCENE
csci_render sphere
expect_pixels "CSCI: sphere centre amb + light · dif, red clamped alone; the background white" \
  sphere.png 32 24 "1 0.5 0.7" 0 0 "1 1 1"

# A triangle lit from behind: only the ambient term (added once, not times dif).
cat > ambient.scene <<'SCENE'
2
amb: 0.2 0.2 0.2
triangle
pos: -50 -50 -10
nor: 0 0 1
dif: 0.5 0.5 0.5
spe: 0 0 0
shi: 1
pos: 50 -50 -10
nor: 0 0 1
dif: 0.5 0.5 0.5
spe: 0 0 0
shi: 1
pos: 0 50 -10
nor: 0 0 1
dif: 0.5 0.5 0.5
spe: 0 0 0
shi: 1
light
pos: 0 0 -20
col: 1 1 1
SCENE
csci_render ambient
expect_pixels "CSCI: ambient-only patch = amb" ambient.png 32 24 "0.2 0.2 0.2"
# The same triangle as a half mirror: (1 - ks) · local + ks · reflected, the reflected ray
# leaving to the white background.
sed 's/^spe: 0 0 0/spe: 0.5 0.5 0.5/' ambient.scene > half_mirror.scene
csci_render half_mirror --reflection 3
expect_grep half_mirror.rts "max_depth = 3" "--reflection is the recursion depth"
expect_pixels "CSCI: (1 - ks) · amb + ks · white" half_mirror.png 32 24 "0.6 0.6 0.6"
# Supersampling and soft shadows keep a uniform area's value.
cp sphere.scene sphere_aa.scene
csci_render sphere_aa --antialias 3 --soft-shadows 8
expect_grep sphere_aa.rts 'samples = 9  sampler = "stratified"' "--antialias N is N² samples"
[[ "$(grep -c 'point_light' sphere_aa.rts)" == 8 ]] || { echo "FAIL: --soft-shadows 8 wrote $(grep -c point_light sphere_aa.rts) lights"; FAILS=$((FAILS + 1)); }
expect_grep sphere_aa.rts "color = rgb\(0.25\)" "each sub-light has color / N"
expect_pixels "CSCI: supersampled, soft-shadowed sphere centre" sphere_aa.png 32 24 "1 0.5 0.7"

# ---- flags in the wrong place ---------------------------------------------------------------
expect_exit 2 "an MIT flag on a CSCI 420 scene" -- "$RTS" import sphere.scene --bounces 2
expect_grep "$TMP/err" "--bounces is MIT 6.837 a2's flag" "names the flag"
expect_exit 2 "a CSCI 420 switch on an MIT scene" -- "$RTS" import diffuse.txt --antialias 2
expect_exit 2 "a bad depth range" -- "$RTS" import diffuse.txt --depth-range 10,6
finish
