#!/usr/bin/env bash
# rts's path tracer against Blender's Cycles (issue 19): the same five scenes rendered by both,
# compared block by block with a z-test, then the CPU time each needs to reach the same error on
# the Cornell box. Needs `scripts/ensure-deps --bench` (blender, python3-numpy) and a built rts.
#
#   bench/cycles/run.sh [OUTDIR] [SAMPLES] [SEEDS]      (defaults: build/cycles 256 4)
#   SCENES="rough_glass" NO_TIMING=1 bench/cycles/run.sh    (some scenes, no equal-error timing)
#   SCENES="caustic env_lit" TIMING_SCENES="caustic env_lit" bench/cycles/run.sh   (their timing)
#
# Everything runs on one thread under `nice` (the comparison is per CPU second, and the build
# machine is shared). Outputs: OUTDIR/<scene>.sbs.png (rts | Cycles | 4x |difference|), the
# comparison lines, and OUTDIR/timing.txt.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OUT=${1:-$ROOT/build/cycles}
SPP=${2:-256}
SEEDS=${3:-4}
RTS=${RTS:-$ROOT/build/cli/rts}
PY=/usr/bin/python3   # Debian's, with numpy (a pyenv python may lack it)
mkdir -p "$OUT"
cd "$OUT"
$PY "$ROOT/bench/cycles/scenes.py" "$OUT"

cycles() {  # scene out.pfm samples seed -> prints "wall cpu" of the render call
  nice blender -b --factory-startup -P "$ROOT/bench/cycles/scenes.py" -- "$1" "$2" "$3" "$4" 1 2>&1 |
    awk '/^cycles_render_seconds/ { print $2, $3 }'
}
rts_cpu() {  # scene out.pfm samples seed -> prints the process's CPU seconds
  /usr/bin/time -f '%U %S' -o rts_time.txt nice "$RTS" render "$1.rts" -o "$2" --samples "$3" --seed "$4" \
    --threads 1 --no-progress 2>/dev/null
  awk '{ print $1 + $2 }' rts_time.txt
}

for scene in ${SCENES:-cornell caustic rough_metal env_lit rough_glass}; do
  a=(); b=()
  for ((s = 0; s < SEEDS; s++)); do
    rts_cpu "$scene" "$scene.rts.$s.pfm" "$SPP" "$((s + 1))" > /dev/null
    cycles "$scene" "$scene.cy.$s.pfm" "$SPP" "$((s + 1))" > /dev/null
    a+=("$scene.rts.$s.pfm"); b+=("$scene.cy.$s.pfm")
  done
  $PY "$ROOT/bench/cycles/compare.py" --name "$scene" --a "${a[@]}" --b "${b[@]}" --png "$scene.sbs.png"
done | tee compare.txt

[[ -n "${NO_TIMING:-}" ]] && exit 0
# Equal error (the Cornell box, or TIMING_SCENES="cornell caustic ..." of those rendered
# above): the reference is the mean of every render above (rts's and Cycles', which agree);
# each engine renders with fresh seeds at 16, 64 and 256 spp.
{
  echo "scene spp engine cpu_s rmse"
  for scene in ${TIMING_SCENES:-cornell}; do
    for spp in 16 64 256; do
      echo "$scene $spp rts $(rts_cpu $scene t.rts.$spp.pfm $spp 101) $($PY "$ROOT/bench/cycles/rmse.py" t.rts.$spp.pfm $scene.rts.*.pfm $scene.cy.*.pfm)"
      echo "$scene $spp cycles $(cycles $scene t.cy.$spp.pfm $spp 101 | cut -d' ' -f2) $($PY "$ROOT/bench/cycles/rmse.py" t.cy.$spp.pfm $scene.rts.*.pfm $scene.cy.*.pfm)"
    done
  done
} | tee timing.txt
