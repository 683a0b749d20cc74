// Every light the path tracer samples by next-event estimation, in physical units
// (docs/path-tracing.md):
//   emissive shapes  emitted radiance (two-sided); rectangles and spheres sampled by solid
//                    angle (spheres by area from inside), other quads, triangles, meshes,
//                    discs (annuli) and boxes by area (a box: a face by its area); textured
//                    emission that reads the object point is read at the sampled point;
//   point, spot      radiant intensity (W/sr), inverse-square falloff (spot: its cone factor);
//   directional      irradiance (W/m^2) on a surface facing it;
//   area_light       a two-sided emitter of the same total power as a point light of its
//                    intensity: radiance 2 I / area (no geometry: it is reached by sampling only);
//   environment      sky radiance: the environment map (importance-sampled by its luminance,
//                    SkyDistribution), else a non-black background colour (uniform).
// One light is picked per shading point: directional light and the sky each 1/n, the lights in
// the scene by their power (luminance) with a uniform share mixed in (light_set.cpp,
// kUniformPickShare); a mesh counts as one light, its triangles picked by area.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "render/accel/world.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/path/sky_distribution.hpp"
#include "render/shade/path/warp.hpp"
#include "render/shade/texture.hpp"

namespace rts::render::path {

using Rgb = glm::dvec3;

struct LightSample {
  Vec3 wi{0.0};           // unit, from the shading point towards the light
  double distance = 0.0;  // to the sampled point; infinity for directional and sky light
  Rgb radiance{0.0};      // arriving radiance (delta lights: irradiance at normal incidence)
  double pdf = 0.0;       // solid angle density, light choice included (delta: the choice alone)
  bool delta = false;     // no other strategy can find this light: no MIS weight
};

class LightSet {
 public:
  LightSet(const World& world, const SceneDesc& scene, const std::vector<CompiledLight>& lights,
           const std::vector<CompiledTexture>& textures);

  bool empty() const { return entries_.empty(); }
  // One light: sample() ignores u_pick.
  bool single() const { return entries_.size() == 1; }
  bool sample(const Vec3& point, double u_pick, glm::dvec2 u, LightSample& out) const;

  // Does NEE sample this instance's emission? (Else a ray that hits it counts all of it.)
  bool sampled(uint32_t instance) const {
    return instance < emitter_of_.size() && emitter_of_[instance] != kNoEntry;
  }
  // The solid-angle density with which sample() from `from` picks the point `hit` of a
  // sampled emitter instance (for the MIS weight of a BSDF ray that hit it).
  double pdf_hit(const Vec3& from, const WorldHit& hit) const;

  // Sky radiance along a direction leaving the scene, and the density NEE gives it.
  bool has_sky() const { return sky_ != kNoEntry; }
  Rgb sky(const Vec3& direction) const;
  double pdf_sky(const Vec3& direction) const {
    return entries_[sky_].pick * (sky_distribution_ ? sky_distribution_->pdf(direction) : 1.0 / (4.0 * kPi));
  }

  // What the set holds, for --stats.
  bool has_shape_emitters() const { return shape_emitters_ > 0; }
  bool has_delta_lights() const { return delta_lights_ > 0; }
  bool has_area_lights() const { return area_lights_ > 0; }
  std::size_t unsampled_emitters() const { return unsampled_emitters_; }
  // Each light's probability of being picked, in the set's order: sampled emitters (by
  // instance), then the scene's lights, then the sky.
  std::vector<double> pick_probabilities() const;

 private:
  enum class Type : uint8_t { Sphere, Quad, Triangle, Mesh, Disc, Box, Cone, Point, Spot, Directional, AreaLight, Sky };
  struct Entry {
    Type type = Type::Point;
    Rgb radiance{0.0};   // emitters: Le; point/spot: intensity; directional: irradiance
    Vec3 p0{0.0}, e1{0.0}, e2{0.0};  // corner (centre for spheres, discs and area lights) and edges
    Vec3 e3{0.0};                    // boxes: the third edge; cones (cylinders too): with e2 the radius' frame
    double radius = 0.0;             // spheres; discs: inner radius / outer radius; cones: at p0
    double radius_end = 0.0;         // cones: the radius at p0 + e1 (both in units of |e2|)
    double area = 0.0;
    bool disc = false;               // area_light: the ellipse inscribed in e1, e2
    bool rect = false;               // quad: e1 and e2 orthogonal, sampled by solid angle
    bool capped = false;             // cones: the two end discs emit too
    uint32_t first = 0, count = 0;   // meshes: their triangles in tris_
    uint32_t uv_first = 0;           // uv-textured meshes: their triangles' uvs in tri_uvs_
    CompiledLight light;             // point, spot
    const CompiledTexture* texture = nullptr;   // textured emission: read at the sampled point
    bool texture_uv = false;                    // ... by its uv (quads, spheres, meshes with uvs)
    Mat4 to_object{1.0};                        // its instance's world -> object ...
    bool transformed = false;                   // ... when it has one (else the identity)
    double pick = 0.0;               // probability that sample() picks this light
    double pick_cdf = 0.0;           // sum of pick up to and including this light
  };
  struct Tri {
    Vec3 p0, e1, e2;
    double cdf;   // cumulative area within its mesh, up to and including this triangle
  };
  struct TriUv {
    glm::vec2 uv0, uv1, uv2;   // a triangle's vertices' uvs, kept for uv-textured emission only
  };
  static constexpr uint32_t kNoEntry = 0xffffffffu;

  // `uvs`: a mesh keeps its triangles' uvs (its emission is an image mapped by uv).
  void add_emitter(const World& world, const SceneDesc& scene, uint32_t instance, const Rgb& le,
                   bool uvs = false);
  // The uv of a quad's or a sphere's point `on` (world) / `object_point`, as its hit gives it.
  static glm::dvec2 emitter_uv(const Entry& e, const Vec3& on, const Vec3& object_point);
  // A point of entry `e` seen from `point` (its radiance untextured); `uv`, when given and the
  // entry is a mesh, gets the point's uv.
  bool sample_entry(const Entry& e, const Vec3& point, glm::dvec2 u, LightSample& out,
                    glm::dvec2* uv = nullptr) const;
  // Sets each entry's pick probability: distant lights 1/n, the others by power.
  void set_pick_probabilities();
  // Area-sampled point and normal to a solid-angle sample seen from `point`.
  bool to_solid_angle(const Vec3& point, const Vec3& on_light, const Vec3& normal, double area_pdf,
                      LightSample& out) const;

  std::vector<Entry> entries_;
  std::vector<Tri> tris_;
  std::vector<TriUv> tri_uvs_;         // beside tris_ from a uv-textured mesh's uv_first
  std::vector<uint32_t> emitter_of_;   // by instance: its entry, or kNoEntry
  uint32_t sky_ = kNoEntry;
  const CompiledTexture* environment_ = nullptr;
  std::optional<SkyDistribution> sky_distribution_;   // environment maps only
  Rgb background_{0.0};
  std::size_t shape_emitters_ = 0, delta_lights_ = 0, area_lights_ = 0, unsampled_emitters_ = 0;
  bool attenuation_falloff_ = false;  // settings.light_falloff_attenuation: Whitted's falloff for lights
};

}  // namespace rts::render::path
