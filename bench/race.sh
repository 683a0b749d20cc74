#!/usr/bin/env bash
# The performance suite (issue 12): rts against POV-Ray 3.7 on equivalent scene pairs
# (bench/race/*.rts and *.pov: same camera, size, objects, lights, recursion depth, samples),
# in the same run, alternating rts and POV-Ray, with the same thread count. For each scene it
# prints the median wall time, CPU time (user + system) and peak RSS of RUNS runs of each
# program and the ratios rts / POV-Ray, plus rts's own phase split; then the Embree harness
# (bench/embree_rays.cpp) on the terrain's camera + shadow rays, and rts's serial I/O rates.
# The table, the machine and the date are written into docs/performance.md between the
# "race:begin" and "race:end" markers (NO_DOC=1 leaves the file alone).
#
#   bench/race.sh                              # 800x600, 3 runs, 2 threads, every scene
#   RUNS=5 THREADS=1 SCENES="spheres glass" bench/race.sh
#
# Scenes: spheres (400 reflective spheres and a glass one), terrain (320k-triangle height field,
# camera + shadow rays), grid90k (90,000 spheres placed by loops), soft (16-sample area light,
# 4 spp), glossy (blurred reflections: roughness 0.1-0.2, 4 spp; POV-Ray's micro-normals with
# the same 2x2 supersampling), glass (nested glass, depth 10), loop (a 1M-iteration evaluation loop: `rts check`
# against POV-Ray parsing), mesh2m (a 2M-triangle height field: memory and BVH build rate),
# patterns (wood, marble, granite, agate and bumps: procedural texture cost), csg (36 dice as
# box-and-sphere intersections minus six pips, lenses, a cut torus), isosurface (three compiled
# functions: a rippled ball, a gyroid, a torus).
# Generated meshes are cached in $RTS_BUILD_DIR/bench-race (never in the repository).
# Fairness choices are explained in docs/performance.md ("The suite").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
W="${W:-800}"
H="${H:-600}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-2}"
SCENES="${SCENES:-spheres terrain grid90k soft glossy glass loop mesh2m patterns csg isosurface}"
build="$root/${RTS_BUILD_DIR:-build}"

"$root/scripts/ensure-deps" --bench
"$root/scripts/build" --target rts rts-bench-io >&2
# The Embree harness is built where libembree-dev is installed (optional).
"$root/scripts/build" --target rts-bench-embree >&2 2>/dev/null || echo "bench/race.sh: no Embree harness (libembree-dev missing)" >&2
rts="$build/cli/rts"
for tool in python3 /usr/bin/time povray; do
  command -v "$tool" >/dev/null || { echo "bench/race.sh: $tool is required" >&2; exit 1; }
done

data="$build/bench-race"
mkdir -p "$data"
cp "$root"/bench/race/*.rts "$root"/bench/race/*.pov "$root"/bench/eval_loop.{rts,pov} "$data/"
for mesh in terrain:400 mesh2m:1000; do
  name="${mesh%%:*}" n="${mesh##*:}"
  if [[ ! -f "$data/$name.obj" || ! -f "$data/$name.inc" || "$root/bench/race/gen_terrain.py" -nt "$data/$name.obj" ]]; then
    echo "generating $name ($((2 * n * n)) triangles)..." >&2
    python3 "$root/bench/race/gen_terrain.py" "$n" "$data/$name"
  fi
done

# One run: prints "WALL CPU RSS_MB"; its output is kept in $data/last.log.
measure() {
  /usr/bin/time -f "%e %U %S %M" -o "$data/time" "$@" >"$data/last.log" 2>&1 || { tail -c 3000 "$data/last.log" >&2; exit 1; }
  awk '{ printf "%.3f %.3f %.0f\n", $1, $2 + $3, $4 / 1024 }' "$data/time"
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }'; }

# The command lines of one scene, into the arrays rts_cmd and pov_cmd.
commands() {
  case "$1" in
    loop)
      rts_cmd=("$rts" check eval_loop.rts)
      pov_cmd=(povray +Ieval_loop.pov +Oloop.pov.png +W8 +H8 -D -A +FN -GA) ;;
    soft|glossy)
      rts_cmd=("$rts" render "$1.rts" -o "$1.rts.png" --width "$W" --height "$H" --threads "$THREADS" --no-progress)
      # POV-Ray's antialiasing as 4 spp: method 1 with threshold 0 supersamples every pixel
      # that differs from its neighbours at all with 2x2 rays (rts: 4 stratified samples).
      pov_cmd=(povray "+I$1.pov" "+O$1.pov.png" "+W$W" "+H$H" -D +AM1 +A0.0 +R2 -J "+WT$THREADS" -GA) ;;
    *)
      rts_cmd=("$rts" render "$1.rts" -o "$1.rts.png" --width "$W" --height "$H" --threads "$THREADS" --no-progress)
      pov_cmd=(povray "+I$1.pov" "+O$1.pov.png" "+W$W" "+H$H" -D -A "+WT$THREADS" -GA) ;;
  esac
}

date_utc="$(date -u '+%Y-%m-%d %H:%M UTC')"
cpu_model="$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"
machine="$(nproc) CPUs ($cpu_model), $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo), load average at start $(cut -d' ' -f1-3 /proc/loadavg)"
pov_version="$(povray --version 2>&1 | awk '/POV-Ray/ { print; exit }')"

table="$data/table.md"
{
  echo "Measured $date_utc on $machine; $pov_version; ${W}x${H}, $THREADS threads, medians of $RUNS alternating runs."
  echo
  echo "| scene | rts wall | rts CPU | rts peak RSS | POV-Ray wall | POV-Ray CPU | POV-Ray peak RSS | rts/POV wall | rts/POV CPU |"
  echo "|---|---|---|---|---|---|---|---|---|"
} >"$table"
notes=()
cd "$data"
for scene in $SCENES; do
  rw=() rc=() rm=() pw=() pc=() pm=()
  commands "$scene"
  for ((i = 0; i < RUNS; ++i)); do
    read -r w c m < <(measure "${rts_cmd[@]}")
    rw+=("$w") rc+=("$c") rm+=("$m")
    summary="$(grep -E '^rts: |^evaluated' "$data/last.log" | tail -1 || true)"
    read -r w c m < <(measure "${pov_cmd[@]}")
    pw+=("$w") pc+=("$c") pm+=("$m")
  done
  mrw="$(median "${rw[@]}")" mrc="$(median "${rc[@]}")" mrm="$(median "${rm[@]}")"
  mpw="$(median "${pw[@]}")" mpc="$(median "${pc[@]}")" mpm="$(median "${pm[@]}")"
  line="| $scene | $mrw s | $mrc s | $mrm MB | $mpw s | $mpc s | $mpm MB | $(ratio "$mrw" "$mpw") | $(ratio "$mrc" "$mpc") |"
  echo "$line" >>"$table"
  echo "$line" >&2
  notes+=("- $scene: rts runs (wall) ${rw[*]}; POV-Ray ${pw[*]}. rts: ${summary#rts: }")
done

# Fixed per-process cost (the spheres at 16x12): POV-Ray's start-up is inside every POV-Ray time.
read -r rfw rfc _ < <(measure "$rts" render spheres.rts -o fixed.png --width 16 --height 12 --threads "$THREADS" --no-progress)
read -r pfw pfc _ < <(measure povray +Ispheres.pov +Ofixed.pov.png +W16 +H12 -D -A "+WT$THREADS" -GA)
{
  echo
  echo "Fixed cost per process (spheres at 16x12): rts $rfw s wall / $rfc s CPU, POV-Ray $pfw s wall / $pfc s CPU."
  echo
  printf '%s\n' "${notes[@]}"
} >>"$table"

# rts's serial phases and the Embree ceiling on the terrain's rays.
{
  echo
  echo "Serial phases (\`rts-bench-io\`, medians):"
  echo
  echo "- OBJ loading: $("$build/bench/rts-bench-io" obj terrain.obj 3)"
  "$rts" render spheres.rts -o spheres1080.png --width 1920 --height 1080 --threads "$THREADS" --no-progress 2>/dev/null
  echo "- PNG writing: $("$build/bench/rts-bench-io" png spheres1080.png 5)"
  if [[ -x "$build/bench/rts-bench-embree" ]]; then
    echo
    echo "Embree 3 on the terrain's rays (\`rts-bench-embree\`, $THREADS threads, ${W}x${H}):"
    echo
    "$build/bench/rts-bench-embree" terrain.obj "$W" "$H" "$THREADS" | sed 's/^/- /'
  fi
} >>"$table"
cat "$table"

if [[ "${NO_DOC:-}" != 1 ]]; then
  doc="$root/docs/performance.md"
  python3 "$root/bench/write_doc_section.py" "$doc" race bench/race.sh "$table"
  echo "wrote the table into docs/performance.md" >&2
fi
