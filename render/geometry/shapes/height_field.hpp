// Height field (POV-Ray's `height_field`): heights in [0, 1] sampled on an nx by nz grid over
// the unit square x, z in [0, 1], y up. Each grid cell is two triangles split along the
// diagonal from (ix + 1, iz) to (ix, iz + 1), as in POV-Ray (hfield.cpp), so a scene and its
// POV-Ray twin show the same facets. `smooth` blends POV-Ray's averaged vertex normals
// bilinearly across a cell; `water_level` hides the surface below it.
//
// Tracing walks the grid (never a mesh of all triangles: the grid is the only storage): a 2-D
// DDA over blocks of 8 x 8 cells, each block skipped when the ray's height over it misses the
// block's height range, then a DDA over the block's cells, each skipped the same way, then
// the cell's two triangles, whose planes the ray meets where a linear function of t vanishes.
// Cells, and the two halves of a cell, are half-open intervals of t, so a ray through an edge
// is counted once (CSG's parity depends on it).
//
// The solid (CSG, `inverse`) is POV-Ray's inside test: inside the unit square, below the
// surface or below water_level, without a floor (POV-Ray's Inside_HField). Its boundary along a
// line is the surface (or the water plane) plus the column's walls under the surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

// The `height_field` block: see docs/shapes.md#height_field. Built by the scene builder (it
// reads an image file, or samples a compiled macro).
template <>
struct ShapeTraits<HeightField> {
  static constexpr PropertyInfo kProperties[] = {
      {"file", "string", "—", "An image (PNG, BMP, JPEG, TGA, HDR): its brightness is the height, the image's bottom row at z = 0. Give `file` or `function`."},
      {"function", "macro of a point", "—", "h(p), p = <x, 0, z> over the unit square: the height there (clamped to [0, 1])."},
      {"resolution", "whole number ≥ 2, or [nx, nz]", "`256`", "With `function`: the samples along x and z."},
      {"smooth", "bool", "`false`", "Blend POV-Ray's averaged vertex normals across each cell (smooth shading)."},
      {"water_level", "number in [0, 1]", "`0`", "The surface below this height is not drawn (the solid is filled up to it)."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "height_field", .properties = kProperties, .closure = Closure::Closed, .has_uv = true};
};

// Builds the grid's blocks and, for `smooth`, POV-Ray's vertex normals: the sum of the four
// quadrants' unit normals around each sample (only those inside the grid), in POV-Ray's own
// units (cells 1 wide, heights 0 .. 65535) so the averages weigh the same.
inline std::shared_ptr<HeightFieldData> make_height_field_data(int nx, int nz, std::vector<float> heights,
                                                               bool smooth) {
  auto d = std::make_shared<HeightFieldData>();
  d->nx = nx;
  d->nz = nz;
  d->height = std::move(heights);
  auto h = [&](int ix, int iz) { return d->height[static_cast<std::size_t>(iz) * nx + ix]; };
  d->min_height = *std::min_element(d->height.begin(), d->height.end());
  d->max_height = *std::max_element(d->height.begin(), d->height.end());
  const int cx = nx - 1, cz = nz - 1;
  d->blocks_x = (cx + d->block - 1) / d->block;
  d->blocks_z = (cz + d->block - 1) / d->block;
  d->block_lo.assign(static_cast<std::size_t>(d->blocks_x) * d->blocks_z, std::numeric_limits<float>::infinity());
  d->block_hi.assign(d->block_lo.size(), -std::numeric_limits<float>::infinity());
  for (int iz = 0; iz < nz; ++iz)
    for (int ix = 0; ix < nx; ++ix) {
      // A sample is a corner of the blocks on both sides of a block border.
      for (int bz = std::max(0, (iz - 1) / d->block); bz <= std::min(d->blocks_z - 1, iz / d->block); ++bz)
        for (int bx = std::max(0, (ix - 1) / d->block); bx <= std::min(d->blocks_x - 1, ix / d->block); ++bx) {
          std::size_t b = static_cast<std::size_t>(bz) * d->blocks_x + bx;
          d->block_lo[b] = std::min(d->block_lo[b], h(ix, iz));
          d->block_hi[b] = std::max(d->block_hi[b], h(ix, iz));
        }
    }
  if (smooth) {
    d->normals.resize(d->height.size());
    const double scale = 65535.0;
    auto corner = [&](int ix, int iz) { return glm::dvec3(ix, scale * h(ix, iz), iz); };
    auto add = [&](glm::dvec3& n, int x0, int z0, int x1, int z1, int x2, int z2) {
      if (std::min({x0, x1, x2, z0, z1, z2}) < 0 || std::max({x0, x1, x2}) > cx || std::max({z0, z1, z2}) > cz) return;
      glm::dvec3 v0 = corner(x0, z0);
      glm::dvec3 c = glm::cross(corner(x2, z2) - v0, corner(x1, z1) - v0);
      double len = glm::length(c);
      if (!(len > 0.0)) return;
      c /= len;
      n += c.y < 0.0 ? -c : c;
    };
    for (int iz = 0; iz < nz; ++iz)
      for (int ix = 0; ix < nx; ++ix) {
        glm::dvec3 n(0.0);
        add(n, ix, iz, ix + 1, iz, ix, iz + 1);
        add(n, ix, iz, ix, iz + 1, ix - 1, iz);
        add(n, ix, iz, ix - 1, iz, ix, iz - 1);
        add(n, ix, iz, ix, iz - 1, ix + 1, iz);
        double len = glm::length(n);
        d->normals[static_cast<std::size_t>(iz) * nx + ix] = len > 0.0 ? glm::vec3(n / len) : glm::vec3(0, 1, 0);
      }
  }
  return d;
}

inline AABB bounds(const HeightField& f) {
  if (!f.data) return AABB{};
  double lo = std::max<double>(f.data->min_height, f.water_level), hi = f.data->max_height;
  if (lo > hi) lo = hi;  // all under water: an empty slab at the top (nothing is drawn)
  return AABB{Vec3(0.0, lo, 0.0), Vec3(1.0, hi, 1.0)};
}

namespace hf_detail {

// Visits the cells of a 2-D grid of square cells `size` wide (cell i spans [i size, (i+1) size))
// that the path o + t d (x and z only) crosses for t in [t0, t1), in order, cell indices kept in
// [x_lo, x_hi) x [z_lo, z_hi): visit(ix, iz, ta, tb) for each non-empty [ta, tb); it returns true
// to stop the walk (the walk then returns true). Boundaries are recomputed from the cell index
// (not accumulated), so neighbouring cells share their boundary t exactly.
template <class F>
bool walk(double ox, double oz, double dx, double dz, double t0, double t1, int x_lo, int x_hi, int z_lo, int z_hi,
          double size, F&& visit) {
  const double inf = std::numeric_limits<double>::infinity();
  int ix = std::clamp(static_cast<int>(std::floor((ox + dx * t0) / size)), x_lo, x_hi - 1);
  int iz = std::clamp(static_cast<int>(std::floor((oz + dz * t0) / size)), z_lo, z_hi - 1);
  const int sx = dx > 0.0 ? 1 : -1, sz = dz > 0.0 ? 1 : -1;
  auto next = [&](int i, double o, double d) { return d == 0.0 ? inf : ((i + (d > 0.0 ? 1 : 0)) * size - o) / d; };
  double t = t0;
  for (int guard = 0; guard < (x_hi - x_lo) + (z_hi - z_lo) + 2; ++guard) {
    double tnx = next(ix, ox, dx), tnz = next(iz, oz, dz);
    double tn = std::min(tnx, tnz);
    double te = std::min(tn, t1);
    if (te > t) {
      if (visit(ix, iz, t, te)) return true;
      t = te;
    }
    if (!(tn < t1)) return false;
    if (tnx <= tnz) {
      ix += sx;
      if (ix < x_lo || ix >= x_hi) return false;
    } else {
      iz += sz;
      if (iz < z_lo || iz >= z_hi) return false;
    }
  }
  return false;
}

// The ray in grid units: x and z in cells, y the height.
struct GridRay {
  double ox, oy, oz, dx, dy, dz;
};

inline GridRay grid_ray(const HeightFieldData& d, const Ray& ray) {
  const double cx = d.nx - 1, cz = d.nz - 1;
  return {ray.origin.x * cx, ray.origin.y, ray.origin.z * cz, ray.direction.x * cx, ray.direction.y, ray.direction.z * cz};
}

// [t0, t1] where the line is inside the square's column (x, z in [0, 1]); false when it misses.
// A line parallel to y inside the column gets the whole line.
inline bool column_span(const Ray& ray, double& t0, double& t1) {
  t0 = -std::numeric_limits<double>::infinity();
  t1 = std::numeric_limits<double>::infinity();
  for (int a : {0, 2}) {
    double o = ray.origin[a], dd = ray.direction[a];
    if (dd == 0.0) {
      if (!(o >= 0.0 && o <= 1.0)) return false;
      continue;
    }
    double ta = (0.0 - o) / dd, tb = (1.0 - o) / dd;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

inline float sample(const HeightFieldData& d, int ix, int iz) { return d.height[static_cast<std::size_t>(iz) * d.nx + ix]; }

// The surface's height at grid point (gx, gz) (clamped into the grid), POV-Ray's triangles.
inline double surface_at(const HeightFieldData& d, double gx, double gz) {
  int ix = std::clamp(static_cast<int>(std::floor(gx)), 0, d.nx - 2);
  int iz = std::clamp(static_cast<int>(std::floor(gz)), 0, d.nz - 2);
  double s = std::clamp(gx - ix, 0.0, 1.0), u = std::clamp(gz - iz, 0.0, 1.0);
  double h00 = sample(d, ix, iz), h10 = sample(d, ix + 1, iz), h01 = sample(d, ix, iz + 1), h11 = sample(d, ix + 1, iz + 1);
  if (s + u < 1.0) return h00 + (h10 - h00) * s + (h01 - h00) * u;
  return h11 + (h01 - h11) * (1.0 - s) + (h10 - h11) * (1.0 - u);
}

// What a root is on: the cell's lower or upper triangle, or the water plane.
enum class Part : uint8_t { Lower, Upper, Water };

// The roots in cell (ix, iz) for t in [ta, tb), ascending: emit(t, part) returns true to stop.
// `solid`: the boundary of the solid (the surface where it is above water, the water plane
// where it is below), else only the surface drawn (at or above water).
template <class F>
bool cell_roots(const HeightFieldData& d, const GridRay& r, double water, bool solid, int ix, int iz, double ta,
                double tb, F&& emit) {
  const double h00 = sample(d, ix, iz), h10 = sample(d, ix + 1, iz), h01 = sample(d, ix, iz + 1),
               h11 = sample(d, ix + 1, iz + 1);
  double lo = std::min({h00, h10, h01, h11}), hi = std::max({h00, h10, h01, h11});
  if (solid) lo = std::max(lo, water), hi = std::max(hi, water);
  else if (hi < water) return false;
  double ya = r.oy + r.dy * ta, yb = r.oy + r.dy * tb;
  double margin = tol::kHeightFieldCellMargin * (1.0 + std::abs(ya) + std::abs(yb));
  if (std::max(ya, yb) < lo - margin || std::min(ya, yb) > hi + margin) return false;
  // s + u along the ray (s, u: the position inside the cell); the diagonal is s + u = 1.
  const double su0 = (r.ox - ix) + (r.oz - iz), su1 = r.dx + r.dz;
  double cuts[4] = {ta, tb, tb, tb};
  int n = 2;
  if (su1 != 0.0) {
    double td = (1.0 - su0) / su1;
    if (td > ta && td < tb) cuts[1] = td, cuts[2] = tb, n = 3;
  }
  for (int p = 0; p + 1 < n; ++p) {
    double lo_t = cuts[p], hi_t = cuts[p + 1];
    double mid = 0.5 * (lo_t + hi_t);
    bool lower = su0 + su1 * mid < 1.0;
    // The plane's height along the ray: c0 + c1 t (s = ox - ix + dx t, u = oz - iz + dz t).
    double c0, c1;
    if (lower) {
      double a = h10 - h00, b = h01 - h00;
      c0 = h00 + a * (r.ox - ix) + b * (r.oz - iz);
      c1 = a * r.dx + b * r.dz;
    } else {
      double a = h11 - h01, b = h11 - h10;  // d/ds and d/du
      c0 = h11 + a * (r.ox - ix - 1.0) + b * (r.oz - iz - 1.0);
      c1 = a * r.dx + b * r.dz;
    }
    // Sub-pieces where the plane is above or below the water (the plane crosses it once).
    double sub[3] = {lo_t, hi_t, hi_t};
    int m = 2;
    if (c1 != 0.0) {
      double tw = (water - c0) / c1;
      if (tw > lo_t && tw < hi_t) sub[1] = tw, sub[2] = hi_t, m = 3;
    }
    for (int q = 0; q + 1 < m; ++q) {
      double a_t = sub[q], b_t = sub[q + 1];
      double plane_mid = c0 + c1 * (0.5 * (a_t + b_t));
      bool dry = plane_mid >= water;
      if (!dry && !solid) continue;
      // y(t) - level(t) = g0 + g1 t vanishes at the root.
      double g0 = dry ? r.oy - c0 : r.oy - water, g1 = dry ? r.dy - c1 : r.dy;
      if (g1 == 0.0) continue;  // parallel to the plane: it grazes, no crossing
      double t = -g0 / g1;
      if (t >= a_t && t < b_t && emit(t, dry ? (lower ? Part::Lower : Part::Upper) : Part::Water)) return true;
    }
  }
  return false;
}

// Walks blocks then cells over [t0, t1) calling cell_roots; returns true when emit stopped it.
template <class F>
bool roots(const HeightFieldData& d, const GridRay& r, double water, bool solid, double t0, double t1, F&& emit) {
  const int cx = d.nx - 1, cz = d.nz - 1, B = d.block;
  return walk(r.ox, r.oz, r.dx, r.dz, t0, t1, 0, d.blocks_x, 0, d.blocks_z, static_cast<double>(B),
              [&](int bx, int bz, double ta, double tb) {
                std::size_t b = static_cast<std::size_t>(bz) * d.blocks_x + bx;
                double lo = d.block_lo[b], hi = d.block_hi[b];
                if (solid) lo = std::max(lo, water), hi = std::max(hi, water);
                else if (hi < water) return false;
                double ya = r.oy + r.dy * ta, yb = r.oy + r.dy * tb;
                double margin = tol::kHeightFieldCellMargin * (1.0 + std::abs(ya) + std::abs(yb));
                if (std::max(ya, yb) < lo - margin || std::min(ya, yb) > hi + margin) return false;
                return walk(r.ox, r.oz, r.dx, r.dz, ta, tb, bx * B, std::min(cx, (bx + 1) * B), bz * B,
                            std::min(cz, (bz + 1) * B), 1.0, [&](int ix, int iz, double ca, double cb) {
                              return cell_roots(d, r, water, solid, ix, iz, ca, cb, emit);
                            });
              });
}

}  // namespace hf_detail

// The hit at root t on `part` (the cell is found again from the point).
inline void height_field_hit_at(const HeightField& f, const Ray& ray, double t, hf_detail::Part part, SurfaceHit& hit) {
  const HeightFieldData& d = *f.data;
  const double cx = d.nx - 1, cz = d.nz - 1;
  Vec3 p = ray.at(t);
  hit.t = t;
  hit.point = p;
  // The root is one division of differences of the grid's own size: the ray's rounding, and
  // the heights' (order 1) times the grid's size in cells.
  hit.error = 8.0 * ray_point_error(ray, t) + tol::kHeightFieldRootRelative * (cx + cz) *
                                                   (1.0 + max_abs_component(ray.origin) + std::abs(t) * max_abs_component(ray.direction));
  hit.has_uv = true;
  hit.uv = glm::dvec2(p.x, p.z);
  if (part == hf_detail::Part::Water) {
    hit.normal = hit.shading_normal = Vec3(0, 1, 0);
    return;
  }
  double gx = p.x * cx, gz = p.z * cz;
  int ix = std::clamp(static_cast<int>(std::floor(gx)), 0, d.nx - 2);
  int iz = std::clamp(static_cast<int>(std::floor(gz)), 0, d.nz - 2);
  double s = std::clamp(gx - ix, 0.0, 1.0), u = std::clamp(gz - iz, 0.0, 1.0);
  const double h00 = hf_detail::sample(d, ix, iz), h10 = hf_detail::sample(d, ix + 1, iz),
               h01 = hf_detail::sample(d, ix, iz + 1), h11 = hf_detail::sample(d, ix + 1, iz + 1);
  // Slopes per cell, turned into the object space's: d/dx = d/ds * (nx - 1).
  Vec3 n = part == hf_detail::Part::Lower ? Vec3(-(h10 - h00) * cx, 1.0, -(h01 - h00) * cz)
                                          : Vec3(-(h11 - h01) * cx, 1.0, -(h11 - h10) * cz);
  hit.normal = n;
  hit.shading_normal = n;
  if (!d.normals.empty() && f.smooth) {
    // POV-Ray's: each vertex normal into object space, unit, then blended bilinearly.
    auto vn = [&](int jx, int jz) {
      glm::vec3 v = d.normals[static_cast<std::size_t>(jz) * d.nx + jx];
      Vec3 w(v.x * cx, v.y * 65535.0, v.z * cz);
      double len = glm::length(w);
      return len > 0.0 ? w / len : Vec3(0, 1, 0);
    };
    Vec3 sn = (1.0 - u) * ((1.0 - s) * vn(ix, iz) + s * vn(ix + 1, iz)) + u * ((1.0 - s) * vn(ix, iz + 1) + s * vn(ix + 1, iz + 1));
    if (glm::length(sn) > 0.0) hit.shading_normal = sn;
  }
}

inline bool intersect(const HeightField& f, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  if (!f.data) return false;
  const HeightFieldData& d = *f.data;
  double t0, t1;
  if (!hf_detail::column_span(ray, t0, t1)) return false;
  // Clip to the drawn slab in y, then to ray_t.
  AABB box = bounds(f);
  if (ray.direction.y != 0.0) {
    double ta = (box.lo.y - ray.origin.y) / ray.direction.y, tb = (box.hi.y - ray.origin.y) / ray.direction.y;
    if (ta > tb) std::swap(ta, tb);
    double pad = tol::kHeightFieldCellMargin * (1.0 + std::abs(ta) + std::abs(tb));
    t0 = std::max(t0, ta - pad);
    t1 = std::min(t1, tb + pad);
  } else if (ray.origin.y < box.lo.y || ray.origin.y > box.hi.y) {
    return false;
  }
  t0 = std::max(t0, ray_t.min);
  t1 = std::min(t1, ray_t.max);
  if (!(t0 < t1) || !std::isfinite(t0) || !std::isfinite(t1)) return false;
  const hf_detail::GridRay r = hf_detail::grid_ray(d, ray);
  double found = 0.0;
  hf_detail::Part part = hf_detail::Part::Lower;
  bool hit_any = hf_detail::roots(d, r, f.water_level, false, t0, t1, [&](double t, hf_detail::Part p) {
    if (!ray_t.surrounds(t)) return false;
    found = t;
    part = p;
    return true;
  });
  if (!hit_any) return false;
  height_field_hit_at(f, ray, found, part, hit);
  return true;
}

// One crossing of the solid's boundary: its t and what it is on (a wall of the column under
// the surface, the surface's triangles, or the water plane).
struct HeightFieldCrossing {
  double t;
  hf_detail::Part part;
  int wall;  // 0: not a wall; else 1 + axis (0 or 2) of the wall's normal, signed by side
};

// Every crossing of the solid's boundary along the whole line, ascending (at most max_out; the
// parity of the rest is lost, so the caller keeps the count even), and whether the line starts
// inside (only a line going up the column does).
inline int height_field_crossings(const HeightField& f, const Ray& ray, HeightFieldCrossing* out, int max_out,
                                  bool& inside_at_start) {
  inside_at_start = false;
  if (!f.data || max_out <= 0) return 0;
  const HeightFieldData& d = *f.data;
  double t0, t1;
  if (!hf_detail::column_span(ray, t0, t1)) return 0;
  const hf_detail::GridRay r = hf_detail::grid_ray(d, ray);
  const double water = f.water_level;
  auto level_at = [&](double t) {
    return std::max(hf_detail::surface_at(d, r.ox + r.dx * t, r.oz + r.dz * t), water);
  };
  if (!std::isfinite(t0) || !std::isfinite(t1)) {
    // Parallel to y inside the column: one crossing, at the level, entering from below.
    if (ray.direction.y == 0.0) return 0;
    double level = level_at(0.0);
    out[0] = {(level - ray.origin.y) / ray.direction.y, hf_detail::Part::Lower, 0};
    // The triangle it lands on.
    double s = r.ox - std::clamp(std::floor(r.ox), 0.0, d.nx - 2.0), u = r.oz - std::clamp(std::floor(r.oz), 0.0, d.nz - 2.0);
    if (level == water && hf_detail::surface_at(d, r.ox, r.oz) < water) out[0].part = hf_detail::Part::Water;
    else if (s + u >= 1.0) out[0].part = hf_detail::Part::Upper;
    inside_at_start = ray.direction.y > 0.0;
    return 1;
  }
  int n = 0;
  // The wall where the line enters the column, when it enters below the level.
  auto wall_at = [&](double t, bool entering) {
    Vec3 p = ray.at(t);
    if (!(p.y < level_at(t))) return false;
    // The wall's axis: the one whose slab bound this t is.
    int axis = 0;
    double best = std::numeric_limits<double>::infinity();
    for (int a : {0, 2}) {
      double dd = ray.direction[a];
      if (dd == 0.0) continue;
      double tw = ((dd > 0.0) == entering ? 0.0 - ray.origin[a] : 1.0 - ray.origin[a]) / dd;
      if (std::abs(tw - t) < best) best = std::abs(tw - t), axis = a;
    }
    bool low_side = (ray.direction[axis] > 0.0) == entering;  // the wall at 0 along this axis
    out[n++] = {t, hf_detail::Part::Water, low_side ? -(1 + axis) : 1 + axis};
    return true;
  };
  if (t0 < t1) wall_at(t0, true);
  hf_detail::roots(d, r, water, true, t0, t1, [&](double t, hf_detail::Part p) {
    if (n >= max_out) return true;
    if (t > t0) out[n++] = {t, p, 0};
    return n >= max_out;
  });
  if (n < max_out) wall_at(t1, false);
  return n;
}

inline void height_field_crossing_hit(const HeightField& f, const Ray& ray, const HeightFieldCrossing& c, SurfaceHit& hit) {
  height_field_hit_at(f, ray, c.t, c.part, hit);
  if (c.wall != 0) {
    Vec3 n(0.0);
    int axis = std::abs(c.wall) - 1;
    n[axis] = c.wall > 0 ? 1.0 : -1.0;
    hit.normal = hit.shading_normal = n;
  }
}

}  // namespace rts::render
