#!/usr/bin/env bash
# Equal-time comparison with POV-Ray 3.7 on the soft-shadow scene (docs/convergence.md):
# POV-Ray's antialiasing threshold is swept at 2x2, 4x4 and 8x8 jittered area-light samples,
# with and without POV-Ray's adaptive area light, each image measured against POV-Ray's own
# high-quality reference (16x16 jittered light samples, all taken, and 6x6 jittered
# supersamples per pixel). Prints: config, wall s, CPU s (user + sys, whole process), RMSE
# (linear RGB).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cp "$here/soft_shadows.pov" "$tmp/"
pov() {  # pov OUT.png ARGS...: renders and prints "wall_seconds cpu_seconds"
  local out="$1"; shift
  (cd "$tmp" && /usr/bin/time -f '%e %U %S' povray +Isoft_shadows.pov "+O$out" +W128 +H96 +FN16 File_Gamma=1.0 \
    -D +WT2 "$@" 2>&1 >/dev/null | tail -1 | awk '{print $1, $2 + $3}')
}
echo "reference..." >&2
pov ref.png Declare=AREA_N=16 Declare=ADAPTIVE=0 +A0.0 +AM1 +R6 +J >/dev/null
for adaptive in 0 1; do
  for n in 2 4 8; do
    for aa in none 0.3 0.1 0.03 0.0; do
      if [[ $aa == none ]]; then args=(-A); else args=(+A$aa +AM2 +R3 +J); fi
      t=$(pov run.png Declare=AREA_N=$n Declare=ADAPTIVE=$adaptive "${args[@]}")
      echo "area ${n}x${n} adaptive $adaptive aa $aa $t $(python3 "$here/png_rmse.py" "$tmp/run.png" "$tmp/ref.png")"
    done
  done
done
