#!/usr/bin/env bash
# Parser benchmark: generates a ~50 MB scene (bench/gen_scene.py, default 640k objects) and
# the equivalent POV-Ray scene, then times `rts parse --quiet` (the whole process: load,
# UTF-8 check, parse, AST) and POV-Ray parsing the .pov (+W1 +H1, so the run is its parse
# plus bounding; POV-Ray also reports its parse phase alone) in the same run. Prints medians
# of RUNS runs (default 3): wall time, CPU time, max RSS.
#
#   bench/parse.sh [--objects N] [--runs N] [--rts PATH_TO_RTS]
#
# Needs python3, GNU time (/usr/bin/time) and povray (scripts/ensure-deps --bench).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
objects=640000
runs=3
rts="${RTS_BIN:-}"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --objects) objects="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --rts) rts="$2"; shift 2 ;;
    *) echo "usage: bench/parse.sh [--objects N] [--runs N] [--rts PATH]" >&2; exit 2 ;;
  esac
done
if [[ -z "$rts" ]]; then
  "$root/scripts/build" --target rts >&2
  rts="$root/${RTS_BUILD_DIR:-build}/cli/rts"
fi
for tool in python3 /usr/bin/time povray; do
  command -v "$tool" >/dev/null || { echo "bench/parse.sh: $tool is required" >&2; exit 1; }
done

work="${TMPDIR:-/tmp}/rts-bench-parse"
mkdir -p "$work"
scene="$work/scene-$objects.rts"
pov="$work/scene-$objects.pov"
if [[ ! -f "$scene" || ! -f "$pov" ]]; then
  echo "generating $objects objects..." >&2
  python3 "$root/bench/gen_scene.py" --objects "$objects" --rts "$scene" --pov "$pov"
fi
bytes=$(stat -c %s "$scene")

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

rts_wall=(); rts_rss=(); rts_cpu=(); pov_wall=(); pov_parse=()
for ((i = 1; i <= runs; i++)); do
  /usr/bin/time -f "%e %M %U %S" -o "$work/rts.time" "$rts" parse --quiet "$scene"
  read -r wall rss user sys < "$work/rts.time"
  rts_wall+=("$wall"); rts_rss+=("$rss"); rts_cpu+=("$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')")
  /usr/bin/time -f "%e" -o "$work/pov.time" \
    povray +W1 +H1 -D +GS +V "+I$pov" "+O$work/pov.png" 2> "$work/pov.log" >/dev/null
  pov_wall+=("$(cat "$work/pov.time")")
  # POV-Ray's own "Parse Time: ... (12.345 seconds)" line.
  pov_parse+=("$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov.log" | head -1)")
  echo "run $i: rts ${wall}s (user ${user}s sys ${sys}s) ${rss}KB | povray ${pov_wall[-1]}s (parse ${pov_parse[-1]}s)" >&2
done

rw=$(printf '%s\n' "${rts_wall[@]}" | median)
rr=$(printf '%s\n' "${rts_rss[@]}" | median)
rc=$(printf '%s\n' "${rts_cpu[@]}" | median)
pw=$(printf '%s\n' "${pov_wall[@]}" | median)
pp=$(printf '%s\n' "${pov_parse[@]}" | median)
awk -v b="$bytes" -v rw="$rw" -v rc="$rc" -v rr="$rr" -v pw="$pw" -v pp="$pp" -v n="$objects" -v runs="$runs" 'BEGIN {
  mb = b / 1e6
  printf "scene: %d objects, %.1f MB; medians of %d runs\n", n, mb, runs
  printf "rts parse --quiet : %6.2f s  %6.1f MB/s  max RSS %.0f MB (%.1fx the file)\n", rw, mb / rw, rr / 1024, rr * 1024 / b
  printf "  its CPU time      : %6.2f s  %6.1f MB/s  (user + sys; the wall time includes waiting on a busy machine)\n", rc, mb / rc
  printf "povray (whole run): %6.2f s  %6.1f MB/s\n", pw, mb / pw
  if (pp > 0) printf "povray parse time : %6.2f s  (its own report)\n", pp
  printf "rts is %.1fx faster than the POV-Ray run", pw / rw
  if (pp > 0) printf ", %.1fx faster than its parse phase", pp / rw
  printf "\n"
}'
