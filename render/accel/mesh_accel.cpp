#include "render/accel/mesh_accel.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "render/geometry/shapes/triangle.hpp"

namespace rts::render {

namespace {
// Triangles per task of the constructor's parallel passes.
constexpr std::size_t kParallelGrain = 16 * 1024;
}  // namespace

MeshAccel::MeshAccel(std::shared_ptr<const MeshData> mesh) : mesh_(std::move(mesh)) {
  // Triangles whose indices point outside the vertex arrays, or with non-finite vertices, are
  // left out of the BVH (never hit). Boxes are made in float (exact: the vertices are floats)
  // straight into the builder's references, only for the valid triangles. Profile findings
  // (peak RSS at 2M triangles): two double box arrays were 96 bytes per triangle of the peak,
  // then a float box array beside the references 24 more; now the references are the only copy.
  const std::size_t n = mesh_->indices.size() / 3;
  const std::size_t vertex_count = mesh_->positions.size();
  auto box_of_triangle = [&](std::size_t i, AABB& box) {
    const uint32_t* idx = &mesh_->indices[i * 3];
    if (idx[0] >= vertex_count || idx[1] >= vertex_count || idx[2] >= vertex_count) return false;
    box = AABB{};
    for (int k = 0; k < 3; ++k) box.extend(Vec3(mesh_->positions[idx[k]]));
    return box.valid() && box.finite();
  };
  // BVH primitive → triangle index, made only once a triangle is left out (until then the
  // valid triangles are 0 .. valid_count - 1).
  std::vector<uint32_t> valid;
  bool all_valid = true;
  std::size_t valid_count = 0;
  // Most meshes have no triangle to leave out: their bounds are found on every thread first
  // (profile finding, the 320k-triangle terrain at 2 threads: this pass and the leaf-ordered
  // copy below were a quarter of the build's wall time when serial).
  struct Scan {
    AABB bounds;
    bool all_valid = true;
  };
  const Scan scan = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, kParallelGrain), Scan{},
      [&](const tbb::blocked_range<std::size_t>& r, Scan acc) {
        for (std::size_t i = r.begin(); i < r.end() && acc.all_valid; ++i) {
          AABB box;
          acc.all_valid = box_of_triangle(i, box);
          acc.bounds.extend(box);
        }
        return acc;
      },
      [](Scan a, const Scan& b) {
        a.bounds.extend(b.bounds);
        a.all_valid = a.all_valid && b.all_valid;
        return a;
      });
  if (scan.all_valid) {
    valid_count = n;
    if (n > 0) bounds_ = AABB{scan.bounds.lo + mesh_->origin, scan.bounds.hi + mesh_->origin};
  }
  for (std::size_t i = 0; i < n && !scan.all_valid; ++i) {
    AABB box;
    if (!box_of_triangle(i, box)) {
      if (all_valid) {
        all_valid = false;
        valid.reserve(n);
        for (std::size_t k = 0; k < valid_count; ++k) valid.push_back(static_cast<uint32_t>(k));
      }
      continue;
    }
    if (!all_valid) valid.push_back(static_cast<uint32_t>(i));
    ++valid_count;
    bounds_.extend(AABB{box.lo + mesh_->origin, box.hi + mesh_->origin});
  }
  triangle_count_ = valid_count;
  bvh_ = build_bvh(valid_count, [&](std::size_t p) {
    AABB box;
    box_of_triangle(all_valid ? p : valid[p], box);
    FloatBox fb;
    for (int a = 0; a < 3; ++a) {
      fb.lo[a] = static_cast<float>(box.lo[a]);
      fb.hi[a] = static_cast<float>(box.hi[a]);
    }
    return fb;
  });
  leaf_vertices_.resize(bvh_.order.size() * 3);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bvh_.order.size(), kParallelGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t slot = r.begin(); slot < r.end(); ++slot) {
                        uint32_t& o = bvh_.order[slot];
                        if (!all_valid) o = valid[o];  // leaves index triangles directly
                        const uint32_t* idx = &mesh_->indices[static_cast<std::size_t>(o) * 3];
                        for (int k = 0; k < 3; ++k) leaf_vertices_[slot * 3 + k] = mesh_->positions[idx[k]];
                      }
                    });
}

void MeshAccel::triangle(uint32_t tri, Vec3& v0, Vec3& v1, Vec3& v2) const {
  const uint32_t* idx = &mesh_->indices[static_cast<std::size_t>(tri) * 3];
  v0 = Vec3(mesh_->positions[idx[0]]);
  v1 = Vec3(mesh_->positions[idx[1]]);
  v2 = Vec3(mesh_->positions[idx[2]]);
}

Ray MeshAccel::local_ray(const Ray& ray) const {
  return Ray{ray.origin - mesh_->origin, ray.direction};
}

bool MeshAccel::intersect(const Ray& object_ray, Interval ray_t, SurfaceHit& hit, bool smooth) const {
  uint32_t best_slot = 0;
  double best_b1 = 0, best_b2 = 0;
  const Ray ray = local_ray(object_ray);
  const TriangleRay tri_ray(ray);
  bool found = traverse_bvh<false>(bvh_, ray, ray_t, [&](uint32_t slot, Interval& t_range) {
    const glm::vec3* v = &leaf_vertices_[static_cast<std::size_t>(slot) * 3];
    double t, b1, b2;
    if (!intersect_triangle(Vec3(v[0]), Vec3(v[1]), Vec3(v[2]), tri_ray, t_range, t, b1, b2)) return false;
    t_range.max = t;
    best_slot = slot;
    best_b1 = b1;
    best_b2 = b2;
    return true;
  });
  if (!found) return false;
  uint32_t best_tri = bvh_.order[best_slot];
  Vec3 v0, v1, v2;
  triangle(best_tri, v0, v1, v2);
  const uint32_t* idx = &mesh_->indices[static_cast<std::size_t>(best_tri) * 3];
  double b0 = 1.0 - best_b1 - best_b2;
  hit.t = ray_t.max;
  double local_error = 0.0;
  hit.point = triangle_point(v0, v1, v2, best_b1, best_b2, local_error) + mesh_->origin;
  hit.error = local_error + error_gamma(1) * (max_abs_component(hit.point) + max_abs_component(mesh_->origin));
  hit.normal = glm::normalize(glm::cross(v1 - v0, v2 - v0));
  hit.shading_normal = hit.normal;
  const auto& normals = mesh_->normals;
  if (smooth && normals.size() == mesh_->positions.size()) {
    Vec3 n = b0 * Vec3(normals[idx[0]]) + best_b1 * Vec3(normals[idx[1]]) +
             best_b2 * Vec3(normals[idx[2]]);
    double len = glm::length(n);
    if (len > tol::kTinyLength) {
      n /= len;
      // Vertex normals state the intended outside: turn the geometric normal to agree when
      // the triangle is wound the other way, so inside/outside tests stay consistent.
      hit.shading_normal = n;
      if (glm::dot(n, hit.normal) < 0.0) hit.normal = -hit.normal;
    }
  }
  hit.triangle = best_tri;
  hit.bary = {best_b1, best_b2};
  const auto& uvs = mesh_->uvs;
  if (uvs.size() == mesh_->positions.size()) {
    const glm::dvec2 uv0(uvs[idx[0]]), uv1(uvs[idx[1]]), uv2(uvs[idx[2]]);
    hit.uv = b0 * uv0 + best_b1 * uv1 + best_b2 * uv2;
    hit.has_uv = true;
    hit.dpdu = hit.dpdv = Vec3(0.0);
    // The tangent frame of the uv parameterisation (pbrt's dp/du, dp/dv), for bump maps.
    const glm::dvec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
    const double det = d1.x * d2.y - d1.y * d2.x;
    if (std::abs(det) > 0.0 && std::isfinite(1.0 / det)) {
      const double inv = 1.0 / det;
      hit.dpdu = (d2.y * (v1 - v0) - d1.y * (v2 - v0)) * inv;
      hit.dpdv = (-d2.x * (v1 - v0) + d1.x * (v2 - v0)) * inv;
    }
  } else {
    hit.uv = {best_b1, best_b2};
    hit.has_uv = false;
    hit.dpdu = hit.dpdv = Vec3(0.0);
  }
  return true;
}

bool MeshAccel::vertex_material(uint32_t tri, glm::dvec2 bary, VertexMaterial& out) const {
  const MeshData& m = *mesh_;
  if (!m.has_vertex_material()) return false;
  const uint32_t* idx = &m.indices[static_cast<std::size_t>(tri) * 3];
  const double w[3] = {1.0 - bary.x - bary.y, bary.x, bary.y};
  const std::size_t n = m.positions.size();
  auto mix = [&](const std::vector<float>& values, double& result) {
    if (values.size() != n) return false;
    result = w[0] * values[idx[0]] + w[1] * values[idx[1]] + w[2] * values[idx[2]];
    return true;
  };
  auto mix_rgb = [&](const std::vector<glm::vec3>& values, Color& result) {
    if (values.size() != n) return false;
    glm::dvec3 c = w[0] * glm::dvec3(values[idx[0]]) + w[1] * glm::dvec3(values[idx[1]]) +
                   w[2] * glm::dvec3(values[idx[2]]);
    result = Color(c.x, c.y, c.z);
    return true;
  };
  out.has_color = mix_rgb(m.colors, out.color);
  out.has_specular = mix_rgb(m.specular, out.specular);
  out.has_diffuse = mix(m.diffuse, out.diffuse);
  out.has_shininess = mix(m.shininess, out.shininess);
  return true;
}

bool MeshAccel::occluded(const Ray& object_ray, Interval ray_t) const {
  const Ray ray = local_ray(object_ray);
  const TriangleRay tri_ray(ray);
  return traverse_bvh<true>(bvh_, ray, ray_t, [&](uint32_t slot, Interval& t_range) {
    const glm::vec3* v = &leaf_vertices_[static_cast<std::size_t>(slot) * 3];
    double t, b1, b2;
    return intersect_triangle(Vec3(v[0]), Vec3(v[1]), Vec3(v[2]), tri_ray, t_range, t, b1, b2);
  });
}

bool MeshAccel::csg_crossings(const Ray& object_ray, double from, double tie_abs, double tie_rel,
                              CsgLeafCrossings& out) const {
  out.inside_at_start = false;
  out.count = 0;
  struct LineHit {
    double t;
    int facing;  // +1: the triangle faces the line (entered, for outward winding), -1: away
  };
  // Every triangle the line meets; a line crossing a mesh more often than this is taken as
  // missing the rest (kept in traversal order): far beyond any solid a scene builds.
  constexpr int kMaxLineHits = 512;
  LineHit hits[kMaxLineHits];
  int n = 0;
  const Ray ray = local_ray(object_ray);
  const TriangleRay tri_ray(ray);
  Interval everywhere = Interval::universe();
  traverse_bvh<false>(bvh_, ray, everywhere, [&](uint32_t slot, Interval& t_range) {
    const glm::vec3* v = &leaf_vertices_[static_cast<std::size_t>(slot) * 3];
    const Vec3 v0(v[0]), v1(v[1]), v2(v[2]);
    double t, b1, b2;
    if (n < kMaxLineHits && intersect_triangle(v0, v1, v2, tri_ray, t_range, t, b1, b2))
      hits[n++] = LineHit{t, glm::dot(ray.direction, glm::cross(v1 - v0, v2 - v0)) < 0.0 ? 1 : -1};
    return false;  // keep the whole line
  });
  if (n == 0) return false;
  std::sort(hits, hits + n, [](const LineHit& a, const LineHit& b) { return a.t < b.t || (a.t == b.t && a.facing < b.facing); });
  // Places along the line, then the winding number across them: inside where it is not zero.
  int winding = 0;
  bool truncated = false;
  for (int i = 0; i < n;) {
    const double t0 = hits[i].t;
    const double tie = tie_abs + tie_rel * std::abs(t0);
    bool toward = false, away = false;
    int j = i;
    for (; j < n && hits[j].t - t0 <= tie; ++j) (hits[j].facing > 0 ? toward : away) = true;
    i = j;
    if (toward == away) continue;  // a graze: touched, not crossed
    const bool was_inside = winding != 0;
    winding += toward ? 1 : -1;
    if ((winding != 0) == was_inside) continue;
    if (t0 < from) {
      out.inside_at_start = winding != 0;
      continue;
    }
    if (out.count == kMaxLeafCrossings) {
      truncated = true;
      break;
    }
    out.t[out.count++] = t0;
  }
  return truncated;
}

std::size_t MeshAccel::memory_bytes() const {
  const MeshData& m = *mesh_;
  return m.positions.size() * sizeof(m.positions[0]) + m.normals.size() * sizeof(m.normals[0]) +
         m.uvs.size() * sizeof(m.uvs[0]) + m.indices.size() * sizeof(m.indices[0]) +
         bvh_.nodes.size() * sizeof(BVHNode) + bvh_.order.size() * sizeof(uint32_t) +
         leaf_vertices_.size() * sizeof(leaf_vertices_[0]);
}

}  // namespace rts::render
