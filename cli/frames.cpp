#include "cli/frames.hpp"

#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "render/scene/scene.hpp"

namespace rts::cli {
namespace {

// A whole number from 0 to `max` made of digits only; false otherwise.
bool parse_whole(const std::string& s, int64_t max, int64_t& out) {
  if (s.empty() || s.size() > 18) return false;
  int64_t v = 0;
  for (char ch : s) {
    if (ch < '0' || ch > '9') return false;
    v = v * 10 + (ch - '0');
  }
  if (v > max) return false;
  out = v;
  return true;
}

std::optional<int64_t> env_whole(const char* name) {
  const char* v = std::getenv(name);
  int64_t out = 0;
  if (v == nullptr || !parse_whole(v, INT64_MAX / 16, out)) return std::nullopt;
  return out;
}

// The position of the last '#' run in the file-name part of `path`: [begin, end).
bool find_run(const std::string& path, std::size_t& begin, std::size_t& end) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t name = slash == std::string::npos ? 0 : slash + 1;
  const std::size_t last = path.find_last_of('#');
  if (last == std::string::npos || last < name) return false;
  end = last + 1;
  begin = last;
  while (begin > name && path[begin - 1] == '#') --begin;
  return true;
}

}  // namespace

std::string parse_frame_range(const std::string& text, FrameRange& out) {
  const int64_t max = render::kMaxFrames - 1;
  const std::size_t dots = text.find("..");
  FrameRange r;
  if (dots == std::string::npos) {
    if (!parse_whole(text, max, r.first))
      return fmt::format("expects a frame range A..B or one frame N (whole numbers from 0 to {}), got '{}'", max, text);
    r.last = r.first;
  } else if (!parse_whole(text.substr(0, dots), max, r.first) || !parse_whole(text.substr(dots + 2), max, r.last)) {
    return fmt::format("expects a frame range A..B (whole numbers from 0 to {}, both included), got '{}'", max, text);
  } else if (r.first > r.last) {
    return fmt::format("the first frame must not come after the last, got '{}'", text);
  }
  out = r;
  return {};
}

double frame_clock(const FrameRange& range, int64_t frame) {
  if (range.last == range.first) return 0.0;
  return static_cast<double>(frame - range.first) / static_cast<double>(range.last - range.first);
}

bool has_frame_pattern(const std::string& pattern) {
  std::size_t b = 0, e = 0;
  return find_run(pattern, b, e);
}

std::string frame_path(const std::string& pattern, int64_t frame) {
  std::size_t b = 0, e = 0;
  if (!find_run(pattern, b, e)) return pattern;
  return pattern.substr(0, b) + fmt::format("{:0{}}", frame, e - b) + pattern.substr(e);
}

std::string default_frame_pattern(const std::string& scene_path) {
  return std::filesystem::path(scene_path).stem().string() + "_####.png";
}

std::string default_manifest_path(const std::string& pattern) {
  std::size_t b = 0, e = 0;
  std::string stem = pattern;
  if (find_run(pattern, b, e)) stem = pattern.substr(0, b) + pattern.substr(e);
  const std::size_t slash = stem.find_last_of('/');
  const std::size_t name = slash == std::string::npos ? 0 : slash + 1;
  const std::size_t dot = stem.find_last_of('.');
  if (dot != std::string::npos && dot > name) stem.resize(dot);
  while (stem.size() > name && (stem.back() == '_' || stem.back() == '-' || stem.back() == '.')) stem.pop_back();
  if (stem.size() == name) stem += "frames";
  return stem + ".manifest.jsonl";
}

std::string resolve_task(std::optional<int64_t> index, std::optional<int64_t> count, TaskSlice& out) {
  TaskSlice t;
  if (index || count) {
    if (!index || !count) return "--task-index and --task-count go together";
    t.index = *index;
    t.count = *count;
  } else if (std::optional<int64_t> id = env_whole("SLURM_ARRAY_TASK_ID")) {
    std::optional<int64_t> n = env_whole("SLURM_ARRAY_TASK_COUNT");
    if (!n) return "SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is not: give --task-index and --task-count";
    const int64_t min = env_whole("SLURM_ARRAY_TASK_MIN").value_or(0);
    if (*id < min) return fmt::format("SLURM_ARRAY_TASK_ID {} is below SLURM_ARRAY_TASK_MIN {}", *id, min);
    t.index = *id - min;
    t.count = *n;
  }
  if (t.count < 1) return fmt::format("the task count must be at least 1, got {}", t.count);
  if (t.index < 0 || t.index >= t.count)
    return fmt::format("task index {} is outside 0..{} (a job array should run indices 0 to count-1, "
                       "e.g. sbatch --array=0-{})", t.index, t.count - 1, t.count - 1);
  out = t;
  return {};
}

std::vector<int64_t> task_frames(const FrameRange& range, const TaskSlice& task) {
  std::vector<int64_t> out;
  for (int64_t f = range.first + task.index; f <= range.last; f += task.count) out.push_back(f);
  return out;
}

}  // namespace rts::cli
