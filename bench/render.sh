#!/usr/bin/env bash
# Rendering race: bench/render_scene.rts with rts against the hand-written equivalent
# bench/render_scene.pov with POV-Ray 3.7, in the same run, same size, same thread count,
# one sample per pixel (POV-Ray: antialiasing off). Prints the median wall time of RUNS runs
# of each and the ratio, as a Markdown table (paste into docs/performance.md).
#
#   bench/render.sh                 # 1280x960, 3 runs, all cores
#   W=800 H=600 RUNS=5 THREADS=1 bench/render.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
W="${W:-1280}"
H="${H:-960}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-$(nproc)}"
rts="${RTS:-$root/${RTS_BUILD_DIR:-build}/cli/rts}"
if [[ ! -x "$rts" ]]; then "$root/scripts/build" --target rts >&2; fi
command -v povray >/dev/null || { echo "bench/render.sh: povray not found (scripts/ensure-deps --bench)" >&2; exit 1; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# Wall-clock seconds of one command (its output discarded; a failure aborts the benchmark).
seconds() {
  local start end
  start=$(date +%s%N)
  "$@" >"$tmp/last.log" 2>&1 || { cat "$tmp/last.log" >&2; exit 1; }
  end=$(date +%s%N)
  echo "scale=3; ($end - $start) / 1000000000" | bc
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

rts_times=() pov_times=()
for ((i = 0; i < RUNS; ++i)); do
  rts_times+=("$(seconds "$rts" render "$root/bench/render_scene.rts" -o "$tmp/rts.png" \
                 --width "$W" --height "$H" --threads "$THREADS" --no-progress)")
  pov_times+=("$(seconds povray "+I$root/bench/render_scene.pov" "+O$tmp/pov.png" "+W$W" "+H$H" \
                 -D -A "+WT$THREADS" -GA +FN)")
done
# The rts summary line of the last run: rays, rays/s, time per phase.
summary="$("$rts" render "$root/bench/render_scene.rts" -o "$tmp/rts.png" --width "$W" --height "$H" \
            --threads "$THREADS" --no-progress 2>&1 | tail -1)"
rts_med="$(median "${rts_times[@]}")"
pov_med="$(median "${pov_times[@]}")"
ratio="$(echo "scale=2; $pov_med / $rts_med" | bc)"

echo "| scene | size | threads | rts (median of $RUNS) | POV-Ray 3.7 (median of $RUNS) | POV-Ray / rts |"
echo "|---|---|---|---|---|---|"
echo "| bench/render_scene | ${W}x${H}, 1 spp | $THREADS | ${rts_med} s | ${pov_med} s | ${ratio}x |"
echo
echo "rts runs: ${rts_times[*]}; POV-Ray runs: ${pov_times[*]}"
echo "$summary"
