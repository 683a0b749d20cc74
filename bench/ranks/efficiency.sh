#!/usr/bin/env bash
# Efficiency of `mpirun -np N rts render` at 8, 64 and 256 ranks, SIMULATED from costs measured
# here (docs/scale-out.md): a one-process, one-thread render's --tile-log gives every tile's
# cost; an `mpirun -np 2` render's gives rank 0's serial cost per gathered tile; simulate.py
# replays them through rts's queue. Also prints the measured -np 2 wall time beside the
# simulated one, as a check of the model. Needs Open MPI (scripts/ensure-deps) and python3.
#   bench/ranks/efficiency.sh [SCENE] [extra rts render flags...]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
rts="${RTS_BINARY:-$root/build/cli/rts}"
scene="${1:-$root/bench/ranks/scene.rts}"
shift || true
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$rts" render "$scene" -o "$tmp/one.png" --threads 1 --no-progress --tile-log "$tmp/one.jsonl" "$@" 2>/dev/null
mpirun --oversubscribe --bind-to none --mca btl self,vader -np 2 \
  "$rts" render "$scene" -o "$tmp/np2.png" --threads 1 --no-progress --tile-log "$tmp/np2.jsonl" "$@" 2>/dev/null
cmp -s "$tmp/one.png" "$tmp/np2.png" || { echo "the -np 2 image differs from one process's" >&2; exit 1; }
python3 "$root/bench/ranks/simulate.py" "$tmp/one.jsonl" "$tmp/np2.jsonl"
echo "# the same image at 16x the samples (tile costs x 16):"
python3 "$root/bench/ranks/simulate.py" "$tmp/one.jsonl" "$tmp/np2.jsonl" --work 16
python3 - "$tmp/np2.jsonl" <<'PY'
import json, sys
s = [json.loads(l) for l in open(sys.argv[1])][-1]["summary"]
print(f"# measured -np 2 (1 thread a rank): start-up {(s['eval_seconds'] + s['build_seconds']) * 1e3:.1f} ms, "
      f"render {s['render_seconds']:.3f} s (compare the simulated 1x, 2-rank row)")
PY
