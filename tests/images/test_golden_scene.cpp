// The `// args:` convention of golden scenes.
#include <catch2/catch.hpp>

#include "tests/images/golden_scene.hpp"

using namespace rts::images;
using Strings = std::vector<std::string>;

TEST_CASE("args lines are collected, other comments ignored", "[golden]") {
  const std::string text =
      "// A sphere\n"
      "// args: --aov normal,depth\n"
      "sphere { radius = 1 }  // args: not at line start\n"
      "  // args:   --seed 7\t--bits 16\n";
  CHECK(scene_args(text) == Strings{"--aov", "normal,depth", "--seed", "7", "--bits", "16"});
  CHECK(scene_args("sphere { radius = 1 }\n").empty());
}

TEST_CASE("requested AOVs come from --aov in both spellings", "[golden]") {
  CHECK(requested_aovs({"--aov", "normal,depth"}) == Strings{"normal", "depth"});
  CHECK(requested_aovs({"--aov=albedo", "--seed", "3", "--aov", "depth"}) ==
        Strings{"albedo", "depth"});
  CHECK(requested_aovs({"--seed", "3"}).empty());
  CHECK(requested_aovs({"--aov"}).empty());
}

TEST_CASE("AOV files sit beside the main output", "[golden]") {
  CHECK(aov_path("/tmp/x/ball.png", "normal") == "/tmp/x/ball.normal.png");
  CHECK(aov_path("ball", "depth") == "ball.depth.png");
}
