#include "render/progress.hpp"

#include <cstdio>
#include <string>

namespace rts::render {

// Redraw at most this often: drawing is a syscall and tiles finish quickly.
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
// Lines mode: at most one line per this interval for the render's tenths (the last always).
constexpr auto kLineInterval = std::chrono::seconds(1);
// A phase says nothing until it has run this long (most scenes evaluate and build in less).
constexpr auto kPhaseQuiet = std::chrono::milliseconds(500);
// Lines mode: a running phase prints its state this often.
constexpr auto kPhaseLineInterval = std::chrono::seconds(2);
constexpr int kBarWidth = 40;

Progress::Progress(std::size_t total, ProgressMode mode, std::string label)
    : total_(total), mode_(total > 0 ? mode : ProgressMode::None), label_(std::move(label)),
      start_(Clock::now()), last_draw_(start_) {}

Progress::~Progress() { finish(); }

void Progress::tick() {
  std::size_t done = ++done_;
  if (mode_ == ProgressMode::None) return;
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  auto now = Clock::now();
  if (mode_ == ProgressMode::Lines) {
    const int decile = static_cast<int>(done * 10 / total_);
    if (decile <= last_decile_ || decile == 10 || now - last_draw_ < kLineInterval) return;  // 100%: finish()
    last_decile_ = decile;
  } else if (now - last_draw_ < kRedrawInterval && done != total_) {
    return;
  }
  last_draw_ = now;
  draw(done);
}

void Progress::draw(std::size_t done) {
  double fraction = static_cast<double>(done) / total_;
  double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  if (mode_ == ProgressMode::Lines) {
    std::fprintf(stderr, "rts: %s: %3d%%  %.1fs elapsed, ETA %.1fs\n", label_.c_str(),
                 static_cast<int>(fraction * 100), elapsed, eta);
  } else {
    int filled = static_cast<int>(fraction * kBarWidth);
    std::string bar(filled, '#');
    bar.append(kBarWidth - filled, '.');
    std::fprintf(stderr, "\r[%s] %3d%%  %.1fs elapsed, ETA %.1fs ", bar.c_str(),
                 static_cast<int>(fraction * 100), elapsed, eta);
  }
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (mode_ == ProgressMode::None) return;
  std::lock_guard lock(draw_mutex_);
  if (mode_ == ProgressMode::Lines) {
    std::fprintf(stderr, "rts: %s: done (%zu of %zu) in %.1fs\n", label_.c_str(), done_.load(), total_,
                 std::chrono::duration<double>(Clock::now() - start_).count());
  } else if (drawn_) {
    std::fprintf(stderr, "\r%*s\r", kBarWidth + 40, "");
  }
  std::fflush(stderr);
  mode_ = ProgressMode::None;
}

namespace {
std::string count_in_words(uint64_t n) {
  char buf[32];
  if (n >= 1'000'000) std::snprintf(buf, sizeof buf, "%.2fM", n / 1e6);
  else if (n >= 10'000) std::snprintf(buf, sizeof buf, "%.1fk", n / 1e3);
  else std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(n));
  return buf;
}
}  // namespace

PhaseProgress::PhaseProgress(ProgressMode mode, std::string label, const std::atomic<uint64_t>* counter,
                             std::string unit)
    : mode_(mode), label_(std::move(label)), counter_(counter), unit_(std::move(unit)), start_(Clock::now()) {
  if (mode_ != ProgressMode::None) thread_ = std::thread([this] { run(); });
}

PhaseProgress::~PhaseProgress() { done(); }

std::string PhaseProgress::text(double elapsed) const {
  std::string s = label_ + ": ";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1fs", elapsed);
  s += buf;
  if (counter_) s += ", " + count_in_words(counter_->load(std::memory_order_relaxed)) + " " + unit_;
  return s;
}

void PhaseProgress::run() {
  std::unique_lock lock(mutex_);
  if (wake_.wait_for(lock, kPhaseQuiet, [&] { return stop_; })) return;
  const auto interval = mode_ == ProgressMode::Lines ? std::chrono::duration_cast<std::chrono::milliseconds>(kPhaseLineInterval)
                                                     : std::chrono::duration_cast<std::chrono::milliseconds>(kRedrawInterval);
  do {
    double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (mode_ == ProgressMode::Lines)
      std::fprintf(stderr, "rts: %s\n", text(elapsed).c_str());
    else
      std::fprintf(stderr, "\r%s ", text(elapsed).c_str());
    std::fflush(stderr);
    drawn_ = true;
  } while (!wake_.wait_for(lock, interval, [&] { return stop_; }));
}

void PhaseProgress::done() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
  double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (mode_ == ProgressMode::Lines) {
    std::fprintf(stderr, "rts: %s (done)\n", text(elapsed).c_str());
  } else if (drawn_) {
    std::fprintf(stderr, "\r%*s\r", kBarWidth + 40, "");
  }
  std::fflush(stderr);
}

}  // namespace rts::render
