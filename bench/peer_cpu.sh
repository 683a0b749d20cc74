#!/usr/bin/env bash
# CPU time of this tree's rts against a peer binary (e.g. the commit before a change), on the
# render benchmarks' scenes, in alternating runs (peer, this, peer, this, ...) so machine
# noise hits both alike. Prints the median user+sys seconds of each and the ratio.
#
#   PEER=/path/to/old/rts bench/peer_cpu.sh                 # 320x240, 7 runs, 1 thread
#   PEER=... W=640 H=480 RUNS=9 SCENES="render_mesh" bench/peer_cpu.sh
# Used for the watertight triangle test (docs/performance.md, "Watertight triangles").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
W="${W:-320}"
H="${H:-240}"
RUNS="${RUNS:-7}"
MESH_N="${MESH_N:-300}"
SCENES="${SCENES:-render_mesh render_scene}"
rts="$(realpath "${RTS:-$root/${RTS_BUILD_DIR:-build}/cli/rts}")"
peer="$(realpath "${PEER:?set PEER to the rts binary to compare with}")"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cp "$root"/bench/render_scene.rts "$root"/bench/render_mesh.rts "$tmp/"
python3 "$root/bench/render_gen_mesh.py" "$MESH_N" "$tmp"

cpu() {  # user+sys seconds of one render
  /usr/bin/time -f '%U %S' -o "$tmp/time" "$1" render "$tmp/$2.rts" -o "$tmp/out.png" \
    --width "$W" --height "$H" --threads 1 --no-progress 2>/dev/null
  awk '{ printf "%.3f\n", $1 + $2 }' "$tmp/time"
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "| scene | size | peer CPU s (median of $RUNS) | this CPU s (median of $RUNS) | this / peer |"
echo "|---|---|---|---|---|"
for scene in $SCENES; do
  a=() b=()
  for ((i = 0; i < RUNS; i++)); do
    a+=("$(cpu "$peer" "$scene")")
    b+=("$(cpu "$rts" "$scene")")
  done
  ma=$(median "${a[@]}") mb=$(median "${b[@]}")
  echo "| $scene | ${W}x$H | $ma | $mb | $(awk -v a="$ma" -v b="$mb" 'BEGIN { printf "%.3f", b / a }') |"
done
