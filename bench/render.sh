#!/usr/bin/env bash
# Rendering race: rts against POV-Ray 3.7 on the same scenes, in the same run, at the same
# size and thread count, one sample per pixel (POV-Ray: antialiasing off). Scenes:
#   render_scene.rts / .pov  100 Phong spheres (half mirrors), a glass sphere, checkered floor
#   render_mesh.rts / .pov   5 instances of one smooth mesh (bench/render_gen_mesh.py, 2*MESH_N^2 tris)
# Prints the median wall time of RUNS runs of each, the ratio, and rts's own summary line, as
# a Markdown table (paste into docs/performance.md).
#
#   bench/render.sh                             # 1280x960, 3 runs, all cores, MESH_N=300
#   W=800 H=600 RUNS=5 THREADS=1 bench/render.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
W="${W:-1280}"
H="${H:-960}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-$(nproc)}"
MESH_N="${MESH_N:-300}"
rts="$(realpath "${RTS:-$root/${RTS_BUILD_DIR:-build}/cli/rts}")"
if [[ ! -x "$rts" ]]; then "$root/scripts/build" --target rts >&2; fi
command -v povray >/dev/null || { echo "bench/render.sh: povray not found (scripts/ensure-deps --bench)" >&2; exit 1; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cp "$root"/bench/render_scene.{rts,pov} "$root"/bench/render_mesh.{rts,pov} "$tmp/"
python3 "$root/bench/render_gen_mesh.py" "$MESH_N" "$tmp"

# Wall-clock seconds of one command (output discarded; a failure aborts the benchmark).
seconds() {
  local start end
  start=$(date +%s%N)
  "$@" >"$tmp/last.log" 2>&1 || { tail -c 2000 "$tmp/last.log" >&2; exit 1; }
  end=$(date +%s%N)
  awk -v s="$start" -v e="$end" 'BEGIN { printf "%.3f\n", (e - s) / 1e9 }'
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

run_rts() { (cd "$tmp" && "$rts" render "$1.rts" -o "$1.rts.png" --width "$W" --height "$H" --threads "$THREADS" --no-progress); }
run_pov() { (cd "$tmp" && povray "+I$1.pov" "+O$1.pov.png" "+W$W" "+H$H" -D -A "+WT$THREADS" -GA +FN); }

echo "| scene | size | threads | rts (median of $RUNS) | POV-Ray 3.7 (median of $RUNS) | POV-Ray / rts |"
echo "|---|---|---|---|---|---|"
summaries=()
for scene in render_scene render_mesh; do
  rts_times=() pov_times=()
  for ((i = 0; i < RUNS; ++i)); do
    rts_times+=("$(seconds run_rts "$scene")")
    pov_times+=("$(seconds run_pov "$scene")")
  done
  rts_med="$(median "${rts_times[@]}")"
  pov_med="$(median "${pov_times[@]}")"
  ratio="$(awk -v p="$pov_med" -v r="$rts_med" 'BEGIN { printf "%.2f", p / r }')"
  echo "| bench/$scene | ${W}x${H}, 1 spp | $THREADS | ${rts_med} s | ${pov_med} s | ${ratio}x |"
  summaries+=("$scene: rts runs ${rts_times[*]}; POV-Ray runs ${pov_times[*]}"
              "  $(run_rts "$scene" 2>&1 | tail -1)")
done
# Fixed per-process cost (startup, parsing, a tiny image): POV-Ray's is large and is part of
# every POV-Ray time above; reported so that tracing speed alone can be compared as well.
W=16 H=12
rts_fixed="$(seconds run_rts render_scene)"
pov_fixed="$(seconds run_pov render_scene)"
echo
echo "Fixed cost (render_scene at 16x12): rts ${rts_fixed} s, POV-Ray ${pov_fixed} s"
printf '%s\n' "${summaries[@]}"
