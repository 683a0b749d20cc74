#!/usr/bin/env bash
# Animation and the scheduler contract (docs/scale-out.md): --frames and the '#' pattern,
# settings.frames, the clock, --task-index/--task-count and Slurm's array variables,
# --skip-existing and the manifest; GNU parallel renders 24 frames with 2 jobs, one job is
# killed mid-frame, the rerun completes the set, and every frame is byte-identical to a
# single-process render.
source "$(dirname "$0")/lib.sh"

cat >"$TMP/anim.rts" <<'SCENE'
settings { width = 48  height = 36  samples = 16 }
camera { position = <0, 2, -6>  look_at = <0, 0.5, 0>  fov = 50 }
area_light { position = <0, 6, -2>  u = <2, 0, 0>  v = <0, 0, 2>  samples = 4 }
plane { normal = <0, 1, 0> }
sphere { center = <-2 + 4 * clock, 0.5 + 0.05 * frame, 0>  radius = 0.5
         material = material { color = rgb(0.2 + 0.8 * clock, 0.3, 1 - clock / 2) } }
SCENE
sums() { (cd "$1" && md5sum ball_*.png) ; }

# A single process renders the reference frames.
mkdir -p "$TMP/ref"
expect_exit 0 "--frames 0..23 renders 24 frames" -- "$RTS" render "$TMP/anim.rts" --frames 0..23 -o "$TMP/ref/ball_####.png" --no-progress
n=$(ls "$TMP/ref"/ball_*.png | wc -l)
[[ "$n" == 24 ]] || { echo "FAIL: $n frames written, expected 24"; FAILS=$((FAILS + 1)); }
[[ -f "$TMP/ref/ball_0000.png" && -f "$TMP/ref/ball_0023.png" ]] || { echo "FAIL: frame names"; ls "$TMP/ref"; FAILS=$((FAILS + 1)); }
lines=$(wc -l <"$TMP/ref/ball.manifest.jsonl")
[[ "$lines" == 24 ]] || { echo "FAIL: manifest has $lines records, expected 24"; FAILS=$((FAILS + 1)); }
expect_grep "$TMP/ref/ball.manifest.jsonl" '"frame":23,"clock":1\.0,' "the last frame's clock is 1"
expect_grep "$TMP/ref/ball.manifest.jsonl" '"checksum":"fnv1a64:[0-9a-f]{16}"' "records carry a checksum"
expect_grep "$TMP/ref/ball.manifest.jsonl" '"scene_hash":"fnv1a64:[0-9a-f]{16}"' "records carry the scene hash"
expect_grep "$TMP/ref/ball.manifest.jsonl" '"error_rmse":[0-9.e-]+' "records carry the error estimate"
cmp -s "$TMP/ref/ball_0000.png" "$TMP/ref/ball_0023.png" && { echo "FAIL: the clock changes nothing"; FAILS=$((FAILS + 1)); }
sums "$TMP/ref" >"$TMP/ref.sums"

# Frames do not depend on which other frames the process rendered: one frame alone.
mkdir -p "$TMP/one"
expect_exit 0 "one frame alone" -- "$RTS" render "$TMP/anim.rts" --frames 0..23 --task-index 7 --task-count 24 -o "$TMP/one/ball_####.png" --no-progress
cmp "$TMP/one/ball_0007.png" "$TMP/ref/ball_0007.png" || { echo "FAIL: frame 7 alone differs"; FAILS=$((FAILS + 1)); }
[[ $(ls "$TMP/one"/ball_*.png | wc -l) == 1 ]] || { echo "FAIL: task 7 of 24 rendered more than frame 7"; FAILS=$((FAILS + 1)); }

# Slurm's job-array variables pick the task: 1 of 5 renders frames 1, 6, 11, 16, 21.
mkdir -p "$TMP/slurm"
SLURM_ARRAY_TASK_ID=4 SLURM_ARRAY_TASK_MIN=3 SLURM_ARRAY_TASK_COUNT=5 \
  "$RTS" render "$TMP/anim.rts" --frames 0..23 -o "$TMP/slurm/ball_####.png" --no-progress 2>"$TMP/err"
got=$(cd "$TMP/slurm" && ls ball_*.png | tr '\n' ' ')
[[ "$got" == "ball_0001.png ball_0006.png ball_0011.png ball_0016.png ball_0021.png " ]] ||
  { echo "FAIL: Slurm task 1 of 5 rendered: $got"; cat "$TMP/err"; FAILS=$((FAILS + 1)); }

# GNU parallel, 2 jobs; one job is killed mid-frame, the rerun completes the set.
mkdir -p "$TMP/par"
job=("$RTS" render "$TMP/anim.rts" --frames 0..23 -o "$TMP/par/ball_####.png" --no-progress --threads 1 --skip-existing --task-count 2 --task-index)
parallel -j2 "${job[@]}" ::: 0 1 >/dev/null 2>"$TMP/par1.err" &
par=$!
for _ in $(seq 1 400); do  # wait until task 1 has written a frame and is inside another
  [[ -f "$TMP/par/ball_0003.png" ]] && break
  sleep 0.05
done
victim=$(pgrep -f -- "--task-index 1\$" | head -1)
if [[ -n "$victim" ]]; then kill -9 "$victim"; else echo "note: task 1 had finished before it could be killed"; fi
wait "$par"; first=$?
written=$(ls "$TMP/par"/ball_*.png 2>/dev/null | wc -l)
if [[ -n "$victim" ]]; then
  [[ "$first" != 0 ]] || { echo "FAIL: parallel reported success after a killed job"; FAILS=$((FAILS + 1)); }
  [[ "$written" -lt 24 ]] || { echo "FAIL: all 24 frames exist after the kill"; FAILS=$((FAILS + 1)); }
fi
parallel -j2 "${job[@]}" ::: 0 1 >/dev/null 2>"$TMP/par2.err"
[[ $? == 0 ]] || { echo "FAIL: the rerun failed"; cat "$TMP/par2.err"; FAILS=$((FAILS + 1)); }
expect_grep "$TMP/par2.err" "skipped [1-9][0-9]* already written" "the rerun skips the frames already written"
sums "$TMP/par" >"$TMP/par.sums"
if cmp -s "$TMP/ref.sums" "$TMP/par.sums"; then echo "ok: 24 frames from parallel + kill + rerun are byte-identical"; else
  echo "FAIL: frames differ from the single-process render"; diff "$TMP/ref.sums" "$TMP/par.sums"; FAILS=$((FAILS + 1)); fi

# settings.frames gives the default range; --frames then picks frames of it, on its clock.
sed 's/samples = 16 }/samples = 16  frames = 24 }/' "$TMP/anim.rts" >"$TMP/anim24.rts"
mkdir -p "$TMP/set" && cd "$TMP/set"
expect_exit 0 "settings.frames, frames 5..6, default name" -- "$RTS" render "$TMP/anim24.rts" --frames 5..6 --no-progress
[[ -f anim24_0005.png && -f anim24_0006.png && ! -f anim24_0004.png ]] || { echo "FAIL: default frame names"; ls; FAILS=$((FAILS + 1)); }
cmp -s anim24_0005.png "$TMP/ref/ball_0005.png" || { echo "FAIL: frame 5 of settings.frames = 24 differs from frame 5 of 0..23"; FAILS=$((FAILS + 1)); }
expect_exit 2 "--frames past settings.frames" -- "$RTS" render "$TMP/anim24.rts" --frames 20..30 --no-progress
expect_grep "$TMP/err" "past the scene's last frame 23" "says where the animation ends"
cd - >/dev/null

# Usage errors, before anything is written.
expect_exit 2 "--frames backwards" -- "$RTS" render "$TMP/anim.rts" --frames 5..2 -o "$TMP/b_##.png"
expect_exit 2 "--frames not a range" -- "$RTS" render "$TMP/anim.rts" --frames 1-5 -o "$TMP/b_##.png"
expect_grep "$TMP/err" "A\.\.B" "says the form"
expect_exit 2 "several frames need a # pattern" -- "$RTS" render "$TMP/anim.rts" --frames 0..3 -o "$TMP/b.png"
expect_grep "$TMP/err" "no '#' run" "says why"
expect_exit 2 "task index out of range" -- "$RTS" render "$TMP/anim.rts" --frames 0..3 --task-index 2 --task-count 2 -o "$TMP/b_##.png"
expect_exit 2 "task index alone" -- "$RTS" render "$TMP/anim.rts" --frames 0..3 --task-index 1 -o "$TMP/b_##.png"
[[ -z "$(ls "$TMP"/b_* 2>/dev/null)" ]] || { echo "FAIL: a usage error wrote frames"; FAILS=$((FAILS + 1)); }

# Video: the frames in one file, written whole; what a video cannot do is a usage error.
expect_exit 0 "-o .mp4 encodes the frames" -- "$RTS" render "$TMP/anim.rts" --frames 0..5 -o "$TMP/v.mp4" --fps 12 --no-progress
expect_grep "$TMP/err" "v.mp4: 6 frames \(0\.\.5\), libx264 at 12 fps" "says what it wrote"
[[ "$(head -c 8 "$TMP/v.mp4" | tail -c 4)" == ftyp ]] || { echo "FAIL: v.mp4 is not an MP4"; FAILS=$((FAILS + 1)); }
expect_exit 0 "-o .webm encodes the frames" -- "$RTS" render "$TMP/anim.rts" --frames 0..2 -o "$TMP/v.webm" --no-progress
[[ "$(head -c 4 "$TMP/v.webm" | od -An -tx1 | tr -d ' ')" == 1a45dfa3 ]] || { echo "FAIL: v.webm is not WebM"; FAILS=$((FAILS + 1)); }
expect_exit 2 "a video has no AOVs" -- "$RTS" render "$TMP/anim.rts" --frames 0..2 -o "$TMP/w.mp4" --aov depth
expect_exit 2 "a video is not split over tasks" -- "$RTS" render "$TMP/anim.rts" --frames 0..2 -o "$TMP/w.mp4" --task-index 0 --task-count 2
ls "$TMP"/w.mp4* >/dev/null 2>&1 && { echo "FAIL: a refused video left a file"; FAILS=$((FAILS + 1)); }

# A still is unchanged; a scene that never reads the clock is warned about when animated.
cat >"$TMP/still.rts" <<'SCENE'
settings { width = 16  height = 12 }
camera { position = <0, 0, -5>  look_at = <0, 0, 0> }
point_light { position = <2, 3, -4> }
sphere { radius = 1 }
SCENE
"$RTS" render "$TMP/still.rts" -o "$TMP/still.png" --no-progress 2>/dev/null
expect_exit 0 "a still as one frame" -- "$RTS" render "$TMP/still.rts" --frames 0 -o "$TMP/still_#.png" --no-progress
cmp -s "$TMP/still.png" "$TMP/still_0.png" || { echo "FAIL: frame 0 of a still differs from the still"; FAILS=$((FAILS + 1)); }
expect_exit 0 "an animation that never reads the clock" -- "$RTS" render "$TMP/still.rts" --frames 0..1 -o "$TMP/same_#.png" --no-progress
expect_grep "$TMP/err" "never reads clock, frame or frames" "is warned about"
finish
