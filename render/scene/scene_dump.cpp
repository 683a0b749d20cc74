// SceneDesc::dump: a deterministic text form of the scene for `rts eval` and golden tests.
// Numbers use fmt's shortest round-trip form with tiny values (floating-point noise from
// rotations) rounded to 0, so dumps are stable; file names are printed without folders.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "render/scene/scene.hpp"

namespace rts::render {

// The rts property's value for a spline kind (as render/geometry/shapes/spline_segments.hpp).
static const char* spline_name(SplineKind k) {
  return k == SplineKind::Quadratic ? "quadratic" : k == SplineKind::Cubic ? "cubic"
         : k == SplineKind::Bezier  ? "bezier"    : "linear";
}

namespace {

// |x| below this (times `scale`, the largest magnitude beside it when that is below 1) prints
// as 0: cos(90°) is 6e-17, not a value anyone wrote; a scene modelled at 1e-13 units keeps
// its vectors.
constexpr double kDumpZero = 1e-12;

std::string num(double x, double scale = 1.0) {
  if (std::fabs(x) < kDumpZero * scale) x = 0.0;  // also turns -0 into 0
  return fmt::format("{}", x);
}
// A shape's own length (a radius, a torus's radii): written by the user, not a component a
// rotation computed, so it keeps its value at any scale (only -0 prints as 0).
std::string len(double x) { return fmt::format("{}", x == 0.0 ? 0.0 : x); }
std::string vec(const Vec3& v) {
  const double scale = std::min(1.0, max_abs_component(v));
  return fmt::format("<{}, {}, {}>", num(v.x, scale), num(v.y, scale), num(v.z, scale));
}
std::string col(const Color& c) { return fmt::format("rgb({}, {}, {})", num(c.r), num(c.g), num(c.b)); }
std::string id(uint32_t i) { return i == kNoId ? std::string("none") : fmt::format("{}", i); }
std::string base(const std::string& path) { return std::filesystem::path(path).filename().string(); }
std::string where(const SourceRef& r) {
  if (r.file == nullptr || r.file[0] == '\0') return "";
  return fmt::format(" @{}:{}:{}", base(r.file), r.line, r.col);
}
std::string yes(bool b) { return b ? "true" : "false"; }

// A transform as "identity" or its 3x4 rows [a b c tx; d e f ty; g h i tz]; entries are zeroed
// relative to the largest when that is below 1, as a vector's (`scale 1e-13` keeps its rows).
std::string mat(const Mat4& m) {
  if (m == Mat4(1.0)) return "identity";
  double largest = 0.0;
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 3; ++row) largest = std::max(largest, std::fabs(m[col][row]));
  const double scale = std::min(1.0, largest);
  std::string s = "[";
  for (int row = 0; row < 3; ++row) {
    if (row) s += "; ";
    s += fmt::format("{} {} {} {}", num(m[0][row], scale), num(m[1][row], scale), num(m[2][row], scale),
                     num(m[3][row], scale));
  }
  return s + "]";
}

const char* texture_kind(TextureKind k) {
  switch (k) {
    case TextureKind::Checker:
      return "checker";
    case TextureKind::Stripes:
      return "stripes";
    case TextureKind::Gradient:
      return "gradient";
    case TextureKind::Image:
      return "image_texture";
    case TextureKind::LatLong:
      return "latlong_map";
    case TextureKind::CubeMap:
      return "cube_map";
    case TextureKind::Pattern:
      return "pattern";
    case TextureKind::SkySphere:
      return "sky_sphere";
  }
  return "?";
}

std::string shape_text(const ShapeDesc& s) {
  struct Visitor {
    std::string operator()(const Sphere& g) {
      return fmt::format("sphere center {} radius {}", vec(g.center), len(g.radius));
    }
    std::string operator()(const Plane& g) {
      return fmt::format("plane normal {} offset {}", vec(g.normal), num(g.offset));
    }
    std::string operator()(const Triangle& g) {
      std::string s = fmt::format("triangle v0 {} v1 {} v2 {}", vec(g.v0), vec(g.v1), vec(g.v2));
      if (g.normals) s += fmt::format(" n0 {} n1 {} n2 {}", vec(g.normals->n0), vec(g.normals->n1), vec(g.normals->n2));
      return s;
    }
    std::string operator()(const Box& g) { return fmt::format("box min {} max {}", vec(g.min), vec(g.max)); }
    std::string operator()(const Cylinder& g) {
      return fmt::format("cylinder from {} to {} radius {} capped {}", vec(g.from), vec(g.to), len(g.radius),
                         yes(g.capped));
    }
    std::string operator()(const Cone& g) {
      return fmt::format("cone from {} to {} radius_from {} radius_to {} capped {}", vec(g.from), vec(g.to),
                         len(g.radius_from), len(g.radius_to), yes(g.capped));
    }
    std::string operator()(const Disc& g) {
      return fmt::format("disc center {} normal {} radius {} inner_radius {}", vec(g.center), vec(g.normal),
                         len(g.radius), len(g.inner_radius));
    }
    std::string operator()(const MeshRef& g) { return fmt::format("mesh {} smooth {}", id(g.mesh), yes(g.smooth)); }
    std::string operator()(const Quad& g) {
      return fmt::format("quad corner {} edge_u {} edge_v {}", vec(g.corner), vec(g.edge_u), vec(g.edge_v));
    }
    std::string operator()(const Torus& g) { return fmt::format("torus major {} minor {}", len(g.major), len(g.minor)); }
    std::string operator()(const Superellipsoid& g) {
      return fmt::format("superellipsoid e {} n {}", num(g.e), num(g.n));
    }
    std::string operator()(const Blob& g) {
      std::string out = fmt::format("blob threshold {}", num(g.threshold));
      for (const BlobComponent& c : g.components)
        out += c.cylinder ? fmt::format(" cylinder {} {} {} {}", vec(c.a), vec(c.b), len(c.radius), num(c.strength))
                          : fmt::format(" sphere {} {} {}", vec(c.a), len(c.radius), num(c.strength));
      return out;
    }
    std::string operator()(const Sor& shape) {
      const SorData& g = *shape;
      std::string out = "sor points";
      for (const Vec3& p : g.points) out += fmt::format(" <{}, {}>", num(p.x), num(p.y));
      return out + (g.open ? " open true" : "");
    }
    std::string operator()(const Lathe& shape) {
      const LatheData& g = *shape;
      std::string out = "lathe points";
      for (const Vec3& p : g.points) out += fmt::format(" <{}, {}>", num(p.x), num(p.y));
      return out + (g.spline != SplineKind::Linear ? fmt::format(" spline {}", spline_name(g.spline)) : "");
    }
    std::string operator()(const Prism& shape) {
      const PrismData& g = *shape;
      std::string out = fmt::format("prism height1 {} height2 {} points", num(g.height1), num(g.height2));
      for (const Vec3& p : g.points) out += fmt::format(" <{}, {}>", num(p.x), num(p.y));
      if (g.spline != SplineKind::Linear) out += fmt::format(" spline {}", spline_name(g.spline));
      if (g.conic) out += " sweep conic";
      return out + (g.open ? " open true" : "");
    }
    std::string operator()(const Poly& g) {
      std::string out = fmt::format("poly order {} terms", g.order);
      for (const PolyTerm& t : g.terms) out += fmt::format(" {}*x^{}y^{}z^{}", num(t.c), t.i, t.j, t.k);
      return out;
    }
    std::string operator()(const HeightField& g) {
      if (!g.data) return "height_field empty";
      return fmt::format("height_field {}x{} heights {}..{} smooth {} water_level {}", g.data->nx, g.data->nz,
                         num(g.data->min_height), num(g.data->max_height), g.smooth ? "true" : "false",
                         num(g.water_level));
    }
    std::string operator()(const Isosurface& shape) {
      const IsosurfaceData& g = *shape;
      std::string box = g.container_sphere ? fmt::format("sphere {} {}", vec(g.center), len(g.radius))
                                           : fmt::format("box {} {}", vec(g.box_min), vec(g.box_max));
      return fmt::format("isosurface function {} threshold {} max_gradient {} accuracy {} max_trace {} "
                         "contained_by {}",
                         g.function ? "compiled" : "none", num(g.threshold), num(g.max_gradient),
                         num(g.accuracy), g.max_trace, box);
    }
  };
  return visit_shape(Visitor{}, s.geometry) + fmt::format(" material {}", id(s.material)) +
         (s.inverse ? " inverse true" : "") +
         (s.casts_shadow ? "" : " casts_shadow false");
}

std::string light_text(const LightDesc& l) {
  std::string common = fmt::format("color {} intensity {} shadows {}{}", col(l.color), num(l.intensity), yes(l.shadows),
                                   l.attenuation_clamp ? " attenuation_clamp true" : "");
  switch (l.kind) {
    case LightKind::Point:
      return fmt::format("point_light position {} attenuation {} {}", vec(l.position), vec(l.attenuation), common);
    case LightKind::Spot:
      return fmt::format("spot_light position {} point_at {} radius {} falloff {} attenuation {} {}", vec(l.position),
                         vec(l.point_at), num(l.radius), num(l.falloff), vec(l.attenuation), common);
    case LightKind::Directional:
      return fmt::format("directional_light direction {} {}", vec(l.direction), common);
    case LightKind::Area:
      return fmt::format("area_light position {} u {} v {} samples {} disc {}{} attenuation {} {}", vec(l.position),
                         vec(l.u), vec(l.v), l.samples, yes(l.disc),
                         l.area_spot ? fmt::format(" point_at {} radius {} falloff {}", vec(l.point_at), num(l.radius),
                                                   num(l.falloff))
                                     : "",
                         vec(l.attenuation), common);
  }
  return "?";
}

}  // namespace

void SceneDesc::dump(std::ostream& out) const {
  const Settings& s = settings;
  out << fmt::format("settings width {} height {} samples {} max_depth {} background {} ambient_light {} seed {}",
                     s.width, s.height, s.samples, s.max_depth, col(s.background), col(s.ambient_light), s.seed);
  if (s.environment != kNoId)
    out << fmt::format(" environment texture {} environment_ambient {}", s.environment, yes(s.environment_ambient));
  if (s.integrator != IntegratorKind::Whitted) out << " integrator " << integrator_name(s.integrator);
  if (!s.aovs.empty()) {
    out << " aov";
    for (const std::string& a : s.aovs) out << ' ' << a;
  }
  if (s.has_depth_range) out << fmt::format(" depth_range {} {}", num(s.depth_near), num(s.depth_far));
  if (s.depth_miss != 0 || s.normal_miss != 0)
    out << fmt::format(" depth_miss {} normal_miss {}", num(s.depth_miss), num(s.normal_miss));
  if (s.clamp > 0) out << " clamp " << num(s.clamp);
  if (s.fog_distance > 0)
    out << fmt::format(" fog distance {} color {} offset {} altitude {}", num(s.fog_distance), col(s.fog_color),
                       num(s.fog_offset), num(s.fog_altitude));
  if (s.fog_distance > 0 && s.fog_turbulence != Vec3(0.0))
    out << fmt::format(" fog_turbulence {} turb_depth {} octaves {} omega {} lambda {}", vec(s.fog_turbulence),
                       num(s.fog_turb_depth), s.fog_octaves, num(s.fog_omega), num(s.fog_lambda));
  if (s.medium != kNoId) out << fmt::format(" medium {} media_samples {}", s.medium, s.media_samples);
  out << '\n';
  const CameraDesc& c = camera;
  out << fmt::format("camera{} {} position {} look_at {} up {} fov {} view_width {} aperture {} focus_distance {}{}{}\n",
                     has_camera ? "" : " (default)",
                     projection_name(c.projection), vec(c.position),
                     vec(c.look_at), vec(c.up), num(c.fov), num(c.view_width), num(c.aperture), num(c.focus_distance),
                     c.fov_vertical ? " fov_axis vertical" : "", c.right_handed ? " handedness right" : "");
  if (c.given_vectors)  // appended, so the dumps of look_at cameras stay as they were
    out << fmt::format("  as given: direction {} right {} up {}\n", vec(c.direction), vec(c.right), vec(c.up));
  out << fmt::format("textures {}\n", textures.size());
  for (std::size_t i = 0; i < textures.size(); ++i) {
    const TextureDesc& t = textures[i];
    out << fmt::format("  texture {}: {}", i, texture_kind(t.kind));
    if (t.kind == TextureKind::Image)
      out << fmt::format(" file {} mapping {}", base(t.image_path), t.mapping);
    else if (t.kind == TextureKind::LatLong)
      out << fmt::format(" file {}", base(t.image_path));
    else if (t.kind == TextureKind::CubeMap) {
      for (const std::string& f : t.face_paths) out << ' ' << base(f);
      if (t.cube_mit) out << " orientation mit";
    } else if (t.kind == TextureKind::Pattern) {
      out << fmt::format(" {} color_map {} turbulence {}{}", static_cast<int>(t.pattern.kind), t.pattern.color_map.size(),
                         vec(t.pattern.turbulence), t.pattern.function ? " function" : "");
      std::string entries;  // a pigment_map's textures, by entry (only when it has some)
      for (const ColorMapEntry& e : t.pattern.color_map)
        if (e.texture != kNoId) entries += fmt::format(" {}", e.texture);
      if (!entries.empty()) out << " entry_textures" << entries;
    } else
      out << fmt::format(" color1 {} color2 {} scale {} axis {}", col(t.color1), col(t.color2), num(t.scale), t.axis);
    // Newer options print only when not their defaults, so older dumps stay as they were.
    if (t.linear) out << " color_space linear";
    if (t.filter == TextureFilter::Nearest) out << " filter nearest";
    out << fmt::format(" transform {}{}\n", mat(t.transform), where(t.loc));
  }
  out << fmt::format("materials {}\n", materials.size());
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const MaterialDesc& m = materials[i];
    if (m.layered) {
      out << fmt::format("  material {}: layers {} (base) to {} (top){}\n", i, m.first_choice,
                         m.first_choice + m.choice_count - 1, where(m.loc));
      continue;
    }
    if (m.choice_count > 0) {
      out << fmt::format("  material {}: chosen by texture {} among materials {} to {}{}\n", i, id(m.choice_pattern),
                         m.first_choice, m.first_choice + m.choice_count - 1, where(m.loc));
      continue;
    }
    out << fmt::format(
        "  material {}: color {} texture {} emission {} ambient {} diffuse {} specular {} shininess {} reflect {} "
        "transmit {} ior {}{} fresnel {} roughness {}{}\n",
        i, col(m.color), id(m.texture), col(m.emission), num(m.ambient), num(m.diffuse),
        m.specular_color == Color(1.0)
            ? num(m.specular)
            : col(Color(m.specular * m.specular_color.r, m.specular * m.specular_color.g, m.specular * m.specular_color.b)),
        num(m.shininess), col(m.reflect), col(m.transmit), num(m.ior), m.ior_relative ? " (relative)" : "",
        yes(m.fresnel), num(m.roughness), where(m.loc));
    const std::pair<const char*, TextureId> maps[] = {
        {"diffuse", m.diffuse_texture}, {"specular", m.specular_texture}, {"reflect", m.reflect_texture},
        {"transmit", m.transmit_texture}, {"emission", m.emission_texture}, {"bump", m.bump},
        {"normal_map", m.normal_map}};
    std::string extra;
    for (const auto& [name, tex] : maps)
      if (tex != kNoId) extra += fmt::format(" {} texture {}", name, tex);
    if (m.bump != kNoId) extra += fmt::format(" bump_scale {}", num(m.bump_scale));
    if (!extra.empty()) out << "    maps" << extra << '\n';
    if (m.has_reflect_min)
      out << fmt::format("    reflect_min {} reflect_falloff {}\n", col(m.reflect_min), num(m.reflect_falloff));
    if (m.medium != kNoId) out << fmt::format("    medium {}\n", m.medium);
    if (!(m.ambient_color == Color(1.0))) out << fmt::format("    ambient color {}\n", col(m.ambient_color));
  }
  // Printed only when there are any, so the dumps of scenes without media stay as they were.
  if (!media.empty()) out << fmt::format("media {}\n", media.size());
  for (std::size_t i = 0; i < media.size(); ++i) {
    const MediumDesc& d = media[i];
    out << fmt::format("  medium {}: absorption {} scattering {} emission {} eccentricity {} density {}{}\n", i,
                       col(d.absorption), col(d.scattering), col(d.emission), num(d.eccentricity), id(d.density),
                       where(d.loc));
  }
  out << fmt::format("meshes {}\n", meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const MeshData& m = *meshes[i];
    out << fmt::format("  mesh {}: vertices {} triangles {} normals {} uvs {} source {}", i, m.positions.size(),
                       m.indices.size() / 3, m.normals.size(), m.uvs.size(),
                       m.source.empty() ? "inline" : base(m.source));
    if (m.has_vertex_material())
      out << fmt::format(" vertex colors {} diffuse {} specular {} shininess {}", m.colors.size(), m.diffuse.size(),
                         m.specular.size(), m.shininess.size());
    out << '\n';
  }
  out << fmt::format("nodes {}\n", nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& n = nodes[i];
    out << fmt::format("  node {}: ", i);
    switch (n.kind) {
      case NodeKind::Shape:
        out << shape_text(shapes[n.index]);
        break;
      case NodeKind::Light:
        out << light_text(lights[n.index]);
        break;
      case NodeKind::Group:
        out << fmt::format("group children {}", groups[n.index].children.size());
        if (groups[n.index].material != kNoId) out << fmt::format(" material {}", id(groups[n.index].material));
        if (!groups[n.index].casts_shadow) out << " casts_shadow false";
        break;
      case NodeKind::Csg: {
        static const char* kOps[] = {"union", "intersection", "difference", "merge", "clip"};
        const CsgDesc& d = csgs[n.index];
        out << fmt::format("{} children {} material {}{}", kOps[static_cast<int>(d.op)], d.children.size(),
                           id(d.material), d.inverse ? " inverse true" : "");
        if (!d.casts_shadow) out << " casts_shadow false";
        break;
      }
    }
    out << where(node_loc(*this, n)) << '\n';
    if (n.kind == NodeKind::Group)
      for (const Child& ch : groups[n.index].children)
        out << fmt::format("    child node {} transform {}{}\n", ch.node, mat(ch.transform), where(ch.loc));
    if (n.kind == NodeKind::Csg)
      for (const Child& ch : csgs[n.index].children)
        out << fmt::format("    child node {} transform {}{}\n", ch.node, mat(ch.transform), where(ch.loc));
  }
  out << fmt::format("roots {}\n", roots.size());
  for (const Child& ch : roots)
    out << fmt::format("  root node {} transform {}{}\n", ch.node, mat(ch.transform), where(ch.loc));
}

}  // namespace rts::render
