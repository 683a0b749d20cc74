#!/usr/bin/env bash
# Thread scaling of the render phase (issue 12): `seconds.render` of --stats-json for 1, 2, 4 ...
# up to all cores on the race scenes (bench/race/*.rts), medians of RUNS runs, and the speedup
# over one thread. Prints a table; writes it between the "scaling:begin"/"scaling:end" markers
# of docs/performance.md and plots it into docs/images/perf_scaling.svg (NO_DOC=1: print only).
#
#   bench/scaling.sh                          # 400x300, 3 runs, spheres soft glossy glass terrain
#   W=800 H=600 RUNS=5 SCENES="soft" bench/scaling.sh
#   RTS_BIN=/path/to/rts NO_DOC=1 bench/scaling.sh   # a binary built elsewhere (another machine)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
W="${W:-400}"
H="${H:-300}"
RUNS="${RUNS:-3}"
SCENES="${SCENES:-spheres soft glossy glass terrain}"
build="$root/${RTS_BUILD_DIR:-build}"
load_at_start="$(cut -d' ' -f1-3 /proc/loadavg)"
if [[ -n "${RTS_BIN:-}" ]]; then
  rts="$RTS_BIN"
else
  "$root/scripts/build" --target rts >&2
  rts="$build/cli/rts"
fi
data="$build/bench-race"   # shared with bench/race.sh (the generated terrain)
mkdir -p "$data"
cp "$root"/bench/race/*.rts "$data/"
# The meshes the race scenes read, generated as bench/race.sh does (mesh2m failed here before).
for mesh in terrain:400 mesh2m:1000; do
  name="${mesh%%:*}" n="${mesh##*:}"
  if [[ " $SCENES " == *" $name "* && ( ! -f "$data/$name.obj" || "$root/bench/race/gen_terrain.py" -nt "$data/$name.obj" ) ]]; then
    echo "generating $name ($((2 * n * n)) triangles)..." >&2
    python3 "$root/bench/race/gen_terrain.py" "$n" "$data/$name"
  fi
done

cores="$(nproc)"
threads=()
for ((t = 1; t < cores; t *= 2)); do threads+=("$t"); done
threads+=("$cores")

median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
render_seconds() {  # SCENE THREADS
  "$rts" render "$data/$1.rts" -o "$data/scaling.png" --width "$W" --height "$H" --threads "$2" --no-progress \
    --stats-json "$data/scaling.json" >"$data/scaling.log" 2>&1 || { tail -c 2000 "$data/scaling.log" >&2; exit 1; }
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["seconds"]["render"])' "$data/scaling.json"
}

rows="$data/scaling_rows.txt"
: > "$rows"
for scene in $SCENES; do
  declare -A times=()
  # Runs alternate over the thread counts, so a change of load hits each count alike.
  for ((i = 0; i < RUNS; i++)); do
    for t in "${threads[@]}"; do times[$t]+="$(render_seconds "$scene" "$t") "; done
  done
  for t in "${threads[@]}"; do
    # shellcheck disable=SC2086
    echo "$scene $t $(median ${times[$t]})" | tee -a "$rows" >&2
  done
  unset times
done

cpu_model="$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"
header="Measured $(date -u '+%Y-%m-%d %H:%M') UTC on $cores CPUs ($cpu_model), load average at start $load_at_start; ${W}x${H}, render phase only (\`seconds.render\`), medians of $RUNS alternating runs."
python3 - "$rows" "$header" "${NO_DOC:-0}" "$root" "$data" <<'PY'
import json, os, subprocess, sys
rows_file, header, no_doc, root, data = sys.argv[1:6]
rows = [l.split() for l in open(rows_file) if l.strip()]
scenes = {}
for scene, t, s in rows:
    scenes.setdefault(scene, []).append((int(t), float(s)))
counts = sorted({t for v in scenes.values() for t, _ in v})
table = [header, "", "| scene | " + " | ".join(f"{t} thread{'s' if t > 1 else ''}" for t in counts) + " |",
         "|---|" + "---|" * len(counts)]
for scene, v in scenes.items():
    one = dict(v)[1]
    cells = [f"{s:.3f} s ({one / s:.2f}×)" for t, s in sorted(v)]
    table.append(f"| {scene} | " + " | ".join(cells) + " |")
text = "\n".join(table)
print(text)
if no_doc == "1":
    sys.exit(0)
series = [{"name": k, "points": [[t, dict(v)[1] / s] for t, s in sorted(v)]} for k, v in scenes.items()]
series.append({"name": "ideal", "points": [[t, t] for t in counts]})
path = os.path.join(data, "scaling_series.json")
json.dump(series, open(path, "w"))
subprocess.run([sys.executable, os.path.join(root, "bench/plot_svg.py"), os.path.join(root, "docs/images/perf_scaling.svg"),
                "Render-phase speedup over one thread", "threads", "speedup", "linear", "linear", path], check=True)
table_file = os.path.join(data, "scaling_table.md")
open(table_file, "w").write(text + "\n")
subprocess.run([sys.executable, os.path.join(root, "bench/write_doc_section.py"), os.path.join(root, "docs/performance.md"),
                "scaling", "bench/scaling.sh", table_file], check=True)
print("wrote the table into docs/performance.md and docs/images/perf_scaling.svg", file=sys.stderr)
PY
