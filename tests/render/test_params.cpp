// ParamSet: typed lookups, conversions, use tracking, "did you mean".
#include <catch2/catch.hpp>

#include "render/scene/params.hpp"

using namespace rts::render;

namespace {
SourceRef at(uint32_t line, uint32_t col) { return SourceRef{"scene.rts", line, col}; }
}  // namespace

TEST_CASE("closest_name suggests near misses only", "[params]") {
  std::vector<std::string_view> names = {"radius", "center", "material"};
  CHECK(closest_name("raduis", names) == "radius");
  CHECK(closest_name("centre", names) == "center");
  CHECK(closest_name("materail", names) == "material");
  CHECK(closest_name("zzz", names).empty());
  CHECK(closest_name("x", {"y"}).empty());  // one letter apart is everything for a 1-letter word
}

TEST_CASE("typed getters return values, defaults and conversions", "[params]") {
  ParamSet ps("sphere", at(1, 1));
  ps.add("radius", 2.5, at(2, 3));
  ps.add("center", Vec3(1, 2, 3), at(3, 3));
  ps.add("gray", 0.5, at(4, 3));
  ps.add("flag", true, at(5, 3));
  CHECK(ps.number("radius", 1) == 2.5);
  CHECK(ps.number("missing", 7) == 7);
  CHECK(ps.vec3("center", Vec3(0)) == Vec3(1, 2, 3));
  CHECK(ps.color("gray", Color(0)) == Color(0.5));
  CHECK(ps.color("center", Color(0)) == Color(1, 2, 3));
  CHECK(ps.boolean("flag", false));
}

TEST_CASE("a later add overrides an earlier one", "[params]") {
  ParamSet ps("sphere", at(1, 1));
  ps.add("radius", 1.0, at(2, 1));
  ps.add("radius", 3.0, at(3, 1));
  CHECK(ps.params().size() == 1);
  CHECK(ps.number("radius", 0) == 3.0);
  CHECK(ps.find("radius")->loc.line == 3);
}

TEST_CASE("wrong types throw at the property", "[params]") {
  ParamSet ps("sphere", at(1, 1));
  ps.add("radius", Vec3(1, 1, 1), at(4, 9));
  ps.add("on", 1.0, at(5, 2));
  try {
    ps.number("radius", 1);
    FAIL("expected a SceneError");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()) == "property 'radius' of sphere expects a number, got a vector");
    CHECK(e.where.line == 4);
    CHECK(e.where.col == 9);
  }
  CHECK_THROWS_AS(ps.boolean("on", false), SceneError);  // number → bool is not allowed
}

TEST_CASE("integer rejects fractions", "[params]") {
  ParamSet ps("settings", at(1, 1));
  ps.add("width", 10.5, at(2, 1));
  CHECK_THROWS_WITH(ps.integer("width", 1), Catch::Contains("whole number"));
}

TEST_CASE("required properties fail at the block", "[params]") {
  ParamSet ps("sphere", at(7, 2));
  try {
    ps.require_number("radius");
    FAIL("expected a SceneError");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()) == "sphere needs property 'radius'");
    CHECK(e.where.line == 7);
  }
}

TEST_CASE("check_unused reports unknown names with a suggestion", "[params]") {
  ParamSet ps("sphere", at(1, 1));
  ps.add("radius", 1.0, at(2, 1));
  ps.add("centre", Vec3(0), at(3, 5));
  ps.number("radius", 1);
  try {
    ps.check_unused({"radius", "center"});
    FAIL("expected a SceneError");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()) == "unknown property 'centre' for sphere; did you mean 'center'? (sphere takes radius, center)");
    CHECK(e.where.line == 3);
    CHECK(e.where.col == 5);
  }
  // Valid names that were simply not needed are not unknown.
  ParamSet ok("sphere", at(1, 1));
  ok.add("center", Vec3(0), at(2, 1));
  CHECK_NOTHROW(ok.check_unused({"radius", "center"}));
}
