#include "render/image/temp_file_guard.hpp"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <cstring>

namespace rts::render {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kSignalCount = sizeof kSignals / sizeof kSignals[0];

// Read by the handler: only a fixed buffer and sig_atomic_t flags (async-signal-safe).
char g_path[PATH_MAX];
volatile sig_atomic_t g_armed = 0;
struct sigaction g_previous[kSignalCount];

void on_signal(int sig) {
  if (g_armed) ::unlink(g_path);
  // Then die (or run the previous handler) as the signal would have without us.
  for (int i = 0; i < kSignalCount; ++i)
    if (kSignals[i] == sig) ::sigaction(sig, &g_previous[i], nullptr);
  ::raise(sig);
}

}  // namespace

TempFileGuard::TempFileGuard(const std::string& path) {
  if (path.size() >= sizeof g_path) return;  // the open fails on such a name anyway
  std::memcpy(g_path, path.c_str(), path.size() + 1);
  g_armed = 1;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int i = 0; i < kSignalCount; ++i) {
    ::sigaction(kSignals[i], nullptr, &g_previous[i]);
    if (g_previous[i].sa_handler == SIG_IGN) continue;  // e.g. nohup: stay ignored
    ::sigaction(kSignals[i], &sa, nullptr);
  }
}

TempFileGuard::~TempFileGuard() {
  if (!g_armed) return;
  for (int i = 0; i < kSignalCount; ++i)
    if (g_previous[i].sa_handler != SIG_IGN) ::sigaction(kSignals[i], &g_previous[i], nullptr);
  g_armed = 0;
}

}  // namespace rts::render
