// Animation frames on the command line: the frame range (--frames A..B), the output name
// pattern (out/ball_####.png), the clock of each frame, and which frames this process renders
// when a scheduler runs several (--task-index/--task-count, or a Slurm job array).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rts::cli {

// Frames first..last, both included (as POV-Ray's +KFI/+KFF): "0..99" is 100 frames.
struct FrameRange {
  int64_t first = 0, last = 0;
  int64_t count() const { return last - first + 1; }
};

// "A..B" (A <= B) or a single frame "N"; whole numbers from 0 to render::kMaxFrames - 1.
// Returns an error message for the user, or empty on success.
std::string parse_frame_range(const std::string& text, FrameRange& out);

// The built-in `clock` at `frame`: 0 at the first frame, 1 at the last (0 for one frame).
double frame_clock(const FrameRange& range, int64_t frame);

// True when `pattern`'s file name has a run of '#' (the frame number goes there).
bool has_frame_pattern(const std::string& pattern);
// `pattern` with its last '#' run replaced by `frame`, zero-padded to the run's length (a
// longer number is written whole, never cut).
std::string frame_path(const std::string& pattern, int64_t frame);
// The default pattern for a scene: "scene_####.png" beside the current folder.
std::string default_frame_pattern(const std::string& scene_path);
// The manifest beside the frames: out/ball_####.png -> out/ball.manifest.jsonl.
std::string default_manifest_path(const std::string& pattern);

// This process's share of a run of several: task `index` of `count`.
struct TaskSlice {
  int64_t index = 0, count = 1;
};
// The task from --task-index/--task-count when given, else from Slurm's job-array variables
// (SLURM_ARRAY_TASK_ID minus SLURM_ARRAY_TASK_MIN, of SLURM_ARRAY_TASK_COUNT), else 0 of 1.
// Returns an error message for the user, or empty.
std::string resolve_task(std::optional<int64_t> index, std::optional<int64_t> count, TaskSlice& out);
// The frames of `range` task `task` renders: every count-th frame from first + index, so
// that tasks of a job array share the work evenly whatever the range's length.
std::vector<int64_t> task_frames(const FrameRange& range, const TaskSlice& task);

}  // namespace rts::cli
