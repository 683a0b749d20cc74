// A progress bar with ETA on stderr, drawn only when stderr is a terminal. Thread-safe:
// workers call tick() after each tile; redraws are throttled.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

namespace rts::render {

class Progress {
 public:
  Progress(std::size_t total, bool requested);
  ~Progress();
  void tick();
  void finish();  // clears the bar

 private:
  void draw(std::size_t done);

  using Clock = std::chrono::steady_clock;
  std::size_t total_;
  bool enabled_;
  std::atomic<std::size_t> done_{0};
  std::mutex draw_mutex_;
  Clock::time_point start_, last_draw_;
  bool drawn_ = false;
};

}  // namespace rts::render
