// Helper for test_png_interrupt.cpp: writes a large, incompressible 16-bit PNG to argv[1], so a
// signal can arrive while the temporary file is open.
//
// It is its own program, started with posix_spawn, because forking the test process is unsafe:
// the fork copies oneTBB's and malloc's state (locks held by worker threads that do not exist in
// the child) and Catch2's signal handlers (which are not async-signal-safe). On a many-core CI
// machine that combination deadlocked the child and the test waited for ever.
#include <cstdio>
#include <exception>
#include <random>

#include "render/image/image.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: png_write_child OUT.png\n");
    return 2;
  }
  using namespace rts::render;
  Image big(2000, 2000);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float& v : big.rgb) v = u(rng);  // noise does not compress: the write takes a while
  try {
    write_png(argv[1], big, 16, Encoding::SRGB);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "png_write_child: %s\n", e.what());
    return 1;
  }
  return 0;  // the write finished before the signal: the parent reports it
}
