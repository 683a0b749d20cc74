// Objects that cast no shadow (casts_shadow = false, POV-Ray's no_shadow): shadow rays pass
// them, every other ray sees them. Checked against the same scene with those objects left
// out: the same occlusion answers, the same transmissive crossings and the same shadow-ray
// hits; and against the scene with every flag set: the same camera-ray hits.
#include <algorithm>
#include <random>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

enum class Build { Flagged, Removed, AllCast };

// `spheres` random spheres (every third one glass), a floor plane and a tilted plane, a CSG
// block, a small group and a group of 80 spheres placed twice (instanced). About a third of
// the objects cast no shadow. Build::Removed leaves those out; Build::AllCast keeps them with
// casts_shadow = true.
SceneDesc make_scene(uint64_t seed, int spheres, Build build) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-4.0, 4.0), r(0.1, 0.7), coin(0.0, 1.0);
  SceneDesc s;
  MaterialDesc glass;
  glass.transmit = Color(0.8, 0.9, 0.7);
  const MaterialId glass_id = add_material(s, glass);
  auto keep = [&](bool casts) { return casts || build != Build::Removed; };
  auto flag = [&](bool casts) { return casts || build == Build::AllCast; };
  for (int i = 0; i < spheres; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const double radius = r(rng);
    const bool casts = coin(rng) > 0.35;
    if (!keep(casts)) continue;
    const NodeId n = add_shape(s, Sphere{c, radius}, i % 3 == 0 ? glass_id : kNoId);
    s.shapes[s.nodes[n].index].casts_shadow = flag(casts);
    place(s, n, i % 4 == 0 ? rotate_deg(30.0 * i, glm::normalize(Vec3(1, 2, 3))) : Mat4(1.0));
  }
  const NodeId floor = add_shape(s, Plane{Vec3(0, 1, 0), -4.5});
  place(s, floor);
  if (keep(false)) {
    const NodeId tilted = add_shape(s, Plane{glm::normalize(Vec3(1, 0.2, 0)), 4.2});
    s.shapes[s.nodes[tilted].index].casts_shadow = flag(false);
    place(s, tilted);
  }
  if (keep(false)) {
    const NodeId a = add_shape(s, Sphere{Vec3(1, 1, 1), 1.2});
    const NodeId b = add_shape(s, Box{Vec3(0.5), Vec3(2.5)});
    CsgDesc d;
    d.op = CsgOp::Difference;
    d.children = {Child{a, Mat4(1.0), {}}, Child{b, Mat4(1.0), {}}};
    d.casts_shadow = flag(false);
    place(s, add_csg(s, std::move(d)));
  }
  if (keep(false)) {
    const NodeId a = add_shape(s, Box{Vec3(-3, -1, -0.2), Vec3(-1, 1, 0.2)});
    const NodeId g = add_group(s, {Child{a, Mat4(1.0), {}}});
    s.groups[s.nodes[g].index].casts_shadow = flag(false);
    place(s, g, rotate_deg(20.0, Vec3(0, 0, 1)));
  }
  std::vector<Child> members;
  for (int i = 0; i < 80; ++i)
    members.push_back(Child{add_shape(s, Sphere{Vec3(u(rng), u(rng), u(rng)) * 0.3, 0.15}), Mat4(1.0), {}});
  const NodeId big = add_group(s, members);
  place(s, big, translate(Vec3(-2, 2, 2)));
  if (keep(false)) {
    const NodeId shadowless = add_group(s, {Child{big, Mat4(1.0), {}}});
    s.groups[s.nodes[shadowless].index].casts_shadow = flag(false);
    place(s, shadowless, translate(Vec3(2, -2, -2)));
  }
  return s;
}

std::vector<double> crossing_ts(const ShadowCrossings& c) {
  std::vector<double> t(c.t, c.t + c.count);
  std::sort(t.begin(), t.end());
  return t;
}

}  // namespace

TEST_CASE("objects that cast no shadow are passed by shadow rays only", "[no_shadow]") {
  for (int spheres : {3, 300}) {  // without and with a top-level BVH
    CAPTURE(spheres);
    const SceneDesc flagged = make_scene(77, spheres, Build::Flagged);
    const SceneDesc removed = make_scene(77, spheres, Build::Removed);
    const SceneDesc all = make_scene(77, spheres, Build::AllCast);
    const FlatScene flat = flatten_scene(flagged);
    REQUIRE(!flat.shadowless.empty());
    REQUIRE(flat.groups.size() == 2);  // the 80-sphere group is instanced, once without a shadow
    const World w(flagged, flat), r(removed, flatten_scene(removed)), a(all, flatten_scene(all));
    REQUIRE(w.has_shadowless());
    REQUIRE_FALSE(r.has_shadowless());
    REQUIRE_FALSE(a.has_shadowless());
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-6.0, 6.0);
    int blocked = 0, differs = 0, crossed = 0;
    for (int i = 0; i < 4000; ++i) {
      const Vec3 from(u(rng), u(rng), u(rng)), to(u(rng), u(rng), u(rng));
      const Ray ray{from, to - from};
      const Interval seg(0.0, 1.0);
      const bool occ = r.occluded(ray, seg);
      REQUIRE(w.occluded(ray, seg) == occ);
      REQUIRE(w.occluded(ray, seg, true) == r.occluded(ray, seg, true));
      blocked += occ;
      differs += occ != a.occluded(ray, seg);
      ShadowCrossings cw, cr;
      const bool bw = w.shadow_crossings(ray, seg, cw), br = r.shadow_crossings(ray, seg, cr);
      REQUIRE(bw == br);
      if (!bw) {
        REQUIRE(crossing_ts(cw) == crossing_ts(cr));
        crossed += cw.count > 0;
      }
      WorldHit hw, hr, ha, hwc;
      const bool sw = w.intersect(ray, Interval::positive(), hw, false, /*shadow_ray=*/true);
      REQUIRE(sw == r.intersect(ray, Interval::positive(), hr));
      if (sw) REQUIRE(hw.t == hr.t);
      const bool tw = w.intersect(ray, Interval::positive(), hw, /*transmissive_only=*/true, true);
      REQUIRE(tw == r.intersect(ray, Interval::positive(), hr, true));
      if (tw) REQUIRE(hw.t == hr.t);
      // Camera and bounced rays see every object.
      const bool cw_hit = w.intersect(ray, Interval::positive(), hwc);
      REQUIRE(cw_hit == a.intersect(ray, Interval::positive(), ha));
      if (cw_hit) REQUIRE(hwc.t == ha.t);
    }
    CHECK(blocked > 400);  // the test sees both answers, and the flags matter
    CHECK(differs > 100);
    CHECK(crossed > 50);
  }
}

TEST_CASE("the area-light occluder search steps aside when an object casts no shadow", "[no_shadow]") {
  const SceneDesc flagged = make_scene(78, 3, Build::Flagged);
  const World w(flagged, flatten_scene(flagged));
  ShadowRegion region;
  region.box = AABB{Vec3(-1.0), Vec3(1.0)};
  OccluderCandidates c;
  CHECK_FALSE(w.occluder_candidates(region, c));  // the traversal, which skips them, is used
}
