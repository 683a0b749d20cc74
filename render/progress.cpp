#include "render/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace rts::render {

// Redraw at most this often: drawing is a syscall and tiles finish quickly.
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kBarWidth = 40;

Progress::Progress(std::size_t total, bool requested)
    : total_(total), enabled_(requested && isatty(STDERR_FILENO) && total > 0),
      start_(Clock::now()), last_draw_(start_) {}

Progress::~Progress() { finish(); }

void Progress::tick() {
  std::size_t done = ++done_;
  if (!enabled_) return;
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  auto now = Clock::now();
  if (now - last_draw_ < kRedrawInterval && done != total_) return;
  last_draw_ = now;
  draw(done);
}

void Progress::draw(std::size_t done) {
  double fraction = static_cast<double>(done) / total_;
  double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  int filled = static_cast<int>(fraction * kBarWidth);
  std::string bar(filled, '#');
  bar.append(kBarWidth - filled, '.');
  std::fprintf(stderr, "\r[%s] %3d%%  %.1fs elapsed, ETA %.1fs ", bar.c_str(),
               static_cast<int>(fraction * 100), elapsed, eta);
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard lock(draw_mutex_);
  if (drawn_) {
    std::fprintf(stderr, "\r%*s\r", kBarWidth + 40, "");
    std::fflush(stderr);
  }
  enabled_ = false;
}

}  // namespace rts::render
