#!/usr/bin/env bash
# Samplers, error estimates, adaptive sampling, time limits and `rts converge` from the
# command line (tiny images: a few seconds in all).
source "$(dirname "$0")/lib.sh"

cat > "$TMP/soft.rts" <<'SCENE'
settings { width = 24  height = 16  samples = 8 }
camera { position = <0, 2, -6>  look_at = <0, 0.6, 0> }
area_light { position = <-1.5, 5, -1.5>  u = <3, 0, 0>  v = <0, 0, 3>  samples = 4 }
plane { normal = <0, 1, 0>  offset = 0 }
sphere { center = <0, 1.2, 0>  radius = 0.6 }
SCENE

for s in random stratified sobol; do
  expect_exit 0 "render with --sampler $s" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/$s.png" --sampler $s
  expect_grep "$TMP/err" "$s sampler, est. error: rmse [0-9.e-]+, rel. mse" "the summary names the sampler and the estimate"
done
expect_exit 0 "1 spp" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/one.png" --samples 1
expect_grep "$TMP/err" "est. error n/a" "1 spp has no estimate"
expect_exit 2 "unknown --sampler" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/x.png" --sampler halton
expect_exit 2 "negative --target-error" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/x.png" --target-error -1

sed 's/samples = 8 }/samples = 8  sampler = "halton" }/' "$TMP/soft.rts" > "$TMP/bad.rts"
expect_exit 1 "unknown settings sampler" -- "$RTS" render "$TMP/bad.rts" -o "$TMP/x.png"
expect_grep "$TMP/err" "bad.rts:1:[0-9]+: error: unknown sampler 'halton'" "located message"

expect_exit 0 "--aov error" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/e.png" --aov error --bits 16
[[ -s "$TMP/e.error.png" ]] || { echo "FAIL: no e.error.png"; FAILS=$((FAILS + 1)); }
expect_exit 0 "--aov error_map" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/m.png" --aov error_map
[[ -s "$TMP/m.error_map.png" ]] || { echo "FAIL: no m.error_map.png"; FAILS=$((FAILS + 1)); }
# The same from the scene: settings.aov takes every name --aov takes.
sed 's/settings {/settings { aov = "error_map" /' "$TMP/soft.rts" >"$TMP/soft_aov.rts"
expect_exit 0 "settings { aov = \"error_map\" }" -- "$RTS" render "$TMP/soft_aov.rts" -o "$TMP/ms.png"
cmp -s "$TMP/m.error_map.png" "$TMP/ms.error_map.png" || { echo "FAIL: settings.aov error_map differs from --aov error_map"; FAILS=$((FAILS + 1)); }

expect_exit 0 "adaptive" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/a.png" --samples 256 --target-error 0.002
expect_grep "$TMP/err" "spp on average" "an adaptive render reports its sample counts"
expect_exit 0 "unreachable target" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/a.png" --samples 16 --target-error 1e-9
expect_grep "$TMP/err" "warning: .*did not reach the target" "an unreachable target is a warning"
expect_exit 0 "target error at 1 spp" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/a.png" --samples 1 --target-error 0.01
expect_grep "$TMP/err" "warning: .*needs at least 2 samples" "a target error without samples to adapt is a warning"
expect_exit 0 "time limit" -- "$RTS" render "$TMP/soft.rts" -o "$TMP/t.png" --samples 65536 --time-limit 0.3
expect_grep "$TMP/err" "warning: .*time limit of 0.3s ran out" "a time limit that runs out is a warning"
[[ -s "$TMP/t.png" ]] || { echo "FAIL: no image after the time limit"; FAILS=$((FAILS + 1)); }

expect_exit 0 "converge" -- "$RTS" converge "$TMP/soft.rts" -o "$TMP/conv" --max-samples 4 --reference-samples 32
for f in convergence.csv convergence.svg convergence-spp.svg reference.pfm; do
  [[ -s "$TMP/conv/$f" ]] || { echo "FAIL: converge did not write $f"; FAILS=$((FAILS + 1)); }
done
expect_grep "$TMP/conv/convergence.csv" "^sampler,spp,mean_spp,seconds,cpu_seconds,rmse,rel_mse,psnr,est_rmse" "csv header"
[[ $(grep -c '^random,' "$TMP/conv/convergence.csv") == 3 ]] || { echo "FAIL: 3 random rows (1,2,4 spp) expected"; FAILS=$((FAILS + 1)); }
expect_grep "$TMP/conv/convergence.csv" "^sobol,1,.*,n/a,n/a,n/a$" "1 spp has no estimate in the csv"
expect_grep "$TMP/out" "fitted slopes" "slopes printed"
expect_grep "$TMP/out" "equal-time RMSE" "equal-time table printed"
expect_grep "$TMP/conv/convergence.svg" "<svg" "an SVG plot"
# The rendered reference can be reused; a wrong-sized or missing one is a render error.
expect_exit 0 "converge --reference" -- "$RTS" converge "$TMP/soft.rts" -o "$TMP/conv2" --max-samples 2 --samplers sobol --reference "$TMP/conv/reference.pfm"
expect_exit 3 "reference of another size" -- "$RTS" converge "$TMP/soft.rts" -o "$TMP/conv3" --max-samples 2 --width 10 --reference "$TMP/conv/reference.pfm"
expect_exit 3 "missing reference" -- "$RTS" converge "$TMP/soft.rts" -o "$TMP/conv3" --reference "$TMP/nope.pfm"
expect_exit 2 "converge: unknown sampler" -- "$RTS" converge "$TMP/soft.rts" --samplers halton
finish
