#!/usr/bin/env bash
# Two-level instancing (issue 24): one group of M x M spheres placed C x C times
# (bench/instancing/copies.rts), M*M*C*C spheres in the image. Prints, per size and binary,
# the build phase (`seconds.build`: flattening, BVHs), the evaluation, the whole process's wall
# time and its peak RSS (/usr/bin/time), medians of RUNS runs; with BASE_BIN set (an rts built
# before instancing), the same for it, alternating, and whether both images are identical.
#
#   bench/instancing.sh                               # this tree's build/cli/rts
#   BASE_BIN=/tmp/rts_old SIZES="32x32 32x64" bench/instancing.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-2}"
SIZES="${SIZES:-32x32 32x64 100x32}"
rts="${RTS_BIN:-$root/build/cli/rts}"
data="$root/build/bench-instancing"
mkdir -p "$data"

median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
# One run: prints "EVAL_S BUILD_S WALL_S PEAK_MB".
measure() {  # BIN TAG M C
  /usr/bin/time -f "%e %M" -o "$data/time" "$1" render "$root/bench/instancing/copies.rts" -D "m=$3" -D "c=$4" \
    --max-objects 100000000 --threads "$THREADS" --no-progress --stats-json "$data/stats.json" \
    -o "$data/$2.png" >"$data/last.log" 2>&1 || { tail -c 2000 "$data/last.log" >&2; exit 1; }
  python3 - "$data/stats.json" "$data/time" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["seconds"]
wall, kb = open(sys.argv[2]).read().split()[-2:]
print(f'{s["evaluate"]:.3f} {s["build"]:.3f} {float(wall):.2f} {int(kb) / 1024:.0f}')
PY
}

printf '| spheres (group x placements) | binary | evaluate | build | wall | peak RSS (MiB) | bytes per sphere |\n|---|---|---|---|---|---|---|\n'
for size in $SIZES; do
  m="${size%x*}" c="${size#*x}"
  spheres=$((m * m * c * c))
  bins=("$rts")
  [[ -n "${BASE_BIN:-}" ]] && bins+=("$BASE_BIN")
  declare -A ev=() bu=() wa=() pk=()
  for ((i = 0; i < RUNS; i++)); do
    for b in "${bins[@]}"; do
      tag="$(basename "$b")_$size"
      read -r e bs w mb < <(measure "$b" "$tag" "$m" "$c")
      ev[$b]+="$e " bu[$b]+="$bs " wa[$b]+="$w " pk[$b]+="$mb "
    done
  done
  for b in "${bins[@]}"; do
    peak="$(median ${pk[$b]})"
    printf '| %d (%d x %d) | %s | %s s | %s s | %s s | %s | %d |\n' "$spheres" $((m * m)) $((c * c)) \
      "$(basename "$b")" "$(median ${ev[$b]})" "$(median ${bu[$b]})" "$(median ${wa[$b]})" "$peak" \
      "$(python3 -c "print(round($peak * 1048576 / $spheres))")"
  done
  if [[ -n "${BASE_BIN:-}" ]]; then
    cmp -s "$data/$(basename "$rts")_$size.png" "$data/$(basename "$BASE_BIN")_$size.png" \
      && echo "  images identical" || echo "  IMAGES DIFFER"
  fi
  unset ev bu wa pk
done
