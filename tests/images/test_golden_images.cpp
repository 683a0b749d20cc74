// Golden images: renders every tests/golden/images/<name>.rts with the real `rts` binary and
// compares the result (and any AOVs asked for by `// args: --aov ...`) with <name>.png beside
// the scene. Run one scene with: images_golden_tests -c <name>
// Regenerate on purpose with scripts/update-golden-images [name...] (never automatically).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "render/image/image.hpp"
#include "tests/images/golden_scene.hpp"
#include "tests/images/image_diff.hpp"
#include "tests/images/run_process.hpp"
#include "tests/images/temp_dir.hpp"

using namespace rts::images;
namespace fs = std::filesystem;
using rts::render::Encoding;

namespace {

const fs::path kSceneDir = fs::path(RTS_SOURCE_DIR) / "tests" / "golden" / "images";
const fs::path kOutputDir = RTS_GOLDEN_OUTPUT;
constexpr const char* kThreads = "2";
constexpr double kDiffGain = 16.0;   // makes a 2/255 difference clearly visible

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> golden_scene_names() {
  std::vector<std::string> names;
  if (!fs::is_directory(kSceneDir)) return names;
  for (const auto& entry : fs::directory_iterator(kSceneDir)) {
    if (entry.path().extension() == ".rts") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Compares one produced image with its golden file; on mismatch leaves <label>.actual.png and
// <label>.diff.png in the output folder and explains.
void compare_output(const std::string& name, const std::string& label, const fs::path& actual) {
  const fs::path golden = kSceneDir / (label + ".png");
  INFO("golden image: " << golden.string());
  if (!fs::exists(golden)) {
    FAIL_CHECK("no golden image " << golden.string() << ": render it on purpose with\n"
               "    scripts/update-golden-images " << name << "\nand look at it before keeping it");
    return;
  }
  if (!fs::exists(actual)) {
    FAIL_CHECK("rts did not write " << actual.string());
    return;
  }
  // Linear decoding compares the stored codes, which is what the tolerances are in.
  const auto expected_image = rts::render::read_png(golden.string(), {}, Encoding::Linear);
  const auto actual_image = rts::render::read_png(actual.string(), {}, Encoding::Linear);
  const DiffThresholds thresholds;
  const DiffStats stats = diff_images(expected_image, actual_image, thresholds.channel_tolerance);
  if (images_match(stats, thresholds)) {
    SUCCEED(label << " matches");
    return;
  }
  fs::create_directories(kOutputDir);
  const fs::path kept = kOutputDir / (label + ".actual.png");
  const fs::path diff = kOutputDir / (label + ".diff.png");
  fs::copy_file(actual, kept, fs::copy_options::overwrite_existing);
  std::string diff_note = "(sizes differ: no diff image)";
  const auto picture = amplified_difference(expected_image, actual_image, kDiffGain);
  if (!picture.rgb.empty()) {
    rts::render::write_png(diff.string(), picture, 8, Encoding::Linear);
    diff_note = diff.string();
  }
  FAIL_CHECK(label << " differs from its golden image\n"
             << describe(stats, thresholds) << "actual: " << kept.string() << "\n"
             << "diff (x" << kDiffGain << "): " << diff_note);
}

void check_scene(const std::string& name) {
  const fs::path scene = kSceneDir / (name + ".rts");
  const std::vector<std::string> extra = scene_args(read_text(scene));
  TempDir work;
  const std::string output = work.file(name + ".png");
  std::vector<std::string> argv = {RTS_BINARY, "render", scene.string(), "-o", output,
                                   "--threads", kThreads, "--no-progress"};
  argv.insert(argv.end(), extra.begin(), extra.end());

  const std::string log = work.file("rts.log");
  const int status = run_process(argv, log);
  if (status != 0) {
    FAIL_CHECK("rts render " << scene.string() << " exited with " << status << ":\n"
               << read_text(log));
    return;
  }
  compare_output(name, name, output);
  for (const std::string& aov : requested_aovs(extra)) {
    compare_output(name, name + "." + aov, aov_path(output, aov));
  }
}

std::string file_bytes(const std::string& path) { return read_text(path); }

}  // namespace

TEST_CASE("golden images render as recorded", "[golden-images]") {
  REQUIRE(fs::exists(RTS_BINARY));
  const auto names = golden_scene_names();
  REQUIRE_FALSE(names.empty());
  for (const std::string& name : names) {
    DYNAMIC_SECTION(name) { check_scene(name); }
  }
}

// Every random decision derives from (pixel, sample, seed): the PNG must not depend on how many
// threads rendered it. Checked on the scenes that use the most randomness.
TEST_CASE("renders are byte-identical whatever the thread count", "[golden-images]") {
  REQUIRE(fs::exists(RTS_BINARY));
  for (const std::string name : {"shadow_soft", "camera_depth_of_field", "material_roughness"}) {
    DYNAMIC_SECTION(name) {
      const fs::path scene = kSceneDir / (name + ".rts");
      TempDir work;
      std::string previous;
      for (const char* threads : {"1", "3", "8"}) {
        const std::string output = work.file(name + "-" + threads + ".png");
        const std::string log = work.file("rts.log");
        const int status = run_process({RTS_BINARY, "render", scene.string(), "-o", output,
                                        "--threads", threads, "--no-progress"}, log);
        REQUIRE(status == 0);
        const std::string bytes = file_bytes(output);
        REQUIRE_FALSE(bytes.empty());
        if (!previous.empty()) {
          INFO("--threads " << threads << " differs from the previous thread count");
          CHECK(bytes == previous);
        }
        previous = bytes;
      }
    }
  }
}
