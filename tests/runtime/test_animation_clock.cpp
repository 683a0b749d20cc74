// The animation constants `clock`, `frame` and `frames` (EvalOptions::animation): their values,
// that a scene's own names shadow them, that a still sees frame 0 of 1, and settings.frames.
#include <catch2/catch.hpp>

#include "eval_helpers.hpp"

using namespace rts;
using namespace rts::render;
using rts::test::eval_error;
using rts::test::eval_text;

namespace {

// The radii of the spheres a program places, in order: how these tests read values back.
std::vector<double> radii(const std::string& body, const AnimationClock& clock) {
  EvalOptions opts;
  opts.animation = clock;
  SceneDesc s = eval_text(body, opts);
  std::vector<double> out;
  for (const Child& c : s.roots) {
    const Node& n = s.nodes[c.node];
    if (n.kind == NodeKind::Shape)
      if (auto* sp = shape_if<Sphere>(s.shapes[n.index].geometry)) out.push_back(sp->radius);
  }
  return out;
}

const std::string kReadAll =
    "sphere { radius = clock + 1 }\nsphere { radius = frame + 1 }\nsphere { radius = frames }\n";

}  // namespace

TEST_CASE("clock, frame and frames carry the frame being evaluated", "[eval][animation]") {
  CHECK(radii(kReadAll, AnimationClock{0.25, 3, 13}) == std::vector<double>{1.25, 4, 13});
  CHECK(radii(kReadAll, AnimationClock{1.0, 12, 13}) == std::vector<double>{2.0, 13, 13});
}

TEST_CASE("a still is frame 0 of 1 at clock 0", "[eval][animation]") {
  CHECK(radii(kReadAll, AnimationClock{}) == std::vector<double>{1, 1, 1});
}

TEST_CASE("a scene's own names shadow the animation constants", "[eval][animation]") {
  // Scenes written before the constants existed keep their meaning.
  CHECK(radii("let frame = 7\nsphere { radius = frame }\n", AnimationClock{0.5, 2, 5}) == std::vector<double>{7});
  CHECK(radii("macro m(clock) { sphere { radius = clock } }\nm(3)\n", AnimationClock{0.5, 2, 5}) ==
        std::vector<double>{3});
}

TEST_CASE("the constants drive loops and conditions like any number", "[eval][animation]") {
  const std::string body = "for i in 0 .. frame { sphere { radius = 1 } }\nif clock > 0.5 { sphere { radius = 9 } }\n";
  CHECK(radii(body, AnimationClock{0.25, 2, 5}).size() == 2);
  CHECK(radii(body, AnimationClock{0.75, 3, 5}) == std::vector<double>{1, 1, 1, 9});
}

TEST_CASE("settings.frames gives the animation's length and is checked", "[eval][animation]") {
  CHECK(eval_text("settings { frames = 24 }").settings.frames == 24);
  CHECK(eval_text("sphere { radius = 1 }").settings.frames == 1);
  CHECK_THAT(eval_error("settings { frames = 0 }"), Catch::Contains("a whole number from 1 to"));
  CHECK_THAT(eval_error("settings { frames = 2.5 }"), Catch::Contains("frames"));
}

TEST_CASE("a misspelt constant is suggested", "[eval][animation]") {
  CHECK_THAT(eval_error("sphere { radius = clok }"), Catch::Contains("did you mean 'clock'"));
}
