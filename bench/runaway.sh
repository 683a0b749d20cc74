#!/usr/bin/env bash
# Runaway scenes (issue 24): how long a macro that calls itself twice, 60 deep, runs at the
# default settings before the step budget (--max-steps, 100M) ends it with its located
# message. Target: within 10 s of wall time on a quiet machine. Prints the median wall and CPU
# (user + sys) time of RUNS runs, alternating with PEER (an older rts binary) when it is set.
#
#   bench/runaway.sh                       # 3 runs
#   PEER=/tmp/old-rts RUNS=5 bench/runaway.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
RUNS="${RUNS:-3}"
rts="${RTS:-$root/${RTS_BUILD_DIR:-build}/cli/rts}"
if [[ ! -x "$rts" ]]; then "$root/scripts/build" --target rts >&2; fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
printf 'macro f(d) {\n  if d > 0 { f(d - 1)  f(d - 1) }\n}\nf(60)\n' > "$tmp/bomb.rts"

measure() {  # prints "WALL CPU"; the run must fail with the step budget's located message
  /usr/bin/time -f "%e %U %S" -o "$tmp/time" "$1" check "$tmp/bomb.rts" >"$tmp/log" 2>&1 && {
    echo "bench/runaway.sh: the scene did not fail" >&2; exit 1; }
  grep -q "bomb.rts:2:[0-9]*: error: evaluation ran more than" "$tmp/log" || { cat "$tmp/log" >&2; exit 1; }
  tail -n 1 "$tmp/time" | awk '{ printf "%.2f %.2f\n", $1, $2 + $3 }'
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

names=(rts) bins=("$rts")
[[ -n "${PEER:-}" ]] && names+=(peer) bins+=("$PEER")
declare -A wall cpu
for ((i = 0; i < RUNS; ++i)); do
  for k in "${!bins[@]}"; do
    read -r w c < <(measure "${bins[$k]}")
    wall[$k]+=" $w" cpu[$k]+=" $c"
  done
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
for k in "${!bins[@]}"; do
  echo "${names[$k]}: wall median $(median ${wall[$k]}) s (runs:${wall[$k]}), CPU median $(median ${cpu[$k]}) s (runs:${cpu[$k]})"
done
