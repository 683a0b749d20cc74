#!/usr/bin/env bash
# The path tracer from the command line: settings.integrator and --integrator (the flag wins),
# the statistics naming the integrator and its parts, the emissive-only scene not called
# unlit, byte-identical images across thread counts, unknown names refused.
source "$(dirname "$0")/lib.sh"

cat > "$TMP/box.rts" <<'SCENE'
settings { width = 24  height = 16  samples = 8  integrator = "path" }
camera { position = <0, 1, -3>  look_at = <0, 1, 0> }
let white = material { color = rgb(0.7)  diffuse = 1 }
quad { corner = <-1, 0, -1>  edge_u = <2, 0, 0>  edge_v = <0, 0, 2>  material = white }
quad { corner = <-1, 0, 1>  edge_u = <2, 0, 0>  edge_v = <0, 2, 0>  material = white }
quad { corner = <-0.3, 1.9, -0.3>  edge_u = <0.6, 0, 0>  edge_v = <0, 0, 0.6>  material = material { emission = rgb(8) } }
SCENE

expect_exit 0 "settings.integrator = path" -- "$RTS" render "$TMP/box.rts" -o "$TMP/p1.png" --threads 1 --stats
expect_grep "$TMP/err" "path integrator" "the summary names the path integrator"
expect_grep "$TMP/err" "path_used next_event_estimation mis emissive_shapes" "--stats lists the path parts used"
cp "$TMP/err" "$TMP/p1.err.keep"
if grep -q "places no lights" "$TMP/err"; then echo "FAIL: an emissive quad lights a path-traced scene"; FAILS=$((FAILS + 1)); fi
expect_exit 0 "3 threads" -- "$RTS" render "$TMP/box.rts" -o "$TMP/p3.png" --threads 3
cmp -s "$TMP/p1.png" "$TMP/p3.png" || { echo "FAIL: path images differ between 1 and 3 threads"; FAILS=$((FAILS + 1)); }
expect_exit 0 "--integrator whitted overrides the scene" -- "$RTS" render "$TMP/box.rts" -o "$TMP/w.png" --integrator whitted
if grep -q "path integrator" "$TMP/err"; then echo "FAIL: --integrator whitted still path traced"; FAILS=$((FAILS + 1)); fi
expect_grep "$TMP/err" "places no lights" "Whitted mode warns that emission lights nothing"
expect_exit 2 "unknown --integrator" -- "$RTS" render "$TMP/box.rts" -o "$TMP/x.png" --integrator photon
sed 's/integrator = "path"/integrator = "photon"/' "$TMP/box.rts" > "$TMP/bad.rts"
expect_exit 1 "unknown settings.integrator" -- "$RTS" render "$TMP/bad.rts" -o "$TMP/x.png"
expect_grep "$TMP/err" "bad.rts:1:[0-9]+: error: unknown integrator 'photon'" "located error"

# settings.clamp: off by default (listed as left out), on when set (listed as used, and no
# pixel brighter than the clamp), a located error when negative.
expect_grep "$TMP/p1.err.keep" "path_left_out.*clamp" "--stats says clamp is off by default"
sed 's/integrator = "path"/integrator = "path"  clamp = 0.5/' "$TMP/box.rts" > "$TMP/clamp.rts"
expect_exit 0 "clamp = 0.5" -- "$RTS" render "$TMP/clamp.rts" -o "$TMP/c.pfm" --stats
expect_grep "$TMP/err" "path_used .*clamp" "--stats lists clamp when it is on"
python3 - "$TMP/c.pfm" <<'PY' || { echo "FAIL: a pixel is brighter than the clamp"; FAILS=$((FAILS + 1)); }
import struct, sys
d = open(sys.argv[1], 'rb').read().split(b'\n', 3)
w, h = map(int, d[1].split())
v = struct.unpack('<%df' % (w * h * 3), d[3][:w * h * 12])
sys.exit(0 if max(v) <= 0.5 + 1e-6 and max(v) > 0.4 else 1)
PY
sed 's/integrator = "path"/integrator = "path"  clamp = -1/' "$TMP/box.rts" > "$TMP/badclamp.rts"
expect_exit 1 "negative clamp" -- "$RTS" render "$TMP/badclamp.rts" -o "$TMP/x.png"
expect_grep "$TMP/err" "badclamp.rts:1:[0-9]+: error: .*clamp" "located error for a negative clamp"
finish
