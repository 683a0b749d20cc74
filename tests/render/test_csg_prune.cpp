// CSG pruning (render/geometry/csg/csg_prune.hpp): leaves left out because their state cannot
// matter inside the ray's interval must never change the surface found. Random trees over
// random crossing lists on a coarse grid (so that many crossings coincide and batch together)
// against the sweep over every leaf; then whole scenes through World: pruning on and off give
// the same hits on random rays, and a shadow ray's occlusion agrees with the closest hit.
#include <algorithm>
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "render/geometry/csg/csg_prune.hpp"
#include "render/geometry/csg/csg_tree.hpp"
#include "render/geometry/csg/leaf_crossings.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// A random tree in post-order; leaves numbered in the order made.
uint32_t random_node(CsgTree& t, std::mt19937& rng, int depth) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CsgNode n;
  n.inverse = u(rng) < 0.12;
  if (depth == 0 || u(rng) < 0.3) {
    n.leaf = true;
    n.first = t.leaf_count++;
  } else {
    const CsgOp ops[] = {CsgOp::Union, CsgOp::Merge, CsgOp::Intersection, CsgOp::Difference, CsgOp::Clip};
    n.op = ops[std::uniform_int_distribution<int>(0, 4)(rng)];
    uint32_t count = std::uniform_int_distribution<uint32_t>(1, 4)(rng);
    std::vector<uint32_t> kids;
    for (uint32_t k = 0; k < count; ++k) kids.push_back(random_node(t, rng, depth - 1));
    n.first = static_cast<uint32_t>(t.children.size());
    n.count = count;
    t.children.insert(t.children.end(), kids.begin(), kids.end());
  }
  t.nodes.push_back(n);
  return static_cast<uint32_t>(t.nodes.size() - 1);
}

// A leaf's crossings on a grid of halves: a bounded solid (an even count, outside at both
// ends) or, one time in eight, a half-space (one crossing, or none and inside throughout).
CsgLeafCrossings random_leaf(std::mt19937& rng, bool& bounded) {
  std::uniform_int_distribution<int> grid(-4, 16);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CsgLeafCrossings c;
  bounded = u(rng) >= 0.125;
  if (!bounded) {
    c.inside_at_start = u(rng) < 0.5;
    c.count = u(rng) < 0.9 ? 1 : 0;
    c.t[0] = 0.5 * grid(rng);
    return c;
  }
  c.count = u(rng) < 0.8 ? 2 : 4;
  for (int k = 0; k < c.count; ++k) c.t[k] = 0.5 * grid(rng);
  // Insertion sort of at most four values: GCC 12 cannot bound std::sort's indices here and
  // warns (-Warray-bounds) about ones it never reaches.
  for (int i = 1; i < c.count; ++i)
    for (int j = i; j > 0 && c.t[j - 1] > c.t[j]; --j) std::swap(c.t[j - 1], c.t[j]);
  return c;
}

// The sweep as it was before the speed work (main at dca14c6): every batch evaluates the
// tree and runs the visibility pass. The faster sweep must give the same surface.
struct RefEvent {
  double t;
  uint32_t leaf;
};

bool reference_first_surface(const CsgTree& tree, const CsgLeafCrossings* leaves, const Interval& ray_t, double tie_abs,
                       double tie_rel, CsgSurface& out) {
  const uint32_t nl = tree.leaf_count;
  const std::size_t nn = tree.nodes.size();
  if (nl == 0 || nl > kMaxCsgLeaves || nn == 0 || nn > kMaxCsgNodes) return false;
  RefEvent ev[kMaxCsgLeaves * kMaxLeafCrossings];
  uint8_t leaf_in[kMaxCsgLeaves];
  int ne = 0;
  for (uint32_t l = 0; l < nl; ++l) {
    leaf_in[l] = leaves[l].inside_at_start ? 1 : 0;
    for (int k = 0; k < leaves[l].count && k < kMaxLeafCrossings; ++k) ev[ne++] = RefEvent{leaves[l].t[k], l};
  }
  if (ne == 0) return false;  // the state never changes along the line: no surface
  std::sort(ev, ev + ne, [](const RefEvent& a, const RefEvent& b) { return a.t < b.t || (a.t == b.t && a.leaf < b.leaf); });

  uint8_t before[kMaxCsgNodes], after[kMaxCsgNodes], visible[kMaxCsgNodes];
  tree.evaluate(leaf_in, before);
  int i = 0;
  while (i < ne) {
    const double t0 = ev[i].t;
    if (t0 >= ray_t.max) return false;  // later batches are all beyond the range
    const double tie = tie_abs + tie_rel * std::abs(t0);
    int j = i;
    while (j < ne && ev[j].t - t0 <= tie) {
      leaf_in[ev[j].leaf] ^= 1;
      ++j;
    }
    tree.evaluate(leaf_in, after);
    // Which nodes show a surface in this batch (post-order, so children first).
    for (std::size_t k = 0; k < nn; ++k) {
      const CsgNode& n = tree.nodes[k];
      bool v = before[k] != after[k];
      if (!n.leaf && n.op == CsgOp::Union)
        for (uint32_t c = 0; c < n.count && !v; ++c) v = visible[tree.children[n.first + c]] != 0;
      if (!n.leaf && n.op == CsgOp::Clip) {  // the first child's surface where every clipper is inside
        const uint32_t* c = tree.children.data() + n.first;
        bool in_before = true, in_after = true;
        for (uint32_t q = 1; q < n.count; ++q) {
          in_before = in_before && before[c[q]] != 0;
          in_after = in_after && after[c[q]] != 0;
        }
        v = visible[c[0]] != 0 && (in_before || in_after);
      }
      visible[k] = v;
    }
    if (visible[nn - 1]) {
      // Down to the leaf: the first child that shows; the orientation from the highest node
      // on the way whose state changes (a union's inner surface: the child's own).
      uint32_t k = static_cast<uint32_t>(nn - 1);
      bool oriented = false, entering = false;
      while (true) {
        if (!oriented && before[k] != after[k]) {
          oriented = true;
          entering = after[k] != 0;
        }
        const CsgNode& n = tree.nodes[k];
        if (n.leaf) break;
        uint32_t next = k;
        for (uint32_t c = 0; c < n.count; ++c)
          if (visible[tree.children[n.first + c]]) {
            next = tree.children[n.first + c];
            break;
          }
        if (next == k) break;  // cannot happen: a changed operation has a changed child
        k = next;
      }
      const CsgNode& leaf = tree.nodes[k];
      if (leaf.leaf) {
        double t = t0;
        for (int e = i; e < j; ++e)
          if (ev[e].leaf == leaf.first) {
            t = ev[e].t;
            break;
          }
        if (ray_t.surrounds(t)) {
          out.t = t;
          out.leaf = leaf.first;
          out.entering = entering;
          return true;
        }
      }
    }
    std::copy(after, after + nn, before);
    i = j;
  }
  return false;
}

bool same(bool a, const CsgSurface& x, bool b, const CsgSurface& y) {
  return a == b && (!a || (x.t == y.t && x.leaf == y.leaf && x.entering == y.entering));
}

}  // namespace

TEST_CASE("csg pruning: leaves left out never change the sweep's surface", "[csg]") {
  std::mt19937 rng(20261128);
  const double tie_abs = 1e-12, tie_rel = 1e-12;
  int found = 0, pruned_leaves = 0, total_leaves = 0, skipped = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    CsgTree tree;
    random_node(tree, rng, 3);
    std::vector<CsgLeafCrossings> all(tree.leaf_count);
    std::vector<bool> bounded(tree.leaf_count);
    for (uint32_t l = 0; l < tree.leaf_count; ++l) {
      bool b;
      all[l] = random_leaf(rng, b);
      bounded[l] = b;
    }
    std::uniform_int_distribution<int> grid(-2, 14);
    double a = 0.5 * grid(rng), b = 0.5 * grid(rng);
    Interval ray_t(std::min(a, b), grid(rng) < 0 ? Interval::kInfinity : std::max(a, b) + 0.5);

    std::vector<CsgLeafCrossings> kept(tree.leaf_count);
    Interval root = csg_gather(tree, ray_t, kept.data(), [&](uint32_t l, const Interval& span) {
      // As World does: a bounded leaf whose extent misses the widened span stays empty.
      const double lo = span.min - 4.0 * (tie_abs + tie_rel * std::abs(span.min));
      const double hi = span.max + 4.0 * (tie_abs + tie_rel * std::abs(span.max));
      if (bounded[l] && (all[l].t[all[l].count - 1] < lo || all[l].t[0] > hi)) return;
      kept[l] = all[l];
    });
    for (uint32_t l = 0; l < tree.leaf_count; ++l) pruned_leaves += kept[l].count != all[l].count;
    total_leaves += static_cast<int>(tree.leaf_count);

    CsgSurface full, pruned;
    bool f = csg_first_surface(tree, all.data(), ray_t, tie_abs, tie_rel, full);
    bool p = csg_first_surface(tree, kept.data(), ray_t, tie_abs, tie_rel, pruned);
    CsgSurface ref;
    bool r = reference_first_surface(tree, all.data(), ray_t, tie_abs, tie_rel, ref);
    found += f;
    INFO("trial " << trial);
    REQUIRE(same(f, full, r, ref));
    REQUIRE(same(f, full, p, pruned));
    // World skips the sweep when the root cannot be inside near ray_t: then there is nothing.
    const Interval wide(ray_t.min - 4.0 * (tie_abs + tie_rel * std::abs(ray_t.min)),
                        ray_t.max + 4.0 * (tie_abs + tie_rel * std::abs(ray_t.max)));
    if (root.intersect(wide).empty()) {
      REQUIRE_FALSE(f);
      ++skipped;
    }
  }
  // The test means something only if both happen often.
  CHECK(found > 2000);
  CHECK(pruned_leaves > total_leaves / 10);
  CHECK(skipped > 1000);
}

TEST_CASE("csg leaves: sphere and box crossings are convex_crossings's, bit for bit", "[csg]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-1.0, 1.0);
  int crossed = 0;
  for (int i = 0; i < 200000; ++i) {
    Sphere sp{Vec3(c(rng), c(rng), c(rng)), i % 97 == 0 ? 0.0 : 0.1 + u(rng)};
    Box bx{Vec3(c(rng), c(rng), c(rng)) - 0.5, Vec3(c(rng), c(rng), c(rng)) + 0.5};
    Vec3 o(3 * c(rng), 3 * c(rng), 3 * c(rng));
    Vec3 d(c(rng), c(rng), c(rng));
    switch (i % 8) {  // rays along axes, starting on the surfaces, grazing
      case 0: d = Vec3(0, 0, c(rng)); break;
      case 1: d = Vec3(c(rng), 0, 0); o.y = bx.min.y; break;
      case 2: o = sp.center + sp.radius * glm::normalize(d); break;
      case 3: o = Vec3(bx.max.x, o.y, o.z); d.x = 0; break;
      case 4: d = Vec3(0.0); break;
      default: break;
    }
    Ray ray{o, d};
    CsgLeafCrossings fast, ref;
    leaf_crossings(sp, ray, fast);
    convex_crossings(sp, ray, ref);
    INFO("ray " << i);
    REQUIRE(fast.count == ref.count);
    REQUIRE(fast.inside_at_start == ref.inside_at_start);
    for (int k = 0; k < ref.count; ++k) REQUIRE(fast.t[k] == ref.t[k]);
    leaf_crossings(bx, ray, fast);
    convex_crossings(bx, ray, ref);
    REQUIRE(fast.count == ref.count);
    for (int k = 0; k < ref.count; ++k) REQUIRE(fast.t[k] == ref.t[k]);
    crossed += ref.count > 0;
  }
  CHECK(crossed > 20000);
}

// ---- whole scenes through World ---------------------------------------------------------------

namespace {

// A random CSG node (shape, or a block of 1-4 children) placed by a random rotation,
// translation and (sometimes) scale; some children are flush copies of a sibling's box face,
// so coincident crossings are common.
NodeId random_csg_node(SceneDesc& s, std::mt19937& rng, int depth, MaterialId mat) {
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-1.0, 1.0);
  if (depth == 0 || u(rng) < 0.3) {
    ShapeGeometry g;
    double pick = u(rng);
    if (pick < 0.3) g = Sphere{Vec3(c(rng), c(rng), c(rng)) * 0.5, 0.3 + 0.7 * u(rng)};
    else if (pick < 0.55) g = Box{Vec3(-0.5 - 0.5 * u(rng)), Vec3(0.5, 0.5 + 0.5 * u(rng), 0.5)};
    else if (pick < 0.7) g = Torus{0.7, 0.2 + 0.2 * u(rng)};
    else if (pick < 0.85) g = Cylinder{Vec3(0, -0.6, 0), Vec3(0, 0.6, 0), 0.2 + 0.5 * u(rng), true};
    else if (pick < 0.92) g = Box{Vec3(-0.5), Vec3(0.5)};  // flush with the boxes above: ties
    else g = Plane{Vec3(c(rng), 1.0, c(rng)), 0.3 * c(rng)};
    NodeId n = add_shape(s, g, u(rng) < 0.5 ? mat + 1 : mat);
    s.shapes.back().inverse = u(rng) < 0.1;
    return n;
  }
  CsgDesc d;
  const CsgOp ops[] = {CsgOp::Union, CsgOp::Merge, CsgOp::Intersection, CsgOp::Difference, CsgOp::Clip};
  d.op = ops[std::uniform_int_distribution<int>(0, 4)(rng)];
  d.inverse = u(rng) < 0.1;
  int count = std::uniform_int_distribution<int>(1, 4)(rng);
  for (int k = 0; k < count; ++k) {
    Mat4 m = u(rng) < 0.3 ? Mat4(1.0)
                          : translate(Vec3(c(rng), c(rng), c(rng)) * 0.4) *
                                rotate_deg(180.0 * c(rng), glm::normalize(Vec3(c(rng), c(rng), 1.0))) *
                                (u(rng) < 0.3 ? scale(Vec3(0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng))) : Mat4(1.0));
    d.children.push_back(Child{random_csg_node(s, rng, depth - 1, mat), m, {}});
  }
  return add_csg(s, std::move(d));
}

}  // namespace

TEST_CASE("csg pruning: World's hits and shadow rays agree with every leaf computed", "[csg]") {
  std::mt19937 rng(112826);
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-1.0, 1.0);
  int hits = 0, blocked = 0, rays = 0;
  for (int scene_no = 0; scene_no < 40; ++scene_no) {
    SceneDesc s;
    MaterialId a = add_material(s, emissive(Color(1, 0, 0)));
    add_material(s, emissive(Color(0, 1, 0)));
    for (int b = 0; b < 3; ++b) {
      NodeId n = random_csg_node(s, rng, 3, a);
      if (s.nodes[n].kind != NodeKind::Csg) {  // a block at the top
        CsgDesc d;
        d.op = CsgOp::Intersection;
        d.children.push_back(Child{n, Mat4(1.0), {}});
        n = add_csg(s, std::move(d));
      }
      place(s, n, translate(Vec3(2.0 * b - 2.0, 0, 0)));
    }
    FlatScene flat = flatten_scene(s);
    World pruned(s, flat), full(s, flat);
    full.set_csg_pruning(false);
    for (int r = 0; r < 500; ++r) {
      // From outside, and from inside the blocks (shadow rays start on or in them).
      Vec3 o = u(rng) < 0.5 ? Vec3(6 * c(rng), 4 * c(rng), -6) : Vec3(3 * c(rng), c(rng), c(rng));
      Vec3 target(3 * c(rng), c(rng), c(rng));
      Ray ray{o, target - o};
      if (u(rng) < 0.2) ray.direction = Vec3(c(rng), c(rng), c(rng));  // anywhere
      Interval range(u(rng) < 0.5 ? 0.0 : 0.5 * u(rng), u(rng) < 0.5 ? Interval::kInfinity : 0.3 + 1.5 * u(rng));
      WorldHit hp, hf;
      bool p = pruned.intersect(ray, range, hp), f = full.intersect(ray, range, hf);
      INFO("scene " << scene_no << " ray " << r);
      REQUIRE(p == f);
      if (p) {
        CHECK(hp.t == hf.t);
        CHECK(hp.instance == hf.instance);
        CHECK(hp.normal == hf.normal);
        ++hits;
      }
      // Occlusion over the segment agrees with the closest hit inside it.
      bool o_p = pruned.occluded(ray, range), o_f = full.occluded(ray, range);
      CHECK(o_p == p);
      CHECK(o_f == f);
      blocked += o_p;
      ++rays;
    }
  }
  CHECK(hits > rays / 10);
  CHECK(blocked > rays / 10);
}
