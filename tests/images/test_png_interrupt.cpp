// Interrupting a PNG write (Ctrl-C, kill) removes the temporary file and leaves the old image
// as it was (issue 7, defect 10). A child program (png_write_child) writes a large,
// incompressible image; the parent signals it as soon as its temporary file appears. Every wait
// has a deadline, so a child that never ends fails the test instead of hanging the suite.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "render/image/image.hpp"
#include "tests/images/temp_dir.hpp"

extern char** environ;

using namespace rts::render;
using rts::images::TempDir;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

std::vector<char> bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool has_temp_file(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

// Waits for the child until the deadline; then kills it outright (SIGKILL) and reports that.
bool wait_with_deadline(pid_t child, int& status, Clock::time_point deadline) {
  while (Clock::now() < deadline) {
    const pid_t r = waitpid(child, &status, WNOHANG);
    if (r == child) return true;
    if (r < 0 && errno != EINTR) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(child, SIGKILL);
  waitpid(child, &status, 0);
  return false;
}

void interrupt_write_with(int sig) {
  TempDir dir;
  std::string out = dir.file("out.png");
  Image small(4, 4);
  write_png(out, small, 8, Encoding::SRGB);
  const std::vector<char> before = bytes_of(out);

  std::string program = RTS_PNG_WRITE_CHILD;
  std::vector<char*> args{program.data(), out.data(), nullptr};
  pid_t child = 0;
  REQUIRE(posix_spawn(&child, program.c_str(), nullptr, nullptr, args.data(), environ) == 0);

  bool seen = false;
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (!seen && Clock::now() < deadline) {
    seen = has_temp_file(dir.path());
    if (!seen) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  kill(child, sig);
  int status = 0;
  const bool ended = wait_with_deadline(child, status, Clock::now() + std::chrono::seconds(30));
  REQUIRE(seen);
  REQUIRE(ended);  // the signal ended the child within 30 s
  // It died of the signal, as an unhandled one would have it (exit status 128 + sig).
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == sig);
  CHECK_FALSE(has_temp_file(dir.path()));
  CHECK(bytes_of(out) == before);
}

}  // namespace

TEST_CASE("SIGTERM during a PNG write removes the temporary file and keeps the old image", "[png][signal]") {
  interrupt_write_with(SIGTERM);
}

TEST_CASE("SIGINT during a PNG write removes the temporary file and keeps the old image", "[png][signal]") {
  interrupt_write_with(SIGINT);
}
