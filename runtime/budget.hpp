// The evaluation budgets of --max-steps, --max-iterations and --max-memory, and the stack
// guard for deep recursion: what a runaway scene hits before it can hang or exhaust the
// machine. Internal to runtime/; the interpreter owns one and forwards its services to the
// builtins. Every failure is a located LanguageError naming the flag that raises the limit.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "parser/source.hpp"
#include "runtime/evaluator.hpp"

namespace rts::runtime {

struct Value;

class Budget {
 public:
  explicit Budget(const EvalLimits& limits);

  // Counts `n` evaluation steps of kind `what` ("macro calls", "list elements built"...)
  // against --max-steps, and now and then the process's memory against --max-memory.
  void spend(uint64_t n, SourceLoc loc, const char* what) {
    if (add_steps(n)) check(loc, what);
  }
  // The fast half of spend(), for callers that build `what` only when it is needed: true
  // when check() must run now.
  bool add_steps(uint64_t n) {
    steps_ += n;
    return steps_ > limits_.max_steps || steps_ >= next_memory_check_;
  }
  // Fails past --max-steps; otherwise checks the memory and schedules the next check.
  void check(SourceLoc loc, const char* what);
  // Fails once evaluation has run longer than limits.max_seconds (0: never). Cheap enough for
  // every statement: some cost time without spending steps (a `let` among 100,000 others in
  // one scope looks at them all for its name).
  void check_time(SourceLoc loc, const char* what) const {
    if (timed_ && std::chrono::steady_clock::now() > deadline_) time_exhausted(loc, what);
  }
  // One loop iteration: counted against --max-iterations and as a step.
  void count_iteration(SourceLoc loc);
  // Fails (located) unless `bytes` more fit under --max-memory; `what` names the value.
  void check_memory(std::size_t bytes, SourceLoc loc, const char* what) const;
  // The text of `v` (str, format, print, error, assert), its bytes counted as steps: a text
  // past the steps left fails at `loc` before it is finished, so it never outgrows the budget.
  std::string text_of(const Value& v, SourceLoc loc, bool quote_strings);

  // The lowest stack address evaluation may reach before failing cleanly (0: unchecked).
  void set_stack_floor(std::uintptr_t floor, std::size_t stack_bytes) {
    stack_floor_ = floor;
    stack_bytes_ = stack_bytes;
  }
  // Fails cleanly when the C++ stack runs low; `macro_depth` goes into the message.
  void check_stack(SourceLoc loc, unsigned macro_depth) const {
    if (stack_floor_ && reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0)) < stack_floor_)
      stack_exhausted(loc, macro_depth);
  }

 private:
  [[noreturn]] void stack_exhausted(SourceLoc loc, unsigned macro_depth) const;
  [[noreturn]] void time_exhausted(SourceLoc loc, const char* what) const;

  const EvalLimits& limits_;
  uint64_t steps_ = 0;
  uint64_t iterations_ = 0;
  uint64_t next_memory_check_;
  std::uintptr_t stack_floor_ = 0;
  std::size_t stack_bytes_ = 0;
  bool timed_ = false;  // limits.max_seconds > 0
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace rts::runtime
