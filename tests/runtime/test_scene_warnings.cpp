// scene_warnings (runtime/scene_warnings.hpp): the one set of warnings `rts check`, `rts
// render` and the language server show about an evaluated scene.
#include <catch2/catch.hpp>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/evaluator.hpp"
#include "runtime/scene_warnings.hpp"

namespace {

struct Checked {
  std::unique_ptr<rts::SourceManager> sources;  // the files the warnings' locations point into
  std::vector<rts::Diagnostic> warnings;
  std::string text;  // as the sink prints them
};

Checked check(const std::string& scene) {
  Checked c;
  c.sources = std::make_unique<rts::SourceManager>();
  rts::SourceManager& sources = *c.sources;
  const rts::SourceFile* file = sources.add("test.rts", scene);
  std::ostringstream ignored;
  rts::DiagnosticSink eval_sink(ignored);
  rts::EvalResult r = rts::evaluate_source(sources, *file, rts::EvalOptions{}, eval_sink);
  c.warnings = rts::scene_warnings(r, sources, file);
  for (const rts::Diagnostic& d : c.warnings) c.text += rts::format_diagnostic(d);
  return c;
}

const std::string kLit = "point_light { position = <0, 9, 0> }\n";

}  // namespace

TEST_CASE("a camera inside a closed shape is a warning at the camera, with the shape's place", "[warnings]") {
  Checked c = check("camera { position = <0, 1, 0>  look_at = <0, 0, 5> }\n" + kLit + "sphere { radius = 3 }\n");
  REQUIRE(c.warnings.size() == 1);
  CHECK(c.warnings[0].severity == rts::Severity::Warning);
  CHECK(c.warnings[0].loc.line() == 1);
  CHECK(c.text.find("the camera is inside a sphere") != std::string::npos);
  REQUIRE(c.warnings[0].notes.size() == 1);
  CHECK(c.warnings[0].notes[0].loc.line() == 3);
}

TEST_CASE("the inside test follows the placement's transform and each shape's extent", "[warnings]") {
  std::string cam = "camera { position = <5, 0.5, 0>  look_at = <0, 0, 0> }\n" + kLit;
  CHECK(check(cam + "box { min = <-1, -1, -1>  max = <1, 1, 1> }\n").warnings.empty());
  CHECK(check(cam + "box { min = <-1, -1, -1>  max = <1, 1, 1> } translate <5, 0, 0>\n").warnings.size() == 1);
  CHECK(check(cam + "box { min = <-1, -1, -1>  max = <1, 1, 1> } scale 6\n").warnings.size() == 1);
  CHECK(check(cam + "cylinder { from = <0, 0, 0>  to = <9, 0, 0>  radius = 1 }\n").warnings.size() == 1);
  // An open tube has no inside; a cone narrows to nothing before the camera.
  CHECK(check(cam + "cylinder { from = <0, 0, 0>  to = <9, 0, 0>  radius = 1  capped = false }\n").warnings.empty());
  CHECK(check(cam + "cone { from = <0, 0, 0>  to = <5.2, 0, 0>  radius_from = 1  radius_to = 0 }\n").warnings.empty());
  CHECK(check(cam + "torus { major = 5  minor = 0.6 }\n").warnings.size() == 1);
  CHECK(check(cam + "torus { major = 3  minor = 0.6 }\n").warnings.empty());
  // Inside groups, through every level's transform; a CSG block is not looked into.
  CHECK(check(cam + "group { group { sphere { radius = 0.5 } scale 4 } translate <5, 0, 0> }\n").warnings.size() == 1);
  CHECK(check(cam + "group { sphere { radius = 0.5 } } translate <-5, 0, 0>\n").warnings.empty());
  CHECK(check(cam + "difference { sphere { radius = 9 } sphere { radius = 8 } }\n").warnings.empty());
  // Open surfaces never contain the camera.
  CHECK(check(cam + "plane { normal = <0, 1, 0>  offset = 2 }\n").warnings.empty());
  // A clear container (a box of haze around the scene) or glass is seen through: no warning.
  const std::string big = "box { min = <-9, -9, -9>  max = <9, 9, 9>  material = material { ";
  CHECK(check(cam + big + "transmit = 1  ior = 1  diffuse = 0  media_scattering = rgb(0.1) } }\n").warnings.empty());
  CHECK(check(cam + big + "transmit = 0.9  ior = 1.33 } }\n").warnings.empty());
  CHECK(check(cam + big + "color = rgb(0.5) } }\n").warnings.size() == 1);
}

TEST_CASE("what the builder skipped and an empty or unlit scene are warnings too", "[warnings]") {
  Checked t = check("camera { position = <0, 0, -5> }\n" + kLit +
                    "sphere { radius = 1 }\ntriangle { v0 = <0, 0, 0>  v1 = <1, 1, 1>  v2 = <2, 2, 2> }\n");
  REQUIRE(t.warnings.size() == 1);
  CHECK(t.text.find("test.rts:4:1: warning: triangle has zero area") != std::string::npos);
  CHECK(check("camera { position = <0, 0, -5> }\n" + kLit).text.find("places no objects") != std::string::npos);
  CHECK(check("sphere { radius = 1 }\n").text.find("places no lights") != std::string::npos);
}

TEST_CASE("a camera past the range rts renders exactly is a warning at the camera", "[warnings]") {
  // Scaled by 1e150 (the camera 3e150 from the origin) the scene renders exactly: no warning.
  auto scaled = [](const std::string& k) {
    return "let k = " + k + "\ncamera { position = <0, 1, -3>*k  look_at = <0, 0, 0> }\n" +
           "point_light { position = <0, 9, 0>*k }\nsphere { radius = k }\n";
  };
  CHECK(check(scaled("1e150")).warnings.empty());
  CHECK(check(scaled("1e-150")).warnings.empty());
  Checked big = check(scaled("1e160"));
  REQUIRE(big.warnings.size() == 1);
  CHECK(big.warnings[0].loc.line() == 2);
  CHECK(big.text.find("the camera is 3e+160 units from the origin") != std::string::npos);
  Checked small = check(scaled("1e-160"));
  REQUIRE(small.warnings.size() == 1);
  CHECK(small.warnings[0].loc.line() == 2);
  CHECK(small.text.find("the camera looks across 3e-160 units") != std::string::npos);
}
