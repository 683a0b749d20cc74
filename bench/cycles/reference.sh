#!/usr/bin/env bash
# Renders the stored Cycles reference of tests/render/test_media.cpp ("path-mode media agree
# with Cycles"): the smoke_lamp scene of bench/cycles/scenes.py at 32x32, 8 seeds of 16384
# samples each (one thread each, two at a time), into tests/golden/path/smoke_lamp_cycles.pfm
# (the mean) and smoke_lamp_cycles_var.pfm (the variance of that mean, from the seeds' spread).
# Needs blender and python3-numpy; about 5 minutes on 2 cores. Look at the result before
# committing it.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
render() {
  for s in "$@"; do
    RTS_CYCLES_SIZE=32 nice blender -b --factory-startup -P "$ROOT/bench/cycles/scenes.py" -- smoke_lamp \
      "$OUT/cy.$s.pfm" 16384 "$s" 1 > /dev/null 2>&1
  done
}
render 1 2 3 4 & render 5 6 7 8 & wait
/usr/bin/python3 "$ROOT/bench/cycles/combine.py" "$ROOT/tests/golden/path/smoke_lamp_cycles" "$OUT"/cy.*.pfm
