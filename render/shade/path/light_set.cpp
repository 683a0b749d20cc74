#include "render/shade/path/light_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/geometry/tolerances.hpp"
#include "render/sample/camera.hpp"
#include "render/shade/path/spherical_rect.hpp"

namespace rts::render::path {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Rgb to_rgb(const Color& c) { return Rgb(c.r, c.g, c.b); }
// Rec. 709 luminance: what the sky's importance grid and the lights' power ranking weigh.
double luminance(const Rgb& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
bool is_black(const Rgb& c) { return !(std::max({c.x, c.y, c.z}) > 0.0); }

Vec3 point_to_world(const InstanceMaps* xf, const Vec3& p) {
  return xf ? Vec3(xf->to_world * glm::dvec4(p, 1.0)) : p;
}
Vec3 vector_to_world(const InstanceMaps* xf, const Vec3& v) { return xf ? xf->vector_to_world * v : v; }

// A mesh whose vertices carry uvs (one per position), as its hits read them.
bool has_vertex_uvs(const MeshData& m) { return !m.uvs.empty() && m.uvs.size() == m.positions.size(); }

// A transform that keeps spheres spheres (rotation, mirror, uniform scale, translation):
// its scale factor, or 0 when it stretches some axis more than another.
double uniform_scale(const InstanceMaps* xf) {
  if (!xf) return 1.0;
  const glm::dmat3& m = xf->vector_to_world;
  double s0 = glm::length(m[0]), s1 = glm::length(m[1]), s2 = glm::length(m[2]);
  double tol = 1e-9 * std::max({s0, s1, s2});
  if (std::abs(s0 - s1) > tol || std::abs(s0 - s2) > tol) return 0.0;
  if (std::abs(glm::dot(m[0], m[1])) > tol * s0 || std::abs(glm::dot(m[0], m[2])) > tol * s0 ||
      std::abs(glm::dot(m[1], m[2])) > tol * s0)
    return 0.0;
  return s0;
}

// A rectangle is sampled by solid angle only from points closer than this many diagonals to
// its centre, where area sampling's 1/r^2 spikes: a floor 0.05 below a 1 x 0.6 light shows a
// third of the standard error. Farther away it does not pay (measured on the Cycles Cornell
// box, bench/cycles, docs/path-tracing.md): solid-angle sampling everywhere cut the RMSE by 1%
// for 27% more CPU time (four asin, a sin and a cos per sample, and again for the MIS weight
// of each ray that hits the light), out to 2 diagonals by 1% for 10%; at 1 the box's time and
// error are unchanged.
constexpr double kSolidAngleDiagonals = 1.0;

// Does `point` sample the rectangle corner + [0,1] e1 + [0,1] e2 by solid angle?
bool near_rectangle(const Vec3& point, const Vec3& corner, const Vec3& e1, const Vec3& e2) {
  const Vec3 d = corner + 0.5 * (e1 + e2) - point;
  const double reach = kSolidAngleDiagonals * kSolidAngleDiagonals * glm::dot(e1 + e2, e1 + e2);
  return glm::dot(d, d) < reach;
}

// The lights in the scene are picked by power with this share picked uniformly: power alone
// starves a faint light that is the only one a corner sees, where the uniform share caps the
// loss at 1 / share of uniform picking's samples. On bench/path/lamps.rts (five lights, 32
// spp) the RMSE is 0.069 picked uniformly, 0.060 by power alone, 0.052 with a share of 0.1
// and 0.050 with 0.25 (docs/path-tracing.md).
constexpr double kUniformPickShare = 0.25;

}  // namespace

LightSet::LightSet(const World& world, const SceneDesc& scene, const std::vector<CompiledLight>& lights,
                   const std::vector<CompiledTexture>& textures) {
  emitter_of_.assign(world.instance_count(), kNoEntry);
  for (uint32_t i = 0; i < world.instance_count(); ++i) {
    MaterialId id = world.instance(i).material;
    if (id >= scene.materials.size()) continue;
    const MaterialDesc& m = scene.materials[id];
    if (m.emission_texture != kNoId) {
      // Varies over the surface: sampled when the texture reads the object point, or reads uv
      // on a quad, a sphere or a mesh with uvs (whose uv a sampled point gives back); other
      // uv-mapped emitters are found by BSDF rays alone, and so is any CSG part.
      const bool known = m.emission_texture < textures.size();
      const bool by_uv = known && textures[m.emission_texture].uses_uv();
      const Instance& inst = world.instance(i);
      const bool mesh_uvs = inst.kind == kPrimKind<MeshRef> && inst.index < scene.meshes.size() &&
                            scene.meshes[inst.index] && has_vertex_uvs(*scene.meshes[inst.index]);
      const bool uv_known = inst.kind == kPrimKind<Quad> || inst.kind == kPrimKind<Sphere> || mesh_uvs;
      if (!known || (by_uv && !uv_known) || i >= world.instance_count() - world.csg_part_count()) {
        ++unsampled_emitters_;
        continue;
      }
      const std::size_t before = entries_.size();
      add_emitter(world, scene, i, Rgb(1.0), by_uv);
      if (entries_.size() == before) continue;
      Entry& e = entries_.back();
      e.texture = &textures[m.emission_texture];
      e.texture_uv = by_uv;
      if (const std::optional<InstanceMaps> maps = world.transform(i)) {
        e.to_object = maps->to_object;
        e.transformed = true;
      }
      // For picking by power: the texture at the emitter's reference point (a corner or its
      // centre; uv's centre), a rough guess; any guess keeps the estimate unbiased.
      TexturePoint p;
      p.object_point = e.transformed ? Vec3(e.to_object * glm::dvec4(e.p0, 1.0)) : e.p0;
      p.uv = glm::dvec2(0.5);
      p.has_uv = by_uv;
      e.radiance = glm::max(to_rgb(e.texture->eval(p)), Rgb(0.0));
      continue;
    }
    Rgb le = to_rgb(m.emission);
    // A CSG part shows only where its block's result does: sampling its whole surface would
    // light from cut-away parts, so it is found by BSDF rays only.
    if (!is_black(le) && i >= world.instance_count() - world.csg_part_count()) {
      ++unsampled_emitters_;
      continue;
    }
    if (!is_black(le)) add_emitter(world, scene, i, le);
  }
  attenuation_falloff_ = scene.settings.light_falloff_attenuation;
  for (const CompiledLight& l : lights) {
    if (is_black(l.power)) continue;
    Entry e;
    switch (l.kind) {
      case LightKind::Point: e.type = Type::Point; break;
      case LightKind::Spot: e.type = Type::Spot; break;
      case LightKind::Directional: e.type = Type::Directional; break;
      case LightKind::Area: e.type = Type::AreaLight; break;
    }
    e.light = l;
    e.radiance = l.power;
    e.p0 = l.position;
    if (l.kind == LightKind::Area) {
      e.e1 = l.u;
      e.e2 = l.v;
      e.disc = l.disc;
      e.area = scaled_length(glm::cross(l.u, l.v)) * (l.disc ? kPi / 4.0 : 1.0);
      if (!(e.area > tol::kMinEmitterArea)) continue;   // a zero-size area light sends nothing
      e.radiance = glm::min(2.0 * l.power / e.area, Rgb(tol::kMaxRadiance));
      ++area_lights_;
    } else {
      ++delta_lights_;
    }
    entries_.push_back(e);
  }
  if (scene.settings.environment < textures.size()) {
    environment_ = &textures[scene.settings.environment];
    sky_distribution_.emplace([this](const Vec3& d) {
      return luminance(sky(d));
    });
  }
  background_ = to_rgb(scene.settings.background);
  if (environment_ || !is_black(background_)) {
    sky_ = static_cast<uint32_t>(entries_.size());
    Entry e;
    e.type = Type::Sky;
    entries_.push_back(e);
  }
  set_pick_probabilities();
}

void LightSet::set_pick_probabilities() {
  if (entries_.empty()) return;
  // Lights at a distance (directional, the sky) get their uniform share, 1/n each: their power
  // through the scene is not comparable with a lamp's, as how much of it enters the part
  // the camera sees depends on walls (a sun-lit house's rooms see their lamps only). The
  // lights in the scene share the rest by power (luminance, W up to a common factor) mixed
  // with kUniformPickShare: an open emitter sends pi A L from each side, a closed one from its
  // outside only; a point light 4 pi I, a spot over its cone, an area_light 4 pi I (radiance
  // 2 I / A, two-sided).
  auto distant = [](const Entry& e) { return e.type == Type::Directional || e.type == Type::Sky; };
  std::vector<double> power(entries_.size(), 0.0);
  double total = 0.0;
  std::size_t local = 0;
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    const Entry& e = entries_[k];
    double p = 0.0;
    switch (e.type) {
      case Type::Sphere:
      case Type::Box: p = kPi * e.area * luminance(e.radiance); break;
      case Type::Cone: p = (e.capped ? 1.0 : 2.0) * kPi * e.area * luminance(e.radiance); break;
      case Type::Quad:
      case Type::Triangle:
      case Type::Mesh:
      case Type::Disc:
      case Type::AreaLight: p = 2.0 * kPi * e.area * luminance(e.radiance); break;
      case Type::Point: p = 4.0 * kPi * luminance(e.radiance); break;
      case Type::Spot:
        p = 2.0 * kPi * (1.0 - 0.5 * (e.light.cos_inner + e.light.cos_outer)) * luminance(e.radiance);
        break;
      case Type::Directional:
      case Type::Sky: continue;
    }
    ++local;
    power[k] = std::isfinite(p) && p > 0.0 ? p : 0.0;
    total += power[k];
  }
  const double n = static_cast<double>(entries_.size());
  const double local_mass = static_cast<double>(local) / n;
  const double by_power = total > 0.0 && std::isfinite(total) ? 1.0 - kUniformPickShare : 0.0;
  double cdf = 0.0;
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    Entry& e = entries_[k];
    e.pick = distant(e) ? 1.0 / n
                        : local_mass * ((by_power > 0.0 ? by_power * power[k] / total : 0.0) +
                                        (1.0 - by_power) / static_cast<double>(local));
    cdf += e.pick;
    e.pick_cdf = cdf;
  }
  entries_.back().pick_cdf = 1.0;   // u_pick < 1 always lands on a light
}

std::vector<double> LightSet::pick_probabilities() const {
  std::vector<double> out;
  for (const Entry& e : entries_) out.push_back(e.pick);
  return out;
}

void LightSet::add_emitter(const World& world, const SceneDesc& scene, uint32_t instance, const Rgb& le,
                           bool uvs) {
  const Instance& inst = world.instance(instance);
  const std::optional<InstanceMaps> maps = world.transform(instance);
  const InstanceMaps* xf = maps ? &*maps : nullptr;
  Entry e;
  e.radiance = le;
  if (inst.kind == kPrimKind<Sphere>) {
    double s = uniform_scale(xf);
    const Sphere& sp = world.shape<Sphere>(inst.index);
    e.type = Type::Sphere;
    e.p0 = point_to_world(xf, sp.center);
    e.radius = s * sp.radius;
    e.area = 4.0 * kPi * e.radius * e.radius;
    if (s == 0.0) e.area = 0.0;  // an ellipsoid: not sampled
  } else if (inst.kind == kPrimKind<Quad>) {
    const Quad& q = world.shape<Quad>(inst.index);
    e.type = Type::Quad;
    e.p0 = point_to_world(xf, q.corner);
    e.e1 = vector_to_world(xf, q.edge_u);
    e.e2 = vector_to_world(xf, q.edge_v);
    e.area = scaled_length(glm::cross(e.e1, e.e2));
    e.rect = std::abs(glm::dot(e.e1, e.e2)) <= tol::kRectangleCosine * glm::length(e.e1) * glm::length(e.e2);
  } else if (inst.kind == kPrimKind<Triangle>) {
    const Triangle& t = world.shape<Triangle>(inst.index);
    e.type = Type::Triangle;
    e.p0 = point_to_world(xf, t.v0);
    e.e1 = point_to_world(xf, t.v1) - e.p0;
    e.e2 = point_to_world(xf, t.v2) - e.p0;
    e.area = 0.5 * scaled_length(glm::cross(e.e1, e.e2));
  } else if (inst.kind == kPrimKind<MeshRef>) {
    const MeshData& mesh = *scene.meshes[inst.index];
    e.type = Type::Mesh;
    e.first = static_cast<uint32_t>(tris_.size());
    e.uv_first = static_cast<uint32_t>(tri_uvs_.size());
    uvs = uvs && has_vertex_uvs(mesh);
    double total = 0.0;
    for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
      Vec3 v[3];
      for (int j = 0; j < 3; ++j) v[j] = point_to_world(xf, mesh.origin + Vec3(mesh.positions[mesh.indices[k + j]]));
      Tri t{v[0], v[1] - v[0], v[2] - v[0], 0.0};
      if (uvs) tri_uvs_.push_back({mesh.uvs[mesh.indices[k]], mesh.uvs[mesh.indices[k + 1]], mesh.uvs[mesh.indices[k + 2]]});
      double a = 0.5 * scaled_length(glm::cross(t.e1, t.e2));
      if (std::isfinite(a)) total += a;
      t.cdf = total;
      tris_.push_back(t);
    }
    e.count = static_cast<uint32_t>(tris_.size()) - e.first;
    e.area = total;
  } else if (inst.kind == kPrimKind<Disc>) {
    // Two radii of the disc, mapped to the world: any linear transform keeps it a (possibly
    // elliptic) annulus whose points stay uniform by area.
    const Disc& d = world.shape<Disc>(inst.index);
    Frame f(d.normal);
    e.type = Type::Disc;
    e.p0 = point_to_world(xf, d.center);
    e.e1 = vector_to_world(xf, d.radius * f.t);
    e.e2 = vector_to_world(xf, d.radius * f.b);
    e.radius = d.inner_radius / d.radius;
    e.area = kPi * (1.0 - e.radius * e.radius) * scaled_length(glm::cross(e.e1, e.e2));
  } else if (inst.kind == kPrimKind<Box>) {
    const Box& b = world.shape<Box>(inst.index);
    const Vec3 size = b.max - b.min;
    e.type = Type::Box;
    e.p0 = point_to_world(xf, b.min);
    e.e1 = vector_to_world(xf, Vec3(size.x, 0.0, 0.0));
    e.e2 = vector_to_world(xf, Vec3(0.0, size.y, 0.0));
    e.e3 = vector_to_world(xf, Vec3(0.0, 0.0, size.z));
    e.area = 2.0 * (scaled_length(glm::cross(e.e1, e.e2)) + scaled_length(glm::cross(e.e2, e.e3)) +
                    scaled_length(glm::cross(e.e3, e.e1)));
  } else if (inst.kind == kPrimKind<Cylinder> || inst.kind == kPrimKind<Cone>) {
    // The side and, when capped, the two end discs, uniform by area; a cylinder is a cone of
    // equal radii. Only under a transform that keeps it circular (as spheres): a stretched one
    // is not sampled.
    Vec3 from, to;
    double r0, r1;
    bool capped;
    if (inst.kind == kPrimKind<Cylinder>) {
      const Cylinder& c = world.shape<Cylinder>(inst.index);
      from = c.from, to = c.to, r0 = r1 = std::abs(c.radius), capped = c.capped;
    } else {
      const Cone& c = world.shape<Cone>(inst.index);
      from = c.from, to = c.to, r0 = std::abs(c.radius_from), r1 = std::abs(c.radius_to), capped = c.capped;
    }
    const double s = uniform_scale(xf);
    const Vec3 axis = to - from;
    const double height = glm::length(axis);
    if (s > 0.0 && height > 0.0 && r0 + r1 > 0.0) {
      Frame f(axis / height);
      e.type = Type::Cone;
      e.p0 = point_to_world(xf, from);
      e.e1 = vector_to_world(xf, axis);
      e.e2 = vector_to_world(xf, f.t);
      e.e3 = vector_to_world(xf, f.b);
      e.radius = r0;
      e.radius_end = r1;
      e.capped = capped;
      const double side = kPi * (r0 + r1) * std::sqrt(height * height + (r1 - r0) * (r1 - r0));
      e.area = s * s * (side + (capped ? kPi * (r0 * r0 + r1 * r1) : 0.0));
    }
  }
  // Planes, tori...: their emission is found by BSDF rays only.
  if (!(e.area > tol::kMinEmitterArea) || !std::isfinite(e.area)) {
    ++unsampled_emitters_;
    return;
  }
  emitter_of_[instance] = static_cast<uint32_t>(entries_.size());
  entries_.push_back(e);
  ++shape_emitters_;
}

bool LightSet::to_solid_angle(const Vec3& point, const Vec3& on_light, const Vec3& normal, double area_pdf,
                              LightSample& out) const {
  Vec3 d = on_light - point;
  double dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0) || !std::isfinite(dist2)) return false;
  double dist = std::sqrt(dist2);
  out.wi = d / dist;
  double cos_l = std::abs(glm::dot(normal, out.wi));
  if (cos_l < tol::kGrazingCosine) return false;
  out.distance = dist;
  out.pdf = area_pdf * dist2 / cos_l;
  return std::isfinite(out.pdf) && out.pdf > 0.0;
}

bool LightSet::sample(const Vec3& point, double u_pick, glm::dvec2 u, LightSample& out) const {
  if (entries_.empty()) return false;
  // The first light whose cumulative probability passes u_pick (a handful of lights: a linear
  // walk beats a binary search's branches; many emitters: binary search).
  auto it = entries_.size() <= 8
                ? std::find_if(entries_.begin(), entries_.end(), [&](const Entry& x) { return u_pick < x.pick_cdf; })
                : std::upper_bound(entries_.begin(), entries_.end(), u_pick,
                                   [](double v, const Entry& x) { return v < x.pick_cdf; });
  const Entry& e = it == entries_.end() ? entries_.back() : *it;
  glm::dvec2 mesh_uv(0.0);
  if (!sample_entry(e, point, u, out, &mesh_uv)) return false;
  if (e.texture) {
    // Textured emission: the texture at the sampled point, in the object's space and with its
    // uv, as a ray that hits the point reads it.
    const Vec3 on = point + out.distance * out.wi;
    TexturePoint p;
    p.object_point = e.transformed ? Vec3(e.to_object * glm::dvec4(on, 1.0)) : on;
    if (e.texture_uv) {
      p.uv = e.type == Type::Mesh ? mesh_uv : emitter_uv(e, on, p.object_point);
      p.has_uv = true;
    }
    out.radiance = glm::min(to_rgb(e.texture->eval(p)), Rgb(tol::kMaxRadiance));
  }
  return true;
}

glm::dvec2 LightSet::emitter_uv(const Entry& e, const Vec3& on, const Vec3& object_point) {
  if (e.type == Type::Sphere) {
    // As World::surface_uv: the direction from the centre, in the object's space.
    const Vec3 centre = e.transformed ? Vec3(e.to_object * glm::dvec4(e.p0, 1.0)) : e.p0;
    return sphere_uv(glm::normalize(object_point - centre));
  }
  // A quad: (s, t) of on = p0 + s e1 + t e2, by the dual basis, as the quad's own test finds it.
  const Vec3 n = glm::cross(e.e1, e.e2);
  const double n2 = glm::dot(n, n);
  const Vec3 d = on - e.p0;
  return {glm::dot(d, glm::cross(e.e2, n)) / n2, glm::dot(d, glm::cross(n, e.e1)) / n2};
}

bool LightSet::sample_entry(const Entry& e, const Vec3& point, glm::dvec2 u, LightSample& out,
                            glm::dvec2* uv) const {
  out.delta = false;
  switch (e.type) {
    case Type::Point:
    case Type::Spot: {
      Vec3 d = e.p0 - point;
      double dist2 = glm::dot(d, d);
      if (!(dist2 > 0.0) || !std::isfinite(dist2)) return false;
      out.distance = std::sqrt(dist2);
      out.wi = d / out.distance;
      double spot = e.type == Type::Spot ? spot_factor(e.light, -out.wi) : 1.0;
      const double falloff = attenuation_falloff_ ? attenuation_factor(e.light.attenuation, out.distance,
                                                                       e.light.attenuation_clamp)
                                                  : 1.0 / dist2;
      out.radiance = glm::min(e.radiance * (spot * falloff), Rgb(tol::kMaxRadiance));
      out.pdf = e.pick;
      out.delta = true;
      return spot > 0.0;
    }
    case Type::Directional:
      out.wi = -e.light.direction;
      out.distance = kInf;
      out.radiance = e.radiance;
      out.pdf = e.pick;
      out.delta = true;
      return true;
    case Type::AreaLight: {
      glm::dvec2 p = e.disc ? 0.5 * concentric_disc(u) : u - 0.5;
      Vec3 on = e.p0 + p.x * e.e1 + p.y * e.e2;
      if (attenuation_falloff_) {
        // Whitted's area light: each point of it a point light of the whole power, attenuated.
        const Vec3 d = on - point;
        const double dist = glm::length(d);
        if (!(dist > 0.0) || !std::isfinite(dist)) return false;
        out.wi = d / dist;
        out.distance = dist;
        out.radiance = glm::min(
            e.light.power * attenuation_factor(e.light.attenuation, dist, e.light.attenuation_clamp),
            Rgb(tol::kMaxRadiance));
        if (e.light.area_spot) out.radiance *= area_spot_factor(e.light, point);
        out.pdf = e.pick;
        out.delta = true;
        return true;
      }
      if (!to_solid_angle(point, on, unit_vector(glm::cross(e.e1, e.e2)), e.pick / e.area, out)) return false;
      out.radiance = e.light.area_spot ? e.radiance * area_spot_factor(e.light, point) : e.radiance;
      out.delta = true;  // no ray can hit it: sampling is its only strategy
      return true;
    }
    case Type::Quad: {
      if (e.rect && near_rectangle(point, e.p0, e.e1, e.e2)) {
        // By solid angle, unless the point is in the light's plane (a point of the light
        // itself, or grazing): area sampling's grazing test then finds no light there.
        SphericalRect sr(point, e.p0, e.e1, e.e2);
        if (sr.height_ratio() > tol::kGrazingCosine && sr.solid_angle() >= tol::kMinSphericalRectAngle) {
          Vec3 d = sr.sample(u) - point;
          double dist = glm::length(d);
          if (!(dist > 0.0) || !std::isfinite(dist)) return false;
          out.wi = d / dist;
          out.distance = dist;
          out.pdf = e.pick / sr.solid_angle();
          out.radiance = e.radiance;
          return std::isfinite(out.pdf);
        }
      }
      Vec3 on = e.p0 + u.x * e.e1 + u.y * e.e2;
      if (!to_solid_angle(point, on, unit_vector(glm::cross(e.e1, e.e2)), e.pick / e.area, out)) return false;
      out.radiance = e.radiance;
      return true;
    }
    case Type::Triangle: {
      glm::dvec2 b = uniform_triangle(u);
      Vec3 on = e.p0 + b.x * e.e1 + b.y * e.e2;
      if (!to_solid_angle(point, on, unit_vector(glm::cross(e.e1, e.e2)), e.pick / e.area, out)) return false;
      out.radiance = e.radiance;
      return true;
    }
    case Type::Mesh: {
      // A triangle by area (binary search of the cumulative areas), then a point on it; u.x
      // is reused within the chosen triangle's share so the pair stays uniform.
      double target = u.x * e.area;
      auto begin = tris_.begin() + e.first, end = begin + e.count;
      auto it = std::lower_bound(begin, end, target, [](const Tri& t, double v) { return t.cdf < v; });
      if (it == end) it = end - 1;
      double lo = it == begin ? 0.0 : (it - 1)->cdf;
      double share = it->cdf - lo;
      if (!(share > 0.0)) return false;
      glm::dvec2 b = uniform_triangle({std::clamp((target - lo) / share, 0.0, 1.0), u.y});
      Vec3 on = it->p0 + b.x * it->e1 + b.y * it->e2;
      // The vertices' uvs at (b0, b.x, b.y), as the mesh's hit interpolates them.
      if (uv && e.texture_uv) {
        const TriUv& w = tri_uvs_[e.uv_first + static_cast<uint32_t>(it - begin)];
        *uv = (1.0 - b.x - b.y) * glm::dvec2(w.uv0) + b.x * glm::dvec2(w.uv1) + b.y * glm::dvec2(w.uv2);
      }
      Vec3 n = glm::cross(it->e1, it->e2);
      if (!to_solid_angle(point, on, unit_vector(n), e.pick / e.area, out)) return false;
      out.radiance = e.radiance;
      return true;
    }
    case Type::Disc: {
      // Uniform by area on the annulus inner..1 (in units of the outer radius).
      double r = std::sqrt(e.radius * e.radius + u.x * (1.0 - e.radius * e.radius));
      double phi = 2.0 * kPi * u.y;
      Vec3 on = e.p0 + r * std::cos(phi) * e.e1 + r * std::sin(phi) * e.e2;
      if (!to_solid_angle(point, on, unit_vector(glm::cross(e.e1, e.e2)), e.pick / e.area, out)) return false;
      out.radiance = e.radiance;
      return true;
    }
    case Type::Box: {
      // A face pair by its area, then one of the two faces and a point on it; u.x is reused
      // within its share. Faces turned away are occluded by the box itself.
      const Vec3 c12 = glm::cross(e.e1, e.e2), c23 = glm::cross(e.e2, e.e3), c31 = glm::cross(e.e3, e.e1);
      const double a12 = scaled_length(c12), a23 = scaled_length(c23), a31 = scaled_length(c31);
      double t = u.x * (a12 + a23 + a31);
      Vec3 a, b, n, far;
      if (t < a12) {
        a = e.e1, b = e.e2, n = c12, far = e.e3, t /= a12;
      } else if (t < a12 + a23) {
        a = e.e2, b = e.e3, n = c23, far = e.e1, t = (t - a12) / a23;
      } else {
        a = e.e3, b = e.e1, n = c31, far = e.e2, t = (t - a12 - a23) / a31;
      }
      t = std::clamp(t, 0.0, 1.0);
      Vec3 base = e.p0;
      if (t >= 0.5) {  // the opposite face
        base += far;
        t = 2.0 * t - 1.0;
      } else {
        t = 2.0 * t;
      }
      Vec3 on = base + t * a + u.y * b;
      if (!to_solid_angle(point, on, unit_vector(n), e.pick / e.area, out)) return false;
      out.radiance = e.radiance;
      return true;
    }
    case Type::Cone: {
      // Cones and cylinders (r0 = r1). Side: the height fraction has density in proportion to
      // the radius there, r0 + t (r1 - r0) (the inverse of its CDF, rationalised so r0 = r1
      // and r0 = 0 stay exact), the angle uniform; then an end disc, uniform by area; u.x is
      // reused within the chosen part's share. Lengths in units of |e2| (the scale).
      const double scale = glm::length(e.e2), r0 = e.radius, r1 = e.radius_end;
      const double axis_len = glm::length(e.e1), h = axis_len / scale;
      const double side = kPi * (r0 + r1) * std::sqrt(h * h + (r1 - r0) * (r1 - r0));
      double t = u.x * e.area / (scale * scale);
      Vec3 on, n;
      if (!e.capped || t < side) {
        const double f = std::clamp(t / side, 0.0, 1.0);
        const double height = f * (r0 + r1) / (r0 + std::sqrt(r0 * r0 + f * (r1 * r1 - r0 * r0)));
        const double radius = r0 + height * (r1 - r0);
        const double phi = 2.0 * kPi * u.y;
        const Vec3 radial = std::cos(phi) * e.e2 + std::sin(phi) * e.e3;   // |radial| = scale
        on = e.p0 + height * e.e1 + radius * radial;
        // Outward normal: the radial direction tilted by the slope, h along it, (r1 - r0) back
        // along the axis (both scaled alike, so the direction is the object's).
        n = (h * scale) * radial - (r1 - r0) * scale * scale * e.e1 / axis_len;
      } else {
        const double cap0 = kPi * r0 * r0;
        t -= side;
        Vec3 base = e.p0;
        double radius = r0;
        if (t >= cap0) {  // the end at `to`
          base += e.e1;
          radius = r1;
          t -= cap0;
        }
        const double cap = kPi * radius * radius;
        if (!(cap > 0.0)) return false;
        const double rho = radius * std::sqrt(std::clamp(t / cap, 0.0, 1.0));
        const double phi = 2.0 * kPi * u.y;
        on = base + rho * (std::cos(phi) * e.e2 + std::sin(phi) * e.e3);
        n = e.e1;
      }
      if (!to_solid_angle(point, on, glm::normalize(n), e.pick / e.area, out)) return false;
      out.radiance = e.radiance;
      return true;
    }
    case Type::Sphere: {
      Vec3 d = e.p0 - point;
      double dist2 = glm::dot(d, d), r2 = e.radius * e.radius;
      if (dist2 <= r2 * (1.0 + tol::kSphereConeMargin)) {
        // Inside (or on) the sphere: every direction sees it; sample its area.
        Vec3 n = uniform_sphere(u);
        if (!to_solid_angle(point, e.p0 + e.radius * n, n, e.pick / e.area, out)) return false;
        out.radiance = e.radiance;
        return true;
      }
      // Outside: uniformly within the cone the sphere subtends.
      double dist = std::sqrt(dist2);
      double sin2_max = r2 / dist2;
      double cos_max = std::sqrt(std::max(0.0, 1.0 - sin2_max));
      double one_minus = sin2_max / (1.0 + cos_max);   // 1 - cos_max without cancellation
      if (!(one_minus > 0.0)) return false;
      double cos_t = 1.0 - u.x * one_minus;
      double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
      double phi = 2.0 * kPi * u.y;
      Frame f(d / dist);
      out.wi = glm::normalize(f.to_world(Vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t)));
      double b = glm::dot(d, out.wi);
      double disc = r2 - (dist2 - b * b);
      out.distance = b - std::sqrt(std::max(0.0, disc));
      out.pdf = e.pick / (2.0 * kPi * one_minus);
      out.radiance = e.radiance;
      return std::isfinite(out.pdf) && out.distance > 0.0;
    }
    case Type::Sky: {
      double pdf = 1.0 / (4.0 * kPi);
      out.wi = sky_distribution_ ? sky_distribution_->sample(u, pdf) : uniform_sphere(u);
      out.distance = kInf;
      out.radiance = sky(out.wi);
      out.pdf = e.pick * pdf;
      return out.pdf > 0.0 && std::isfinite(out.pdf);
    }
  }
  return false;
}

double LightSet::pdf_hit(const Vec3& from, const WorldHit& hit) const {
  if (!sampled(hit.instance)) return 0.0;
  const Entry& e = entries_[emitter_of_[hit.instance]];
  Vec3 d = hit.point - from;
  double dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0)) return 0.0;
  if (e.type == Type::Sphere) {
    Vec3 c = e.p0 - from;
    double c2 = glm::dot(c, c), r2 = e.radius * e.radius;
    if (c2 > r2 * (1.0 + tol::kSphereConeMargin)) {
      double sin2_max = r2 / c2;
      double one_minus = sin2_max / (1.0 + std::sqrt(std::max(0.0, 1.0 - sin2_max)));
      return one_minus > 0.0 ? e.pick / (2.0 * kPi * one_minus) : 0.0;
    }
  }
  if (e.type == Type::Quad && e.rect && near_rectangle(from, e.p0, e.e1, e.e2)) {
    SphericalRect sr(from, e.p0, e.e1, e.e2);
    if (sr.height_ratio() > tol::kGrazingCosine && sr.solid_angle() >= tol::kMinSphericalRectAngle)
      return e.pick / sr.solid_angle();
  }
  double cos_l = std::abs(glm::dot(hit.normal, d)) / std::sqrt(dist2);
  if (cos_l < tol::kGrazingCosine) return 0.0;
  double pdf = e.pick / e.area * dist2 / cos_l;
  return std::isfinite(pdf) ? pdf : 0.0;
}

Rgb LightSet::sky(const Vec3& direction) const {
  if (environment_) return to_rgb(environment_->eval_direction(direction));
  return background_;
}

}  // namespace rts::render::path
