#!/usr/bin/env bash
# How rts's cost grows with scene size (issue 12): build time, render time and peak memory
# for 1k to 4M primitives, spheres placed by loops and triangles of one height-field mesh, at
# a fixed image (400x300, 1 spp, camera + shadow rays). Prints a table; writes it between the
# "growth:begin"/"growth:end" markers of docs/performance.md and plots it on log axes into
# docs/images/perf_growth_*.svg (NO_DOC=1: print only). With a BVH, render time should grow
# about as log(primitives) and build time and memory about linearly.
#
#   bench/growth.sh                      # every size, 3 runs each (medians), 2 threads
#   RUNS=1 MAX=262144 bench/growth.sh    # quicker: sizes up to MAX primitives
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-2}"
MAX="${MAX:-4194304}"
build="$root/${RTS_BUILD_DIR:-build}"
load_at_start="$(cut -d' ' -f1-3 /proc/loadavg)"
"$root/scripts/build" --target rts >&2
rts="$build/cli/rts"
data="$build/bench-growth"
mkdir -p "$data"

median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
# One run of `rts render ARGS...`: prints "BUILD_S RENDER_S PEAK_MB".
measure() {
  /usr/bin/time -f "%M" -o "$data/time" "$rts" render "$@" --threads "$THREADS" --no-progress \
    --stats-json "$data/stats.json" -o "$data/out.png" >"$data/last.log" 2>&1 || { tail -c 2000 "$data/last.log" >&2; exit 1; }
  python3 - "$data/stats.json" "$data/time" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["seconds"]
kb = int(open(sys.argv[2]).read().split()[-1])
print(f'{s["build"]:.4f} {s["render"]:.4f} {kb / 1024:.1f}')
PY
}

rows=()
series_file="$data/rows.txt"
: > "$series_file"
run_size() {  # KIND PRIMITIVES ARGS...
  local kind="$1" prims="$2"
  shift 2
  local b=() r=() m=()
  for ((i = 0; i < RUNS; i++)); do
    read -r bs rs mb < <(measure "$@")
    b+=("$bs") r+=("$rs") m+=("$mb")
  done
  local line
  line="$kind $prims $(median "${b[@]}") $(median "${r[@]}") $(median "${m[@]}")"
  echo "$line" | tee -a "$series_file" >&2
}

for n in 32 64 128 256 512 1024 2048; do
  prims=$((n * n))
  ((prims <= MAX)) || continue
  run_size spheres "$prims" "$root/bench/growth/spheres.rts" -D "n=$n"
done
for n in 23 45 91 181 362 724 1448; do
  prims=$((2 * n * n))
  ((prims <= MAX)) || continue
  dir="$data/terrain$n"
  mkdir -p "$dir"
  cp "$root/bench/growth/terrain.rts" "$dir/"
  if [[ ! -f "$dir/terrain.obj" || "$root/bench/race/gen_terrain.py" -nt "$dir/terrain.obj" ]]; then
    echo "generating terrain $n ($prims triangles)..." >&2
    python3 "$root/bench/race/gen_terrain.py" "$n" "$dir/terrain" && rm -f "$dir/terrain.inc"
  fi
  run_size triangles "$prims" "$dir/terrain.rts"
done

cpu_model="$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"
header="Measured $(date -u '+%Y-%m-%d %H:%M') UTC on $(nproc) CPUs ($cpu_model), load average at start $load_at_start; 400x300, 1 spp, $THREADS threads, medians of $RUNS runs. Peak memory is the whole process's."
python3 - "$series_file" "$data" "$header" "${NO_DOC:-0}" "$root" <<'PY'
import json, os, subprocess, sys
rows_file, data, header, no_doc, root = sys.argv[1:6]
rows = [l.split() for l in open(rows_file) if l.strip()]
table = [header, "",
         "| primitives | kind | build | render | peak memory | bytes per primitive |",
         "|---|---|---|---|---|---|"]
by_kind = {}
for kind, n, b, r, m in rows:
    n, b, r, m = int(n), float(b), float(r), float(m)
    by_kind.setdefault(kind, []).append((n, b, r, m))
    table.append(f"| {n:,} | {kind} | {b:.3f} s | {r:.3f} s | {m:.0f} MB | {m * 2**20 / n:.0f} |")
text = "\n".join(table)
print(text)
if no_doc == "1":
    sys.exit(0)
plots = [("render", 2, "Render time (400x300, 1 spp)", "seconds"),
         ("build", 1, "Build time (flatten, BVHs)", "seconds"),
         ("memory", 3, "Peak memory (whole process)", "MB")]
for name, col, title, unit in plots:
    series = [{"name": k, "points": [[p[0], max(p[col], 1e-4)] for p in v]} for k, v in by_kind.items()]
    path = os.path.join(data, f"{name}.json")
    json.dump(series, open(path, "w"))
    subprocess.run([sys.executable, os.path.join(root, "bench/plot_svg.py"),
                    os.path.join(root, f"docs/images/perf_growth_{name}.svg"), title, "primitives", unit,
                    "log", "log", path], check=True)
table_file = os.path.join(data, "table.md")
open(table_file, "w").write(text + "\n")
subprocess.run([sys.executable, os.path.join(root, "bench/write_doc_section.py"), os.path.join(root, "docs/performance.md"),
                "growth", "bench/growth.sh", table_file], check=True)
print("wrote the table into docs/performance.md and docs/images/perf_growth_*.svg", file=sys.stderr)
PY
