// Feedback on long work, on stderr: a progress bar with ETA for the render's tiles, and for
// phases without a known end (evaluation, loading, the BVH build) their elapsed time and a
// counter. Two displays: a bar redrawn in place (a terminal) or plain lines (a log file,
// `--progress=lines`). Thread-safe: workers call tick() after each tile; redraws are throttled.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace rts::render {

enum class ProgressMode : uint8_t { None, Bar, Lines };

class Progress {
 public:
  // `label` names the work in lines mode ("rendering").
  Progress(std::size_t total, ProgressMode mode, std::string label = "rendering");
  ~Progress();
  void tick();
  void finish();  // clears the bar; lines mode prints the last line

 private:
  void draw(std::size_t done);

  using Clock = std::chrono::steady_clock;
  std::size_t total_;
  ProgressMode mode_;
  std::string label_;
  std::atomic<std::size_t> done_{0};
  std::mutex draw_mutex_;
  Clock::time_point start_, last_draw_;
  int last_decile_ = 0;  // lines mode: the last tenth reported
  bool drawn_ = false;
};

// A phase whose end is not known in advance. A background thread (only when a display is
// asked for) reports it once it has run kPhaseQuiet: the bar shows its elapsed time and
// `*counter` (if any) in `unit`s; lines mode prints a line every kPhaseLineInterval and one
// when it ends. Short phases stay silent in bar mode, so quick renders look as before.
class PhaseProgress {
 public:
  PhaseProgress(ProgressMode mode, std::string label, const std::atomic<uint64_t>* counter = nullptr,
                std::string unit = {});
  ~PhaseProgress();  // = done()
  void done();

  PhaseProgress(const PhaseProgress&) = delete;
  PhaseProgress& operator=(const PhaseProgress&) = delete;

 private:
  void run();
  std::string text(double elapsed) const;

  using Clock = std::chrono::steady_clock;
  ProgressMode mode_;
  std::string label_;
  const std::atomic<uint64_t>* counter_;
  std::string unit_;
  Clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool drawn_ = false;
  std::thread thread_;
};

}  // namespace rts::render
