// Group 7, degenerate input, through the real `rts` binary: zero-area, collinear and
// duplicate triangles and zero-length normals in an OBJ render with a warning naming the
// source location of what was skipped; a zero scale, scales whose product underflows and a
// zero-size area light are refused with a located error. Each scene marks the line the
// message must name with "// expect-warning: TEXT" or "// expect-error: TEXT".
#include <array>
#include <cstdio>
#include <filesystem>
#include <sys/wait.h>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "stability_support.hpp"

using namespace rts::stability;

namespace {

struct Run {
  int exit_code = -1;
  std::string output;  // stderr (and stdout)
};

Run run_rts(const std::string& scene, const std::string& out_png) {
  std::string cmd = fmt::format("'{}' render '{}' -o '{}' --threads 2 --no-progress 2>&1", RTS_BINARY, scene, out_png);
  Run r;
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// The 1-based line holding the marker, and the text after it.
int marker_line(const std::string& path, const std::string& marker, std::string& text) {
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (auto at = line.find(marker); at != std::string::npos) {
      text = line.substr(at + marker.size());
      return n;
    }
  return 0;
}

void check_scene(const std::string& name) {
  std::string path = std::string(RTS_SOURCE_DIR) + "/tests/stability/scenes/" + name + ".rts";
  std::string out = std::string(RTS_STABILITY_OUT) + "/degenerate_" + name + ".png";
  std::filesystem::create_directories(RTS_STABILITY_OUT);
  std::string text;
  bool warning = true;
  int line = marker_line(path, "// expect-warning: ", text);
  if (line == 0) {
    warning = false;
    line = marker_line(path, "// expect-error: ", text);
  }
  REQUIRE(line > 0);
  Run r = run_rts(path, out);
  CAPTURE(name, r.output);
  std::string where = fmt::format("{}:{}:", path, line);
  bool located = r.output.find(where) != std::string::npos;
  bool says = r.output.find(text) != std::string::npos;
  bool kind = r.output.find(warning ? ": warning: " : ": error: ") != std::string::npos;
  record("degenerate", name, warning ? "renders (exit 0) with a located warning" : "refused with a located error",
         (warning ? r.exit_code == 0 : r.exit_code != 0) && located && says && kind ? 1 : 0, "1",
         warning && r.exit_code == 0 ? "degenerate_" + name + ".png" : "");
  if (warning)
    CHECK(r.exit_code == 0);
  else
    CHECK((r.exit_code == 1 || r.exit_code == 3));
  CHECK(located);
  CHECK(says);
  CHECK(kind);
}

}  // namespace

TEST_CASE("degenerate triangles render with a located warning", "[degenerate]") {
  check_scene("degenerate_mesh");
  check_scene("degenerate_triangle");
  check_scene("degenerate_normals");
}

TEST_CASE("singular transforms and zero-size area lights are refused, located", "[degenerate]") {
  check_scene("zero_scale");
  check_scene("underflow_scale");
  check_scene("zero_area_light");
  check_scene("mesh_beyond_float");
}

TEST_CASE("max_depth = 1e9 between two mirrors renders, capped with a located warning", "[recursion]") {
  check_scene("deep_mirrors");
}
