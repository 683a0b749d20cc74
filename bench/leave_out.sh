#!/usr/bin/env bash
# What a scene pays for features it does not use (issue 9). CPU time (user + sys) of `rts
# render` on one thread, medians of RUNS alternating runs of:
#   (a) bench/leave_out_a.rts     diffuse spheres, a plane, one point light
#   (b) bench/leave_out_b.rts     (a) plus unused declarations of every other feature, among
#                                 them a mesh of a ~20 MB OBJ and an image texture (both exist)
#   (c) bench/leave_out_c.rts     (a) with every other feature present at zero strength
#   (d) (a) with --no-specialize  the generic path
# then, specialised against --no-specialize, the glass scenes: bench/leave_out_glass.rts (400
# reflective spheres + 1 glass sphere) and bench/render_scene.rts (100 spheres, half mirrors,
# + 1 glass sphere). Prints a Markdown table (paste into docs/performance.md).
#
#   bench/leave_out.sh                  # RUNS=9, 1280x960, MESH_N=370 (a ~20 MB OBJ)
#   RUNS=5 SIZE="--width 640 --height 480" bench/leave_out.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
RUNS="${RUNS:-9}"
SIZE="${SIZE:---width 1280 --height 960}"   # (a)-(d) and the glass scenes
MESH_N="${MESH_N:-370}"
rts="$(realpath "${RTS:-$root/${RTS_BUILD_DIR:-build}/cli/rts}")"
if [[ ! -x "$rts" ]]; then "$root/scripts/build" --target rts >&2; fi

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cp "$root"/bench/leave_out_{a,b,c,glass}.rts "$root"/bench/render_scene.rts "$tmp/"
python3 "$root/bench/render_gen_mesh.py" "$MESH_N" "$tmp"
mv "$tmp/bench_mesh.obj" "$tmp/leave_out_big.obj"
(cd "$tmp" && "$rts" render leave_out_a.rts -o leave_out_tile.png --width 256 --height 256 --no-progress 2>/dev/null)

# CPU seconds (user + sys, from getrusage: millisecond resolution) of one render; a failure
# aborts the benchmark.
cpu() {
  (cd "$tmp" && python3 -c '
import resource, subprocess, sys
def used():  # children already waited for (a launcher shim counts too: subtracted)
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime
before = used()
if subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=open("last.log", "w")).returncode:
    sys.exit(1)
print(f"{used() - before:.3f}")' "$rts" render "$@" -o out.png --threads 1 --no-progress $SIZE) ||
    { tail -c 2000 "$tmp/last.log" >&2; exit 1; }
}
# Instructions of one render at a small size (valgrind): the figure the machine's load cannot
# blur. Skipped with INSTR=0.
instr() {
  (cd "$tmp" && valgrind --tool=callgrind --callgrind-out-file=/dev/null "$rts" render "$@" -o out.png --threads 1 \
     --no-progress --width 320 --height 240 2>&1 | awk '/Collected/ { print $4 }')
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
pct() { awk -v x="$1" -v r="$2" 'BEGIN { printf "%+.1f%%", (x / r - 1) * 100 }'; }

declare -A runs
variants=(a b c d)
args_a=(leave_out_a.rts) args_b=(leave_out_b.rts) args_c=(leave_out_c.rts) args_d=(leave_out_a.rts --no-specialize)
for ((i = 0; i < RUNS; ++i)); do
  for v in "${variants[@]}"; do
    declare -n args="args_$v"
    runs[$v]+="$(cpu "${args[@]}") "
  done
done
declare -A med
for v in "${variants[@]}"; do med[$v]="$(median ${runs[$v]})"; done

echo "| scene | CPU (median of $RUNS) | vs (a) |"
echo "|---|---|---|"
echo "| (a) diffuse spheres, plane, point light | ${med[a]} s | — |"
echo "| (b) (a) + unused declarations of every feature | ${med[b]} s | $(pct "${med[b]}" "${med[a]}") |"
echo "| (c) (a) + every feature at zero strength | ${med[c]} s | $(pct "${med[c]}" "${med[a]}") |"
echo "| (d) (a) with --no-specialize | ${med[d]} s | $(pct "${med[d]}" "${med[a]}") |"
if [[ "${INSTR:-1}" != 0 ]] && command -v valgrind >/dev/null; then
  echo
  echo "| scene, 320x240 | instructions (callgrind) | vs (a) |"
  echo "|---|---|---|"
  ia="$(instr leave_out_a.rts)"
  echo "| (a) | $ia | — |"
  for v in b c d; do
    declare -n args="args_$v"
    i="$(instr "${args[@]}")"
    echo "| ($v) | $i | $(pct "$i" "$ia") |"
  done
fi
echo
echo "| glass scene (${SIZE//--/}) | specialised | --no-specialize | gain | glass made opaque |"
echo "|---|---|---|---|---|"
for scene in leave_out_glass render_scene; do
  fast=() slow=() opaque=()
  for ((i = 0; i < RUNS; ++i)); do
    fast+=("$(cpu "$scene.rts")")
    slow+=("$(cpu "$scene.rts" --no-specialize)")
    [[ $scene == leave_out_glass ]] && opaque+=("$(cpu "$scene.rts" -D glass_transmit=0)")
  done
  f="$(median "${fast[@]}")" s="$(median "${slow[@]}")" o="-"
  [[ ${#opaque[@]} -gt 0 ]] && o="$(median "${opaque[@]}") s"
  echo "| bench/$scene.rts | $f s | $s s | $(awk -v f="$f" -v s="$s" 'BEGIN { printf "%.2fx", s / f }') | $o |"
done
echo
for v in "${variants[@]}"; do echo "($v) runs: ${runs[$v]}"; done
