// Micro-benchmark of rts's serial I/O phases, for bench/race.sh and docs/performance.md:
//   rts-bench-io obj FILE [RUNS]      loads an OBJ file RUNS times: MB/s of file per CPU second
//   rts-bench-io png W H [RUNS]       writes a synthetic W x H image (gradients + noise) RUNS times
//   rts-bench-io png FILE.png [RUNS]  re-writes a rendered image (read from FILE.png) RUNS times
// Prints the median wall time and the median CPU time (user + system of the whole process,
// all threads) per run: the machine this runs on is shared, and CPU time is the steadier figure.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/image/image.hpp"
#include "render/builder/obj_loader.hpp"

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F>
void measure(int runs, F&& f, double& wall, double& cpu) {
  std::vector<double> walls, cpus;
  for (int i = 0; i < runs; ++i) {
    double c0 = cpu_seconds();
    auto t0 = std::chrono::steady_clock::now();
    f();
    walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpus.push_back(cpu_seconds() - c0);
  }
  wall = median(walls);
  cpu = median(cpus);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rts::render;
  std::string what = argc > 1 ? argv[1] : "";
  if (what == "obj" && argc >= 3) {
    std::string path = argv[2];
    int runs = argc > 3 ? std::atoi(argv[3]) : 3;
    double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    std::size_t tris = 0;
    double wall, cpu;
    measure(runs, [&] { tris = load_obj(path, path, true, SourceRef{})->indices.size() / 3; }, wall, cpu);
    std::printf("obj %s: %.1f MB, %zu triangles: wall %.3f s (%.0f MB/s), CPU %.3f s (%.0f MB/s)\n", path.c_str(),
                mb, tris, wall, mb / wall, cpu, mb / cpu);
    return 0;
  }
  if (what == "png" && argc >= 3 && std::string(argv[2]).ends_with(".png")) {
    Image image = read_png(argv[2], SourceRef{}, Encoding::SRGB);
    int runs = argc > 3 ? std::atoi(argv[3]) : 5;
    if (runs <= 0) return 2;
    std::string path = (std::filesystem::temp_directory_path() / "rts-bench-io.png").string();
    double wall, cpu;
    measure(runs, [&] { write_png(path, image, 8, Encoding::SRGB); }, wall, cpu);
    std::printf("png %s %dx%d: %.0f kB: wall %.3f s, CPU %.3f s\n", argv[2], image.width, image.height,
                static_cast<double>(std::filesystem::file_size(path)) / 1e3, wall, cpu);
    std::filesystem::remove(path);
    return 0;
  }
  if (what == "png" && argc >= 4) {
    int w = std::atoi(argv[2]), h = std::atoi(argv[3]);
    int runs = argc > 4 ? std::atoi(argv[4]) : 5;
    if (w <= 0 || h <= 0 || runs <= 0) return 2;
    // Smooth gradients with fine detail and a little noise, like a rendered frame.
    Image image(w, h);
    uint32_t state = 12345;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) {
          state = state * 1664525u + 1013904223u;
          float noise = static_cast<float>(state >> 8) / 16777216.0f * 0.01f;
          image.rgb[(static_cast<std::size_t>(y) * w + x) * 3 + c] =
              0.5f + 0.4f * std::sin(0.01f * x * (c + 1) + 0.02f * y) * std::cos(0.003f * x * y / (h + 1.0f)) + noise;
        }
    std::string path = (std::filesystem::temp_directory_path() / "rts-bench-io.png").string();
    double wall, cpu;
    measure(runs, [&] { write_png(path, image, 8, Encoding::SRGB); }, wall, cpu);
    std::printf("png %dx%d: %.0f kB: wall %.3f s, CPU %.3f s\n", w, h,
                static_cast<double>(std::filesystem::file_size(path)) / 1e3, wall, cpu);
    std::filesystem::remove(path);
    return 0;
  }
  std::fprintf(stderr, "usage: rts-bench-io obj FILE [RUNS] | png W H [RUNS] | png FILE.png [RUNS]\n");
  return 2;
}
