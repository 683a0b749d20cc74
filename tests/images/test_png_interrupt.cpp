// Interrupting a PNG write (Ctrl-C, kill) removes the temporary file and leaves the old image
// as it was (issue 7, defect 10). A child process writes a large, incompressible image; the
// parent signals it as soon as its temporary file appears.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "render/image/image.hpp"
#include "tests/images/temp_dir.hpp"

using namespace rts::render;
using rts::images::TempDir;
namespace fs = std::filesystem;

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

// Noise does not compress, so encoding it takes long enough to be interrupted.
Image noise(int w, int h) {
  Image img(w, h);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float& v : img.rgb) v = u(rng);
  return img;
}

void interrupt_write_with(int sig) {
  TempDir dir;
  const std::string out = dir.file("out.png");
  Image small(4, 4);
  write_png(out, small, 8, Encoding::SRGB);
  const std::vector<char> before = bytes_of(out);
  Image big = noise(2000, 2000);

  pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    try {
      write_png(out, big, 16, Encoding::SRGB);
    } catch (...) {
    }
    _exit(0);  // the write finished before the signal: the parent reports it
  }
  bool seen = false;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!seen && std::chrono::steady_clock::now() < deadline) {
    seen = has_temp_file(dir.path());
    if (!seen) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  kill(child, sig);
  int status = 0;
  waitpid(child, &status, 0);
  REQUIRE(seen);
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
