// Procedural and image textures, evaluated in texture space = inverse(transform) * object point.
//
// Semantics (docs/rendering.md shows each):
//  - checker:  3D cells of side `scale`; the parity of floor(x/s)+floor(y/s)+floor(z/s) picks
//              color1 (even) or color2 (odd).
//  - stripes:  slabs along `axis`, period `scale`: the first half of each period is color1,
//              the second half color2.
//  - gradient: color1 → color2 linearly along `axis` over `scale`, then repeats (a sawtooth,
//              as POV-Ray's gradient pattern).
//  - image:    bilinear (or nearest) lookup with repeat wrapping; v = 0 is the image's bottom
//              row.
//  - latlong:  an equirectangular environment: u = 0.5 + atan2(x, z) / 2pi (the image's centre
//              column looks along +z, +x to its right), v = 0.5 + asin(y) / pi.
//  - cube_map: six faces, each seen upright and unmirrored from inside the cube (rts's
//              left-handed view: +z front, +x right, +y up); the +y face's bottom edge meets
//              the +z face's top edge, the -y face's top edge meets its bottom edge.
//              orientation = "mit" reads the faces as MIT 6.837 a2 does (see cube_face).
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "render/geometry/transform_inverse.hpp"
#include "render/shade/texture.hpp"
#include "render/shade/pattern/patterns.hpp"

namespace rts::render {

namespace {

// Points exactly on a cell boundary (a checkered plane at y = 0, a box face at x = 1) would
// pick a cell by the sign of rounding noise and flicker between two colors. Shifting every
// coordinate by this fraction of a cell puts boundary points consistently in the upper cell.
constexpr double kCellBoundaryBias = 1e-6;

// Below this distance from the texture-space origin, the spherical mapping has no direction.
constexpr double kMinSphericalRadius = 1e-12;

// A non-positive or NaN scale (the builder should reject it) behaves as 1 instead of
// dividing by zero.
double safe_scale(double scale) { return scale > 0.0 && std::isfinite(scale) ? scale : 1.0; }

// Which cell of side `size` holds x, robust on boundaries.
double cell_index(double x, double size) { return std::floor(x / size + kCellBoundaryBias); }

// Fractional part in [0,1) (NaN and infinities → 0, never a NaN color).
double wrap01(double x) {
  if (!std::isfinite(x)) return 0.0;
  const double f = x - std::floor(x);
  return f >= 1.0 ? 0.0 : f;   // x - floor(x) rounds to 1.0 for tiny negative x
}

Color mix(const Color& a, const Color& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

int clamp_axis(int axis) { return axis < 0 || axis > 2 ? 0 : axis; }

Color checker(const TextureDesc& d, const Vec3& q) {
  const double s = safe_scale(d.scale);
  const double sum = cell_index(q.x, s) + cell_index(q.y, s) + cell_index(q.z, s);
  const double parity = sum - 2.0 * std::floor(sum / 2.0);   // 0 or 1, also for negatives
  return parity >= 0.5 ? d.color2 : d.color1;
}

Color stripes(const TextureDesc& d, const Vec3& q) {
  const double t = wrap01(q[clamp_axis(d.axis)] / safe_scale(d.scale) + kCellBoundaryBias);
  return t < 0.5 ? d.color1 : d.color2;
}

Color gradient(const TextureDesc& d, const Vec3& q) {
  return mix(d.color1, d.color2, wrap01(q[clamp_axis(d.axis)] / safe_scale(d.scale)));
}

// Bilinear lookup at (u, v) with repeat wrapping; v = 0 at the bottom of the image.
Color sample_bilinear(const Image& image, double u, double v) {
  const int w = image.width, h = image.height;
  // Continuous pixel coordinates with pixel centres at integers + 0.5.
  const double x = wrap01(u) * w - 0.5;
  const double y = (1.0 - wrap01(v)) * h - 0.5;
  const double x0f = std::floor(x), y0f = std::floor(y);
  const double fx = x - x0f, fy = y - y0f;
  auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int x0 = wrap(static_cast<int>(x0f), w), x1 = wrap(x0 + 1, w);
  const int y0 = wrap(static_cast<int>(y0f), h), y1 = wrap(y0 + 1, h);
  auto texel = [&](int px, int py) {
    const float* p = image.at(px, py);
    return Color(p[0], p[1], p[2]);
  };
  const Color top = mix(texel(x0, y0), texel(x1, y0), fx);
  const Color bottom = mix(texel(x0, y1), texel(x1, y1), fx);
  return mix(top, bottom, fy);
}

Color sample_nearest(const Image& image, double u, double v) {
  const int x = std::min(static_cast<int>(wrap01(u) * image.width), image.width - 1);
  const int y = std::min(static_cast<int>((1.0 - wrap01(v)) * image.height), image.height - 1);
  const float* p = image.at(std::max(x, 0), std::max(y, 0));
  return Color(p[0], p[1], p[2]);
}

// The face (0..5 = +x, -x, +y, -y, +z, -z) a direction points at and its (u, v) on that face.
// `mit`: MIT 6.837 a2's reading of the faces, which mirrors +x, -x and +z left-right and +y
// top-bottom against rts's (its course scenes were made with it).
int cube_face(const Vec3& d, glm::dvec2& uv, bool mit) {
  const Vec3 a = glm::abs(d);
  int face;
  double s, t, m;
  if (a.x >= a.y && a.x >= a.z) {
    m = a.x;
    face = d.x > 0 ? 0 : 1;
    s = d.x > 0 ? -d.z : d.z;
    t = d.y;
  } else if (a.y >= a.z) {
    m = a.y;
    face = d.y > 0 ? 2 : 3;
    s = d.x;
    t = d.y > 0 ? -d.z : d.z;
  } else {
    m = a.z;
    face = d.z > 0 ? 4 : 5;
    s = d.z > 0 ? d.x : -d.x;
    t = d.y;
  }
  if (mit) {
    if (face == 0 || face == 1 || face == 4) s = -s;
    if (face == 2) t = -t;
  }
  if (!(m > 0.0)) m = 1.0;   // the zero vector: the face centre
  // Clamped inside the face: bilinear filtering wraps, so keep half a texel... away by
  // clamping to [0, 1) and letting the sampler's own wrap stay on the face.
  uv = {std::clamp(0.5 * (s / m + 1.0), 0.0, 1.0), std::clamp(0.5 * (t / m + 1.0), 0.0, 1.0)};
  return face;
}

glm::dvec2 planar_uv(const Vec3& q) { return {q.x, q.z}; }

// Longitude → u (0 at -x, going round through +z), latitude → v (0 at the south pole).
glm::dvec2 spherical_uv(const Vec3& q) {
  const double r = glm::length(q);
  if (!(r > kMinSphericalRadius)) return {0.5, 0.5};
  const Vec3 d = q / r;
  const double u = 0.5 + std::atan2(d.z, d.x) / (2.0 * std::numbers::pi);
  const double v = 0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi;
  return {u, v};
}

bool is_known_mapping(const std::string& mapping) {
  return mapping == "uv" || mapping == "planar" || mapping == "spherical";
}

}  // namespace

CompiledTexture::CompiledTexture(const TextureDesc& desc,
                                 std::vector<std::shared_ptr<const Image>> images)
    : desc_(desc), inverse_(inverse_transform(desc.transform)), images_(std::move(images)) {
  const std::size_t wanted = desc_.kind == TextureKind::CubeMap ? 6
                             : desc_.kind == TextureKind::Image || desc_.kind == TextureKind::LatLong ? 1
                                                                                                   : 0;
  if (images_.size() != wanted) {
    throw RenderError(desc_.loc, fmt::format("texture has {} images, needs {}", images_.size(), wanted));
  }
  for (const auto& image : images_) {
    if (image == nullptr || image->width <= 0 || image->height <= 0) {
      throw RenderError(desc_.loc, fmt::format("image texture '{}' has no image data",
                                               desc_.image_path));
    }
  }
  if (desc_.kind == TextureKind::Image) {
    if (!is_known_mapping(desc_.mapping)) {
      throw RenderError(desc_.loc, fmt::format("unknown image mapping '{}' (expected \"uv\", "
                                               "\"planar\" or \"spherical\")", desc_.mapping));
    }
    uses_uv_ = desc_.mapping == "uv";
  }
}

Color CompiledTexture::sample(const Image& image, double u, double v) const {
  return desc_.filter == TextureFilter::Nearest ? sample_nearest(image, u, v)
                                                : sample_bilinear(image, u, v);
}

double CompiledTexture::texel_size() const {
  if (images_.empty()) return 0.0;
  return 1.0 / std::max(images_[0]->width, images_[0]->height);
}

Color CompiledTexture::lookup_direction(const Vec3& d) const {
  if (desc_.kind == TextureKind::CubeMap) {
    glm::dvec2 uv;
    const int face = cube_face(d, uv, desc_.cube_mit);
    const Image& image = *images_[face];
    // Keep bilinear filtering from wrapping to the opposite edge of the face.
    const double hu = 0.5 / image.width, hv = 0.5 / image.height;
    return sample(image, std::clamp(uv.x, hu, 1.0 - hu), std::clamp(uv.y, hv, 1.0 - hv));
  }
  const double r = glm::length(d);
  if (!(r > kMinSphericalRadius) || !std::isfinite(r)) return sample(*images_[0], 0.5, 0.5);
  const Vec3 n = d / r;
  const double u = 0.5 + std::atan2(n.x, n.z) / (2.0 * std::numbers::pi);
  const double v = 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / std::numbers::pi;
  // Clamp v so the poles' rows do not blend with the opposite pole through wrapping.
  const double hv = 0.5 / images_[0]->height;
  return sample(*images_[0], u, std::clamp(v, hv, 1.0 - hv));
}

Color CompiledTexture::eval_direction(const Vec3& direction) const {
  if (desc_.kind == TextureKind::SkySphere) return eval_sky(direction);
  const Vec3 q = Vec3(inverse_ * glm::dvec4(direction, 0.0));
  if (is_environment()) return lookup_direction(q);
  TexturePoint p;
  p.object_point = direction;
  return eval(p);
}

glm::dvec4 CompiledTexture::eval_map_entries(const Vec3& q) const {
  const std::vector<ColorMapEntry>& map = desc_.pattern.color_map;
  const double t = pattern::wave(desc_.pattern, pattern::raw_value(desc_.pattern, q));
  auto entry = [&](std::size_t i) {
    if (map[i].texture == kNoId) return glm::dvec4(map[i].color, map[i].transmit);
    return map_entries_[i]->eval_layer(q);   // the entry's own transform, then its value at q
  };
  const pattern::MapSpan s = pattern::map_span(map, t);
  if (s.a == s.b) return entry(s.a);
  return entry(s.a) * (1.0 - s.w) + entry(s.b) * s.w;
}

glm::dvec4 CompiledTexture::eval_with_transmit(const TexturePoint& p) const {
  if (desc_.kind != TextureKind::Pattern) {
    const Color c = eval(p);
    return {c.r, c.g, c.b, 0.0};
  }
  const Vec3 q = Vec3(inverse_ * glm::dvec4(p.object_point, 1.0));
  glm::dvec4 c = map_entries_.empty() ? pattern::pattern_color_transmit(desc_.pattern, q) : eval_map_entries(q);
  c.w = std::isfinite(c.w) ? std::clamp(c.w, 0.0, 1.0) : 0.0;
  return c;
}

Color CompiledTexture::eval(const TexturePoint& p) const {
  const Vec3 q = Vec3(inverse_ * glm::dvec4(p.object_point, 1.0));
  switch (desc_.kind) {
    case TextureKind::Checker: return checker(desc_, q);
    case TextureKind::Stripes: return stripes(desc_, q);
    case TextureKind::Gradient: return gradient(desc_, q);
    case TextureKind::Pattern: {
      if (!map_entries_.empty()) {
        const glm::dvec4 c = eval_map_entries(q);
        return {c.x, c.y, c.z};
      }
      const glm::dvec3 c = pattern::pattern_color(desc_.pattern, q);
      return {c.x, c.y, c.z};
    }
    case TextureKind::LatLong:
    case TextureKind::CubeMap: return lookup_direction(q);
    // Only ever the environment (the builder refuses it elsewhere); on a surface it would
    // show the sky in the direction of the point.
    case TextureKind::SkySphere: return eval_sky(p.object_point);
    case TextureKind::Image: break;
  }
  glm::dvec2 uv;
  if (desc_.mapping == "spherical") {
    uv = spherical_uv(q);
  } else if (desc_.mapping == "uv" && p.has_uv) {
    // Surface UVs go through the same texture transform, so `scale 0.5` tiles twice.
    const Vec3 t = Vec3(inverse_ * glm::dvec4(p.uv.x, p.uv.y, 0.0, 1.0));
    uv = {t.x, t.y};
  } else {
    uv = planar_uv(q);
  }
  return sample(*images_[0], uv.x, uv.y);
}

Color CompiledTexture::eval_height(const TexturePoint& p) const {
  if (desc_.kind != TextureKind::Pattern || !map_entries_.empty()) return eval(p);
  const Vec3 q = Vec3(inverse_ * glm::dvec4(p.object_point, 1.0));
  const glm::dvec3 c = pattern::pattern_color(desc_.pattern, q, /*height=*/true);
  return {c.x, c.y, c.z};
}

std::vector<CompiledTexture> compile_textures(const SceneDesc& scene, const std::vector<bool>* used,
                                              std::size_t max_memory) {
  // (path, linear) → image, each file loaded once per color space.
  std::map<std::pair<std::string, bool>, std::shared_ptr<const Image>> loaded;
  auto load = [&](const std::string& path, const TextureDesc& desc) {
    auto key = std::make_pair(path, desc.linear);
    auto it = loaded.find(key);
    if (it == loaded.end()) {
      auto fresh = std::make_shared<const Image>(
          read_image(path, desc.loc, desc.linear ? Encoding::Linear : Encoding::SRGB, max_memory));
      it = loaded.emplace(std::move(key), std::move(fresh)).first;
    }
    return it->second;
  };
  std::vector<CompiledTexture> compiled;
  compiled.reserve(scene.textures.size());   // never reallocated: map entries point into it
  std::vector<int> nesting(scene.textures.size(), 0);   // color maps of maps, per texture
  for (std::size_t id = 0; id < scene.textures.size(); ++id) {
    const TextureDesc& desc = scene.textures[id];
    const bool has_files = desc.kind == TextureKind::Image || desc.kind == TextureKind::LatLong ||
                           desc.kind == TextureKind::CubeMap;
    const bool needed = !used || (id < used->size() && (*used)[id]);
    if (has_files && !needed) {
      // Never evaluated (nothing placed refers to it): keep its slot, skip the files.
      TextureDesc placeholder;
      placeholder.loc = desc.loc;
      compiled.emplace_back(placeholder, std::vector<std::shared_ptr<const Image>>{});
      continue;
    }
    std::vector<std::shared_ptr<const Image>> images;
    if (desc.kind == TextureKind::Image || desc.kind == TextureKind::LatLong) {
      images.push_back(load(desc.image_path, desc));
    } else if (desc.kind == TextureKind::CubeMap) {
      for (const std::string& face : desc.face_paths) images.push_back(load(face, desc));
    }
    compiled.emplace_back(desc, std::move(images));
    const std::vector<ColorMapEntry>& map = desc.pattern.color_map;
    if (desc.kind == TextureKind::Pattern &&
        std::any_of(map.begin(), map.end(), [](const ColorMapEntry& e) { return e.texture != kNoId; })) {
      // A pigment_map: its entries' textures were built before it (its block realised them).
      std::vector<const CompiledTexture*> entries;
      entries.reserve(map.size());
      for (const ColorMapEntry& e : map) {
        if (e.texture == kNoId) {
          entries.push_back(nullptr);   // a plain colour: never evaluated as a texture
        } else if (e.texture < id) {
          entries.push_back(&compiled[e.texture]);
          nesting[id] = std::max(nesting[id], nesting[e.texture] + 1);
        } else {
          throw RenderError(desc.loc, "a color map entry is not a texture built before its pattern");
        }
      }
      if (nesting[id] > kMaxColorMapNesting)
        throw RenderError(desc.loc, fmt::format("color maps whose entries are textures nest {} deep here; at most {}",
                                                nesting[id], kMaxColorMapNesting));
      compiled.back().set_map_entries(std::move(entries));
    }
    if (desc.kind == TextureKind::SkySphere) {
      // The layers were built before the sky (its block realised them), so they precede it.
      std::vector<CompiledTexture> layers;
      for (std::size_t i = 0; i < desc.sky_layers.size(); ++i) {
        const TextureId layer = desc.sky_layers[i];
        if (layer == kNoId) {
          TextureDesc solid;   // a solid color layer: a checker of one color
          solid.color1 = solid.color2 = i < desc.sky_layer_colors.size() ? desc.sky_layer_colors[i] : Color(0.0);
          layers.emplace_back(solid, std::vector<std::shared_ptr<const Image>>{});
        } else if (layer < id) {
          layers.push_back(compiled[layer]);
        } else {
          throw RenderError(desc.loc, "sky_sphere layer is not a texture built before the sky");
        }
      }
      compiled.back().set_sky(std::move(layers), scene.settings.background);
    }
  }
  return compiled;
}

}  // namespace rts::render
