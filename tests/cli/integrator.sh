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
finish
