#!/usr/bin/env bash
# Evaluation race: how fast rts evaluates a scene program (`rts check`: parse + evaluate +
# build the scene, no render) against POV-Ray 3.7 parsing the equivalent scene, in the same run.
#   eval_loop     1,000,000 iterations of s = s + sin(i * 0.001) * cos(i * 0.002)
#   eval_spheres  90,000 spheres from nested loops, each with its own derived material
# POV-Ray runs with an 8x8 image and no antialiasing (+W8 +H8 -A), so its time is parsing
# plus a negligible render; its own "Parse Time" is reported too. Prints medians of RUNS runs
# (wall and CPU time) and the ratios as a Markdown table (paste into docs/performance.md, "## Evaluation").
#
#   bench/eval.sh            # 5 runs each
#   RUNS=9 bench/eval.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
RUNS="${RUNS:-5}"
rts="${RTS:-$root/${RTS_BUILD_DIR:-build}/cli/rts}"
if [[ ! -x "$rts" ]]; then "$root/scripts/build" --target rts >&2; fi
command -v povray >/dev/null || { echo "bench/eval.sh: povray not found (scripts/ensure-deps --bench)" >&2; exit 1; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# Runs one command; prints "WALL CPU" in seconds (CPU = user + system, which a busy shared
# machine disturbs less than wall time); its output is kept in $tmp/last.log.
measure() {
  /usr/bin/time -f "%e %U %S" -o "$tmp/time" "$@" >"$tmp/last.log" 2>&1 || { cat "$tmp/last.log" >&2; exit 1; }
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$tmp/time"
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "| benchmark | rts check: wall | rts: CPU | rts: evaluation | POV-Ray: wall | POV-Ray: CPU | POV-Ray: parse time | POV-Ray / rts (wall) | POV-Ray / rts (CPU) |"
echo "|---|---|---|---|---|---|---|---|---|"
for name in eval_loop eval_spheres; do
  rts_wall=() rts_cpu=() rts_eval=() pov_wall=() pov_cpu=() pov_parse=()
  for ((i = 0; i < RUNS; ++i)); do
    read -r w c < <(measure "$rts" check "$root/bench/$name.rts")
    rts_wall+=("$w") rts_cpu+=("$c")
    rts_eval+=("$(awk '/^evaluated in/ { print $3 }' "$tmp/last.log")")
    read -r w c < <(measure povray "+I$root/bench/$name.pov" "+O$tmp/pov.png" +W8 +H8 -D -A +FN)
    pov_wall+=("$w") pov_cpu+=("$c")
    # POV-Ray prints "Parse Time: 0 hours 0 minutes 0 seconds (0.969 seconds)".
    pov_parse+=("$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$tmp/last.log" | head -1)")
  done
  rw="$(median "${rts_wall[@]}")" rc="$(median "${rts_cpu[@]}")" re="$(median "${rts_eval[@]}")"
  pw="$(median "${pov_wall[@]}")" pc="$(median "${pov_cpu[@]}")" pp="$(median "${pov_parse[@]}")"
  ratio_wall="$(echo "scale=1; $pw / $rw" | bc)"
  ratio_cpu="$(echo "scale=1; $pc / $rc" | bc)"
  echo "| $name | ${rw} s | ${rc} s | ${re} s | ${pw} s | ${pc} s | ${pp} s | ${ratio_wall}x | ${ratio_cpu}x |"
  echo "<!-- $name runs (wall): rts ${rts_wall[*]}; POV-Ray ${pov_wall[*]} -->"
done
echo
echo "Medians of $RUNS runs each."
