#!/usr/bin/env bash
# A still over MPI ranks and with a checkpoint (docs/scale-out.md): mpirun -np 1..4 gives the
# bytes of a single-process render (image, AOVs and ray counts); a render killed mid-way
# resumes from its checkpoint to the same bytes, alone and under mpirun; a torn last record is
# dropped; a journal made for other options is refused; a scene error under mpirun is reported
# once. Open MPI refuses root unless told: these variables allow it (CI runs as root).
source "$(dirname "$0")/lib.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Open MPI keeps allocations from MPI_Init until exit: LeakSanitizer would call them leaks.
export ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0"
if ! command -v mpirun >/dev/null; then echo "FAIL: mpirun is missing (scripts/ensure-deps installs openmpi-bin)"; exit 1; fi
MPIRUN=(mpirun --oversubscribe --bind-to none --mca btl self,vader -np)

cat >"$TMP/s.rts" <<'SCENE'
settings { width = 96  height = 72  samples = 8 }
camera { position = <0, 2, -6>  look_at = <0, 0.5, 0>  fov = 50 }
area_light { position = <0, 6, -2>  u = <2, 0, 0>  v = <0, 0, 2>  samples = 2 }
plane { normal = <0, 1, 0>  material = material { color = checker(rgb(0.9), rgb(0.2), 1) } }
sphere { center = <0, 1, 0>  radius = 1  material = material { color = rgb(0.8, 0.3, 0.2)  reflect = 0.4 } }
SCENE
rays() { grep -o '[0-9.]*[kM]* rays ([^)]*)' "$1"; }

"$RTS" render "$TMP/s.rts" -o "$TMP/one.png" --aov depth,normal,error --no-progress 2>"$TMP/one.err" ||
  { echo "FAIL: the single-process render"; cat "$TMP/one.err"; exit 1; }
for n in 1 2 3 4; do
  expect_exit 0 "mpirun -np $n" -- "${MPIRUN[@]}" "$n" "$RTS" render "$TMP/s.rts" -o "$TMP/np$n.png" \
      --aov depth,normal,error --threads 1 --no-progress
  for f in "" .depth .normal .error; do
    cmp -s "$TMP/one$f.png" "$TMP/np$n$f.png" || { echo "FAIL: -np $n: np$n$f.png differs from one process's"; FAILS=$((FAILS + 1)); }
  done
  [[ "$(rays "$TMP/err")" == "$(rays "$TMP/one.err")" ]] || { echo "FAIL: -np $n counts other rays:"; rays "$TMP/err"; rays "$TMP/one.err"; FAILS=$((FAILS + 1)); }
done
expect_grep "$TMP/err" "by the other 3 rank" "rank 0 reports the split"

# --tile-log: one JSON line per tile (96x72 in 16x16 tiles: 30), then the summary.
expect_exit 0 "mpirun -np 2 --tile-log" -- "${MPIRUN[@]}" 2 "$RTS" render "$TMP/s.rts" -o "$TMP/tl.png" \
    --threads 1 --no-progress --tile-log "$TMP/tl.jsonl"
python3 - "$TMP/tl.jsonl" <<'PY' || FAILS=$((FAILS + 1))
import json, sys
recs = [json.loads(l) for l in open(sys.argv[1])]
tiles, summary = recs[:-1], recs[-1].get("summary")
ok = summary is not None and len(tiles) == 30 and sorted(r["tile"] for r in tiles) == list(range(30)) \
     and summary["ranks"] == 2 and summary["rendered_remote"] == sum(r["rank"] == 1 for r in tiles) \
     and all(r["seconds"] >= 0 and r["bytes"] > 0 for r in tiles)
print("" if ok else f"FAIL: --tile-log holds {len(tiles)} tiles, summary {summary}")
sys.exit(0 if ok else 1)
PY

# Adaptive sampling: rank 0 plans every round from the whole image, so its decisions (the
# samples each pixel takes), the image, the error AOV and the error estimate are one process's
# for any rank count.
errline() { grep -o '[0-9.]* spp on average.*' "$1" | head -1; }
ADAPT=(--samples 64 --target-error 0.006 --aov error --no-progress)
"$RTS" render "$TMP/s.rts" -o "$TMP/ad.png" "${ADAPT[@]}" --threads 1 --stats-json "$TMP/ad.json" 2>"$TMP/ad.err" ||
  { echo "FAIL: the single-process adaptive render"; cat "$TMP/ad.err"; exit 1; }
for n in 1 3; do
  expect_exit 0 "adaptive under mpirun -np $n" -- "${MPIRUN[@]}" "$n" "$RTS" render "$TMP/s.rts" -o "$TMP/ad$n.png" \
      "${ADAPT[@]}" --threads 1 --stats-json "$TMP/ad$n.json"
  # --stats-json: the same document but for the clock (seconds, rays per second).
  python3 - "$TMP/ad.json" "$TMP/ad$n.json" <<'PY' || { echo "FAIL: adaptive -np $n: --stats-json differs beyond timings"; FAILS=$((FAILS + 1)); }
import json, sys
def load(p):
    d = json.load(open(p)); d.pop("seconds"); d["rays"].pop("per_second"); return d
sys.exit(0 if load(sys.argv[1]) == load(sys.argv[2]) else 1)
PY
  for f in "" .error; do
    cmp -s "$TMP/ad$f.png" "$TMP/ad$n$f.png" || { echo "FAIL: adaptive -np $n: ad$n$f.png differs from one process's"; FAILS=$((FAILS + 1)); }
  done
  [[ "$(errline "$TMP/err")" == "$(errline "$TMP/ad.err")" && -n "$(errline "$TMP/ad.err")" ]] ||
    { echo "FAIL: adaptive -np $n reports another error estimate:"; errline "$TMP/err"; errline "$TMP/ad.err"; FAILS=$((FAILS + 1)); }
  [[ "$(rays "$TMP/err")" == "$(rays "$TMP/ad.err")" ]] || { echo "FAIL: adaptive -np $n counts other rays"; FAILS=$((FAILS + 1)); }
done
expect_grep "$TMP/err" "over ([2-9]|[1-9][0-9]+) rounds" "the adaptive render ran in rounds"

# Killed mid-render, resumed from the checkpoint: the same bytes. The heavier scene makes sure
# the kill lands while tiles remain.
sed 's/samples = 8 }/samples = 256 }/' "$TMP/s.rts" >"$TMP/h.rts"
"$RTS" render "$TMP/h.rts" -o "$TMP/h.png" --no-progress 2>/dev/null
kill_after_tiles() {  # kill_after_tiles JOURNAL COMMAND...: start it, SIGKILL once JOURNAL has grown
  local journal="$1"; shift
  "$@" >/dev/null 2>&1 &
  local pid=$!
  for _ in $(seq 1 600); do
    [[ -f "$journal" && $(stat -c %s "$journal") -gt 60000 ]] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
}
kill_after_tiles "$TMP/ck1/rts-checkpoint.journal" "$RTS" render "$TMP/h.rts" -o "$TMP/h1.png" --threads 1 --checkpoint "$TMP/ck1" --no-progress
[[ -f "$TMP/h1.png" ]] && echo "note: the render finished before the kill"
expect_exit 0 "resume from the checkpoint" -- "$RTS" render "$TMP/h.rts" -o "$TMP/h1.png" --threads 1 --checkpoint "$TMP/ck1" --no-progress
expect_grep "$TMP/err" "[1-9][0-9]* from the checkpoint" "the resume reuses the journaled tiles"
cmp -s "$TMP/h.png" "$TMP/h1.png" || { echo "FAIL: the resumed image differs"; FAILS=$((FAILS + 1)); }

# The same under mpirun: the whole job is killed, and resumed with another rank count.
kill_after_tiles "$TMP/ck2/rts-checkpoint.journal" "${MPIRUN[@]}" 3 "$RTS" render "$TMP/h.rts" -o "$TMP/h2.png" --threads 1 --checkpoint "$TMP/ck2"
pkill -9 -f -- "--checkpoint $TMP/ck2" 2>/dev/null
expect_exit 0 "resume under mpirun -np 2" -- "${MPIRUN[@]}" 2 "$RTS" render "$TMP/h.rts" -o "$TMP/h2.png" --threads 1 --checkpoint "$TMP/ck2"
cmp -s "$TMP/h.png" "$TMP/h2.png" || { echo "FAIL: the image resumed under mpirun differs"; FAILS=$((FAILS + 1)); }

# An adaptive render killed and resumed: each round's tiles come back from the journal.
sed 's/samples = 8 }/samples = 96 }/' "$TMP/s.rts" >"$TMP/ha.rts"
HA=(--target-error 0.001 --no-progress --threads 1)
"$RTS" render "$TMP/ha.rts" -o "$TMP/ha.png" "${HA[@]}" 2>/dev/null
kill_after_tiles "$TMP/ck3/rts-checkpoint.journal" "$RTS" render "$TMP/ha.rts" -o "$TMP/ha1.png" "${HA[@]}" --checkpoint "$TMP/ck3"
expect_exit 0 "resume an adaptive render" -- "${MPIRUN[@]}" 2 "$RTS" render "$TMP/ha.rts" -o "$TMP/ha1.png" "${HA[@]}" --checkpoint "$TMP/ck3"
expect_grep "$TMP/err" "[1-9][0-9]* from the checkpoint" "the adaptive resume reuses journaled tiles"
cmp -s "$TMP/ha.png" "$TMP/ha1.png" || { echo "FAIL: the resumed adaptive image differs"; FAILS=$((FAILS + 1)); }

# A torn last record is dropped; the image is still the same.
size=$(stat -c %s "$TMP/ck1/rts-checkpoint.journal")
truncate -s $((size - 100)) "$TMP/ck1/rts-checkpoint.journal"
expect_exit 0 "a torn journal resumes" -- "$RTS" render "$TMP/h.rts" -o "$TMP/h3.png" --checkpoint "$TMP/ck1" --no-progress
expect_grep "$TMP/err" "torn last record" "says it dropped the torn record"
cmp -s "$TMP/h.png" "$TMP/h3.png" || { echo "FAIL: the image after a torn record differs"; FAILS=$((FAILS + 1)); }

# Another scene or other options: refused, nothing written.
expect_exit 3 "a journal for other options" -- "$RTS" render "$TMP/h.rts" -o "$TMP/h4.png" --samples 16 --checkpoint "$TMP/ck1" --no-progress
expect_grep "$TMP/err" "made for another scene or other options" "says why"
[[ -e "$TMP/h4.png" ]] && { echo "FAIL: a refused resume wrote an image"; FAILS=$((FAILS + 1)); }

# Errors under mpirun: a scene error once, from rank 0, with its location; exit codes as alone.
printf 'sphere { radius = oops }\n' >"$TMP/bad.rts"
expect_exit 1 "a scene error under mpirun" -- "${MPIRUN[@]}" 3 "$RTS" render "$TMP/bad.rts" -o "$TMP/bad.png"
[[ $(grep -c "error: undefined name 'oops'" "$TMP/err") == 1 ]] || { echo "FAIL: the error is not reported exactly once:"; cat "$TMP/err"; FAILS=$((FAILS + 1)); }
expect_grep "$TMP/err" "bad.rts:1:19" "located"
expect_exit 2 "an animation under mpirun is refused" -- "${MPIRUN[@]}" 2 "$RTS" render "$TMP/s.rts" --frames 0..3 -o "$TMP/f_#.png"
finish
