#include "render/shade/medium.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/geometry/tolerances.hpp"
#include "render/shade/material.hpp"
#include "render/shade/path/warp.hpp"

namespace rts::render {
namespace {

Rgb rgb_of(const Color& c) { return Rgb(c.r, c.g, c.b); }
double max_of(const Rgb& c) { return std::max({c.x, c.y, c.z}); }
constexpr double kInf = std::numeric_limits<double>::infinity();

// |g| below this samples the isotropic phase directly: the HG inversion divides by g.
constexpr double kIsotropicG = 1e-4;

}  // namespace

double hg_phase(double cos_theta, double g) {
  const double denom = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * path::kPi * denom * std::sqrt(std::max(denom, 0.0)));
}

Vec3 hg_sample(const Vec3& d_in, double g, glm::dvec2 u, double& pdf) {
  double cos_theta;
  if (std::abs(g) < kIsotropicG) {
    cos_theta = 1.0 - 2.0 * u.x;
  } else {
    // The inverse of HG's distribution in cos (pbrt-v4's SampleHenyeyGreenstein, written for
    // the propagation direction).
    const double sq = (1.0 - g * g) / (1.0 + g - 2.0 * g * u.x);
    cos_theta = std::clamp((1.0 + g * g - sq * sq) / (2.0 * g), -1.0, 1.0);
  }
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const double phi = 2.0 * path::kPi * u.y;
  const path::Frame frame(d_in);
  pdf = hg_phase(cos_theta, g);
  return glm::normalize(frame.to_world(Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta)));
}

CompiledMedium::CompiledMedium(const MediumDesc& desc, const CompiledTexture* density)
    : sigma_a_(rgb_of(desc.absorption)), sigma_s_(rgb_of(desc.scattering)), emission_(rgb_of(desc.emission)),
      g_(desc.eccentricity), fade_distance_(desc.fade_distance), fade_power_(desc.fade_power),
      fade_color_(rgb_of(desc.fade_color)), density_(density) {
  sigma_t_ = sigma_a_ + sigma_s_;
  majorant_ = max_of(sigma_t_);
  scatters_ = max_of(sigma_s_) > 0.0;
  emits_ = max_of(emission_) > 0.0;
}

double CompiledMedium::density(const Vec3& p) const {
  if (!density_) return 1.0;
  TexturePoint tp;
  tp.object_point = p;
  const Color c = density_->eval(tp);
  const double d = (c.r + c.g + c.b) / 3.0;
  return d > 0.0 ? std::min(d, 1.0) : 0.0;  // NaN reads as empty
}

Rgb CompiledMedium::absorbed(double length) const {
  Rgb t;
  for (int c = 0; c < 3; ++c) t[c] = sigma_t_[c] > 0.0 ? std::exp(-sigma_t_[c] * length) : 1.0;
  return t;
}

Rgb CompiledMedium::transmittance(double length) const {
  return fades() ? absorbed(length) * fade(length) : absorbed(length);
}

Rgb CompiledMedium::fade(double length) const {
  if (!fades()) return Rgb(1.0);
  const double x = length / fade_distance_;  // infinite for a ray that never leaves: nothing passes
  Rgb f;
  for (int c = 0; c < 3; ++c) {
    const double keep = fade_color_[c];
    f[c] = fade_power_ >= 1000.0 ? (keep < 1.0 ? std::exp(-(1.0 - keep) * x) : 1.0)
                                 : keep + (1.0 - keep) / (1.0 + std::pow(x, fade_power_));
  }
  return f;
}

Rgb CompiledMedium::emitted(double length) const {
  Rgb e(0.0);
  for (int c = 0; c < 3; ++c) {
    if (!(emission_[c] > 0.0)) continue;
    // Saturated like every radiance: eps / sigma_t overflows for extreme coefficients.
    e[c] = std::min(sigma_t_[c] > 0.0 ? emission_[c] * (-std::expm1(-sigma_t_[c] * length) / sigma_t_[c])
                                      : emission_[c] * length,
                    tol::kMaxRadiance);
  }
  return e;
}

Rgb CompiledMedium::transmittance(const Vec3& origin, const Vec3& dir, double length, MediumRng& rng) const {
  if (homogeneous()) return transmittance(length);
  if (!(majorant_ > 0.0)) return Rgb(1.0);
  // Ratio tracking: each tentative collision keeps the null fraction of the light.
  Rgb t(1.0);
  double s = 0.0;
  for (int i = 0; i < tol::kMaxMediumCollisions; ++i) {
    s -= std::log1p(-rng.next()) / majorant_;
    if (s >= length) return t;
    t *= Rgb(majorant_) - density(origin + s * dir) * sigma_t_;
    t /= majorant_;
    // Russian roulette once little is left: unbiased, and it ends walks to infinity.
    if (max_of(t) < 0.1) {
      if (rng.next() < 0.5) return Rgb(0.0);
      t *= 2.0;
    }
  }
  return Rgb(0.0);
}

Rgb CompiledMedium::transmittance_marched(const Vec3& origin, const Vec3& dir, double length, int steps,
                                          bool shadow) const {
  // POV-Ray's shadow rays take no fade of power 0 (a constant half on camera and refracted
  // rays); measured against POV-Ray 3.7 (tests/golden/import/pov/fade.pov).
  if (homogeneous())
    return shadow && fades() && !(fade_power_ > 0.0) ? absorbed(length) : transmittance(length);
  if (!(majorant_ > 0.0)) return Rgb(1.0);
  const double reach = std::min(length, tol::kMediaMarchDepth / majorant_);
  const double ds = reach / steps;
  double depth = 0.0;  // the sum of densities times ds
  for (int i = 0; i < steps; ++i) depth += density(origin + (i + 0.5) * ds * dir) * ds;
  Rgb t;
  for (int c = 0; c < 3; ++c) t[c] = std::exp(-sigma_t_[c] * depth);
  return t;
}

bool CompiledMedium::free_flight(const Vec3& origin, const Vec3& dir, double length, MediumRng& rng, Rgb& beta,
                                 Rgb& radiance, double& t) const {
  if (homogeneous()) {
    // Emission in closed form (its integral over the segment, whatever happens on it).
    if (emits_) radiance += beta * emitted(length);
    if (!scatters_) {  // absorption alone: closed form, no noise
      beta *= transmittance(length);
      return false;
    }
    // Exact distance sampling, one channel's extinction picked at random and the three
    // densities averaged (one-sample MIS over the channels): no null collisions, however
    // different the channels are.
    const int c = std::min(2, static_cast<int>(rng.next() * 3.0));
    const double d = sigma_t_[c] > 0.0 ? -std::log1p(-rng.next()) / sigma_t_[c] : kInf;
    if (d < length) {
      const Rgb tr = transmittance(d);
      const double pdf = (sigma_t_.x * tr.x + sigma_t_.y * tr.y + sigma_t_.z * tr.z) / 3.0;
      if (!(pdf > 0.0)) {
        beta = Rgb(0.0);
        return false;
      }
      beta *= sigma_s_ * tr / pdf;
      t = d;
      return true;
    }
    const Rgb tr = transmittance(length);
    const double survive = (tr.x + tr.y + tr.z) / 3.0;  // the chance of reaching the end
    beta = survive > 0.0 ? beta * tr / survive : Rgb(0.0);
    return false;
  }
  // Null collisions against a majorant (any positive one is exact; an emitting medium without
  // extinction takes 1 per unit length).
  const double sbar = majorant_ > 0.0 ? majorant_ : 1.0;
  // Russian roulette once the null collisions have taken most of the weight (unbiased): a
  // dense patterned absorber then ends in a few dozen steps, not majorant x length of them.
  const double entry = max_of(beta);
  double s = 0.0;
  for (int i = 0; i < tol::kMaxMediumCollisions; ++i) {
    s -= std::log1p(-rng.next()) / sbar;
    if (s >= length) return false;
    const Vec3 p = origin + s * dir;
    const double rho = density(p);
    if (emits_) radiance += glm::min(beta * (rho / sbar) * emission_, Rgb(tol::kMaxRadiance));
    const Rgb scatter = rho * sigma_s_;
    const Rgb null = glm::max(Rgb(sbar) - rho * sigma_t_, 0.0);
    const double ps = max_of(scatter), pn = max_of(null);
    if (!(ps + pn > 0.0)) {  // all of it absorbed here
      beta = Rgb(0.0);
      return false;
    }
    // Scatter or pass with probabilities from the largest channel of each; the weights make
    // every channel's estimate unbiased.
    if (rng.next() * (ps + pn) < ps) {
      beta *= scatter * ((ps + pn) / (sbar * ps));
      t = s;
      return true;
    }
    beta *= null * ((ps + pn) / (sbar * pn));
    if (!(max_of(beta) > 0.0)) return false;
    if (max_of(beta) < 0.1 * entry) {
      if (rng.next() < 0.5) {
        beta = Rgb(0.0);
        return false;
      }
      beta *= 2.0;
    }
  }
  beta = Rgb(0.0);
  return false;
}

std::vector<CompiledMedium> compile_media(const SceneDesc& scene, const std::vector<CompiledTexture>& textures) {
  std::vector<CompiledMedium> out;
  out.reserve(scene.media.size());
  for (const MediumDesc& m : scene.media)
    out.emplace_back(m, m.density < textures.size() ? &textures[m.density] : nullptr);
  return out;
}

MediumStack media_around(const World& world, const std::vector<MaterialDesc>& materials, const Vec3& point) {
  // A direction unlikely to run along an edge or face of a scene built on the axes.
  const Vec3 dir = glm::normalize(Vec3(0.2113248654, 0.5773502692, 0.7886751346));
  struct Around {
    uint32_t medium;
    MaterialId material;
    double exit;  // distance to where the walk leaves it
  };
  std::vector<uint32_t> seen;
  std::vector<Around> around;
  Ray ray{point, dir};
  double travelled = 0.0;
  for (int i = 0; i < tol::kMaxMediumCollisions; ++i) {
    WorldHit hit;
    if (!world.intersect(ray, Interval::positive(), hit, /*transmissive_only=*/true)) break;
    if (std::find(seen.begin(), seen.end(), hit.medium) == seen.end()) {
      seen.push_back(hit.medium);
      if (glm::dot(hit.normal, dir) > 0.0)  // first met from inside: it holds the point
        around.push_back({hit.medium, world.instance(hit.instance).material, travelled + hit.t});
    }
    const Vec3 next = offset_ray_origin(hit.point, hit.normal, dir, hit.error);
    travelled += glm::dot(next - ray.origin, dir);
    ray.origin = next;
  }
  // Outermost (left last) first, as a path entering them from outside would have pushed them.
  std::sort(around.begin(), around.end(), [](const Around& a, const Around& b) { return a.exit > b.exit; });
  MediumStack stack;
  for (const Around& a : around) {
    const MaterialDesc* m = a.material < materials.size() ? &materials[a.material] : nullptr;
    const double outside = stack.current();
    const double ior = !m ? outside : m->ior_relative ? outside * m->ior : (passes_through(*m) ? outside : m->ior);
    stack.enter(a.medium, ior, m ? m->medium : kNoId);
  }
  return stack;
}

}  // namespace rts::render
