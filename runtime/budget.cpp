#include "runtime/budget.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "parser/diagnostics.hpp"
#include "render/scene/resource_limits.hpp"
#include "runtime/value.hpp"

namespace rts::runtime {

namespace {
// The resident size is read (a small /proc read) once per this many evaluation steps, so
// that memory growth no single check sees (many small values) is still bounded.
constexpr uint64_t kStepsPerMemoryCheck = 1 << 16;

[[noreturn]] void fail(SourceLoc loc, std::string message) { throw LanguageError(loc, std::move(message)); }
}  // namespace

Budget::Budget(const EvalLimits& limits)
    : limits_(limits),
      next_memory_check_(limits.max_memory || limits.max_seconds > 0 ? kStepsPerMemoryCheck : UINT64_MAX),
      timed_(limits.max_seconds > 0) {
  if (timed_)
    deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                       std::chrono::duration<double>(limits.max_seconds));
}

void Budget::time_exhausted(SourceLoc loc, const char* what) const {
  fail(loc, fmt::format("evaluation ran longer than its time budget of {} s; it was here, in {}", limits_.max_seconds,
                        what));
}

void Budget::count_iteration(SourceLoc loc) {
  if (++iterations_ > limits_.max_iterations)
    fail(loc, fmt::format("loops ran more than {} iterations in total (raise the limit with --max-iterations)",
                          limits_.max_iterations));
  spend(1, loc, "loop iterations");
}

void Budget::check(SourceLoc loc, const char* what) {
  if (steps_ > limits_.max_steps)
    fail(loc, fmt::format("evaluation ran more than {} steps (loop iterations, macro calls and list elements and "
                          "string bytes built); it ran away here, in {} (raise the limit with --max-steps)",
                          limits_.max_steps, what));
  next_memory_check_ = steps_ + kStepsPerMemoryCheck;
  check_time(loc, what);
  check_memory(0, loc, what);
}

std::string Budget::text_of(const Value& v, SourceLoc loc, bool quote_strings) {
  const uint64_t left = steps_ < limits_.max_steps ? limits_.max_steps - steps_ : 0;
  // And a third of what --max-memory leaves: while a string grows it briefly holds its old
  // buffer and one twice as large.
  const std::size_t max = limits_.max_memory;
  std::size_t room = SIZE_MAX;
  if (max > 0) {
    const std::size_t held = render::resident_bytes();
    room = held < max ? (max - held) / 3 : 0;
  }
  const std::size_t limit = static_cast<std::size_t>(std::min<uint64_t>(left, room));
  std::string text;
  if (!append_text(text, v, quote_strings, limit)) {
    if (room < left)
      fail(loc, fmt::format("this text would need more than {} more memory, past the memory limit of {} (raise it "
                            "with --max-memory)",
                            render::size_in_words(room), render::size_in_words(max)));
    // Past the step budget: spend it all and one more, which fails with the budget's message.
    spend(left + 1, loc, "string bytes built");
  }
  spend(text.size(), loc, "string bytes built");
  return text;
}

void Budget::check_memory(std::size_t bytes, SourceLoc loc, const char* what) const {
  const std::size_t max = limits_.max_memory;
  if (render::memory_fits(max, bytes)) return;
  if (bytes > 0)
    fail(loc, fmt::format("{} would need {} more memory, past the memory limit of {} (raise it with --max-memory)",
                          what, render::size_in_words(bytes), render::size_in_words(max)));
  fail(loc, fmt::format("the scene uses more than the memory limit of {} (it was building {} here; raise the limit "
                        "with --max-memory)",
                        render::size_in_words(max), what));
}

void Budget::stack_exhausted(SourceLoc loc, unsigned macro_depth) const {
  fail(loc, fmt::format("evaluation nested too deeply for its {} stack at macro depth {} (the stack could not be made "
                        "larger: lower --max-recursion or the nesting of the scene)",
                        render::size_in_words(stack_bytes_), macro_depth));
}

}  // namespace rts::runtime
