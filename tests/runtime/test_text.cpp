// The text block (render/builder/text_builder.cpp): one bezier prism per glyph in a group, laid
// out as POV-Ray lays text out, and traced where the font's outline says. The font is Debian's
// fonts-dejavu-core (scripts/ensure-deps installs it).
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "eval_helpers.hpp"
#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"

using namespace rts;
using rts::test::eval_text;

namespace {
const std::string kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

TEST_CASE("text: a prism per glyph, advanced by its width and the offset", "[text]") {
  render::SceneDesc s = eval_text("text { font = \"" + kFont + "\"  string = \"I I\"  thickness = 0.5  offset = <0.1, 0, 0> }");
  REQUIRE(s.groups.size() == 1);
  const render::GroupDesc& g = s.groups[0];
  REQUIRE(g.children.size() == 2);  // the space has no outline: no prism, but its advance
  double x[2], lo[2], hi[2];
  for (int i = 0; i < 2; ++i) {
    const render::Node& n = s.nodes[g.children[i].node];
    REQUIRE(n.kind == render::NodeKind::Shape);
    const auto* p = shape_if<render::Prism>(s.shapes[n.index].geometry);
    REQUIRE(p);
    CHECK((*p)->spline == render::SplineKind::Bezier);
    CHECK((*p)->height1 == -0.5);
    CHECK((*p)->height2 == 0.0);
    lo[i] = (*p)->x_min;
    hi[i] = (*p)->x_max;
    x[i] = g.children[i].transform[3][0];
  }
  // The line starts at the first glyph's left edge, and the two I's are the same glyph.
  CHECK(x[0] + lo[0] == Approx(0.0).margin(1e-6));  // (x_min: the bounds, padded by a tolerance)
  CHECK(lo[1] == lo[0]);
  CHECK(hi[1] == hi[0]);
  // "I", " ": two advances and two offsets apart; DejaVu Sans's I and space are 0.29 and 0.32 em wide.
  CHECK(x[1] - x[0] > 0.29 + 0.32 + 0.2 - 0.02);
  CHECK(x[1] - x[0] < 0.29 + 0.32 + 0.2 + 0.02);

  // A ray from the front meets the stem's face at z = 0 and leaves it at z = 0.5; beside the
  // stem it passes.
  render::FlatScene flat = render::flatten_scene(s);
  render::World world(s, flat);
  const double mid = x[0] + 0.5 * (lo[0] + hi[0]);
  render::WorldHit h;
  REQUIRE(world.intersect(render::Ray{render::Vec3(mid, 0.3, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(5.0));
  CHECK(h.normal.z == Approx(-1.0));
  REQUIRE(world.intersect(render::Ray{render::Vec3(mid, 0.3, 5), render::Vec3(0, 0, -1)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(4.5));
  CHECK_FALSE(world.intersect(render::Ray{render::Vec3(x[0] + hi[0] + 0.05, 0.3, -5), render::Vec3(0, 0, 1)},
                              render::Interval::positive(), h));
  // Above the cap height (0.73 em) nothing.
  CHECK_FALSE(world.intersect(render::Ray{render::Vec3(mid, 0.8, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
}

TEST_CASE("text: holes by the even-odd rule, kerning between pairs", "[text]") {
  // An O: the ray through its middle passes through the counter.
  render::SceneDesc o = eval_text("text { font = \"" + kFont + "\"  string = \"O\"  thickness = 0.2 }");
  render::FlatScene flat = render::flatten_scene(o);
  render::World world(o, flat);
  const auto* p = shape_if<render::Prism>(o.shapes[0].geometry);
  REQUIRE(p);
  const double cx = o.groups[0].children[0].transform[3][0] + 0.5 * ((*p)->x_min + (*p)->x_max);
  const double cy = 0.5 * ((*p)->z_min + (*p)->z_max);  // the outline's second coordinate is the text's y
  render::WorldHit h;
  CHECK_FALSE(world.intersect(render::Ray{render::Vec3(cx, cy, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  CHECK(world.intersect(render::Ray{render::Vec3((*p)->x_min + o.groups[0].children[0].transform[3][0] + 0.02, cy, -5),
                                    render::Vec3(0, 0, 1)},
                        render::Interval::positive(), h));
  // "AV" is kerned tighter than "A" then "V" laid out by advance alone.
  render::SceneDesc av = eval_text("text { font = \"" + kFont + "\"  string = \"AV\" }");
  render::SceneDesc aa = eval_text("text { font = \"" + kFont + "\"  string = \"AA\" }");
  const double av_step = av.groups[0].children[1].transform[3][0] - av.groups[0].children[0].transform[3][0];
  const double aa_step = aa.groups[0].children[1].transform[3][0] - aa.groups[0].children[0].transform[3][0];
  CHECK(av_step < aa_step - 0.01);
}

TEST_CASE("text: a bare font name is found in the font folders, with .ttf added", "[text]") {
  // "DejaVuSans": not beside the scene, no extension (POV-Ray's rule adds .ttf).
  render::SceneDesc s = eval_text("text { font = \"DejaVuSans\"  string = \"I\" }");
  REQUIRE(s.groups.size() == 1);
  CHECK(s.groups[0].children.size() == 1);
  CHECK(rts::test::eval_diagnostic("text { font = \"NoSuchFontAnywhere\"  string = \"I\" }").message.find(
            "cannot find font file 'NoSuchFontAnywhere'") != std::string::npos);
}
