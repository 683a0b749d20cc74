// SceneBuilder: validates block parameters and fills the SceneDesc. Here: the block kinds and
// their property names, settings, camera and textures; materials and media are in
// material_builder.cpp, shapes, lights, groups and CSG blocks in scene_nodes.cpp.
#include "render/builder/scene_builder.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/shade/lights.hpp"
#include "render/builder/block_properties.hpp"
#include "render/builder/height_field_builder.hpp"
#include "render/builder/obj_loader.hpp"
#include "render/builder/pattern_builder.hpp"
#include "render/builder/scene_builder_detail.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

using builder_detail::names_of;
using builder_detail::names_of_block;
using builder_detail::resolve_path;
using builder_detail::second_word;
using builder_detail::reference;

namespace {

constexpr double kMaxFovDegrees = 180.0;

struct KindInfo {
  std::string_view name;
  BlockCategory category;
};
constexpr KindInfo kKinds[] = {
    {"settings", BlockCategory::Settings},
    {"camera", BlockCategory::Camera},
    {"material", BlockCategory::Material},
    {"checker", BlockCategory::Texture},
    {"stripes", BlockCategory::Texture},
    {"gradient", BlockCategory::Texture},
    {"image_texture", BlockCategory::Texture},
    {"latlong_map", BlockCategory::Texture},
    {"cube_map", BlockCategory::Texture},
    {"sky_sphere", BlockCategory::Texture},
    // pattern textures (render/builder/pattern_builder.cpp)
    {"bozo", BlockCategory::Texture}, {"spotted", BlockCategory::Texture}, {"granite", BlockCategory::Texture},
    {"marble", BlockCategory::Texture}, {"wood", BlockCategory::Texture}, {"agate", BlockCategory::Texture},
    {"onion", BlockCategory::Texture}, {"leopard", BlockCategory::Texture}, {"wrinkles", BlockCategory::Texture},
    {"crackle", BlockCategory::Texture}, {"cells", BlockCategory::Texture}, {"bumps", BlockCategory::Texture},
    {"dents", BlockCategory::Texture}, {"ripples", BlockCategory::Texture}, {"waves", BlockCategory::Texture},
    {"pattern", BlockCategory::Texture}, {"radial", BlockCategory::Texture}, {"spiral1", BlockCategory::Texture},
    {"spiral2", BlockCategory::Texture}, {"boxed", BlockCategory::Texture}, {"cylindrical", BlockCategory::Texture},
    {"planar", BlockCategory::Texture}, {"spherical", BlockCategory::Texture},
    {"", BlockCategory::Shape},  // here: every shape kind (kShapeInfos), in ShapeGeometry's order
    {"point_light", BlockCategory::Light},
    {"spot_light", BlockCategory::Light},
    {"directional_light", BlockCategory::Light},
    {"area_light", BlockCategory::Light},
    {"group", BlockCategory::Group},
    {"union", BlockCategory::Csg},
    {"intersection", BlockCategory::Csg},
    {"difference", BlockCategory::Csg},
    {"merge", BlockCategory::Csg},
    {"clip", BlockCategory::Csg},
    {"text", BlockCategory::Shape},   // built as a group of prisms (text_builder.cpp)
};

const std::vector<std::string_view> kSettingsNames = names_of_block("settings");
const std::vector<std::string_view> kCameraNames = names_of_block("camera");
const std::vector<std::string_view> kImageTextureNames = names_of_block("image_texture");
const std::vector<std::string_view> kLatLongNames = names_of_block("latlong_map");
const std::vector<std::string_view> kCubeMapNames = names_of_block("cube_map");
const std::vector<std::string_view> kSkySphereNames = names_of_block("sky_sphere");
const std::vector<std::string_view> kCheckerNames = names_of_block("checker");
const std::vector<std::string_view> kPatternTextureNames = names_of_block("stripes");
const std::vector<std::string_view> kMaterialNames = names_of_block("material");
// Texture axis: 0/1/2 or "x"/"y"/"z".
int axis_of(ParamSet& ps) {
  const ParamValue* v = ps.value("axis");
  if (!v) return 0;
  if (auto* s = std::get_if<std::string>(v)) {
    if (*s == "x") return 0;
    if (*s == "y") return 1;
    if (*s == "z") return 2;
    throw SceneError(loc_of(ps, "axis"),
                     fmt::format("property 'axis' of {} must be \"x\", \"y\" or \"z\", got \"{}\"", ps.kind(), *s));
  }
  int a = ps.integer("axis", 0);
  require(ps, "axis", a >= 0 && a <= 2, "0, 1 or 2", a);
  return a;
}

// The six face files of a cube-map directory, in the order +x, -x, +y, -y, +z, -z: named
// posx/negx/posy/negy/posz/negz (the OpenGL convention) or right/left/up/down/front/back (MIT
// 6.837's cubeMap directories), each .png, .bmp, .jpg, .jpeg, .tga or .hdr.
std::vector<std::string> cube_map_faces(const std::string& dir, const std::string& shown, SourceRef where) {
  namespace fs = std::filesystem;
  static const char* kSchemes[2][6] = {{"posx", "negx", "posy", "negy", "posz", "negz"},
                                       {"right", "left", "up", "down", "front", "back"}};
  static const char* kExtensions[] = {".png", ".bmp", ".jpg", ".jpeg", ".tga", ".hdr"};
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw SceneError(where, fmt::format("cube_map directory '{}' does not exist", shown));
  for (const auto& scheme : kSchemes) {
    std::vector<std::string> faces;
    for (const char* name : scheme) {
      for (const char* ext : kExtensions) {
        fs::path p = fs::path(dir) / (std::string(name) + ext);
        if (fs::is_regular_file(p, ec)) {
          faces.push_back(p.string());
          break;
        }
      }
    }
    if (faces.size() == 6) return faces;
    if (!faces.empty())
      throw SceneError(where, fmt::format("cube_map directory '{}' has {} of the six faces {}, {}, {}, {}, {}, {}", shown,
                                          faces.size(), scheme[0], scheme[1], scheme[2], scheme[3], scheme[4], scheme[5]));
  }
  throw SceneError(where, fmt::format("cube_map directory '{}' has no faces: expected posx, negx, posy, negy, posz, "
                                      "negz or right, left, up, down, front, back (.png, .bmp, .jpg, .tga or .hdr)",
                                      shown));
}

}  // namespace

namespace builder_detail {

bool second_word(ParamSet& ps, std::string_view name, std::string_view first, std::string_view second) {
  const std::string v = ps.string(name, std::string(first));
  if (v != first && v != second)
    throw SceneError(loc_of(ps, name), fmt::format("unknown {} '{}' (expected {} or {})", name, v, first, second));
  return v == second;
}

// Paths in a scene are relative to the file that names them.
std::string resolve_path(const std::string& path, SourceRef where) {
  namespace fs = std::filesystem;
  fs::path p(path);
  if (p.is_absolute() || where.file == nullptr || where.file[0] == '\0') return path;
  return (fs::path(where.file).parent_path() / p).lexically_normal().string();
}

}  // namespace builder_detail

std::vector<std::string_view> SceneBuilder::property_names(std::string_view kind) {
  if (const std::vector<std::string_view>* names = names_of(kind)) return *names;
  if (is_pattern_kind(kind)) return pattern_property_names(kind);
  static const std::pair<std::string_view, const std::vector<std::string_view>*> kTable[] = {
      {"settings", &kSettingsNames},          {"camera", &kCameraNames},       {"material", &kMaterialNames},
      {"image_texture", &kImageTextureNames}, {"latlong_map", &kLatLongNames}, {"cube_map", &kCubeMapNames},
      {"checker", &kCheckerNames},            {"stripes", &kPatternTextureNames}, {"gradient", &kPatternTextureNames},
      {"sky_sphere", &kSkySphereNames}};
  for (const auto& [name, names] : kTable)
    if (name == kind) return *names;
  return {};  // group (no properties) and unknown kinds
}

BlockCategory SceneBuilder::category(std::string_view kind) {
  if (find_shape(kind)) return BlockCategory::Shape;
  for (const KindInfo& k : kKinds)
    if (!k.name.empty() && k.name == kind) return k.category;
  return BlockCategory::Unknown;
}

std::vector<std::string_view> SceneBuilder::block_kinds() {
  std::vector<std::string_view> out;
  for (const KindInfo& k : kKinds) {
    if (!k.name.empty())
      out.push_back(k.name);
    else
      for (const ShapeInfo& shape : kShapeInfos) out.push_back(shape.name);
  }
  return out;
}

// The extra images `rts render` writes by default (its flags override them): AOVs, the depth
// mapping, the miss values.
void SceneBuilder::output_settings(ParamSet& ps, Settings& s) {
  if (ps.has("aov")) {
    const std::string list = ps.string("aov", "");
    s.aovs.clear();
    std::size_t start = 0;
    while (start <= list.size()) {
      std::size_t comma = list.find(',', start);
      if (comma == std::string::npos) comma = list.size();
      std::string name = list.substr(start, comma - start);
      // The names --aov takes (render/renderer.cpp's parse_aovs, a layer above the builder).
      if (name != "normal" && name != "depth" && name != "albedo" && name != "error" && name != "error_map")
        throw SceneError(loc_of(ps, "aov"), fmt::format("unknown AOV '{}' in property 'aov' of settings (expected a "
                                                        "comma-separated list of normal, depth, albedo, error, "
                                                        "error_map)",
                                                        name));
      s.aovs.push_back(name);
      start = comma + 1;
    }
  }
  if (const ParamValue* v = ps.value("depth_range")) {
    const auto* range = std::get_if<std::vector<double>>(v);
    if (!range || range->size() != 2 || !std::isfinite((*range)[0]) || !std::isfinite((*range)[1]) ||
        (*range)[0] > (*range)[1])
      throw SceneError(loc_of(ps, "depth_range"),
                       "property 'depth_range' of settings expects [NEAR, FAR]: two finite numbers, NEAR <= FAR");
    s.has_depth_range = true;
    s.depth_near = (*range)[0];
    s.depth_far = (*range)[1];
  }
  s.depth_miss = ps.number("depth_miss", s.depth_miss);
  s.normal_miss = ps.number("normal_miss", s.normal_miss);
}

void SceneBuilder::settings(ParamSet& ps) {
  Settings& s = scene_.settings;
  s.width = ps.integer("width", s.width);
  require(ps, "width", s.width >= 1, ">= 1", s.width);
  s.height = ps.integer("height", s.height);
  require(ps, "height", s.height >= 1, ">= 1", s.height);
  s.samples = ps.integer("samples", s.samples);
  require(ps, "samples", s.samples >= 1 && s.samples <= kMaxSamplesPerPixel,
          fmt::format("from 1 to {}", kMaxSamplesPerPixel), s.samples);
  s.max_depth = ps.integer("max_depth", s.max_depth);
  require(ps, "max_depth", s.max_depth >= 0, ">= 0", s.max_depth);
  s.background = ps.color("background", s.background);
  s.ambient_light = ps.color("ambient_light", s.ambient_light);
  non_negative_color(ps, "ambient_light", s.ambient_light);
  if (const TextureRef* env = reference<TextureRef>(ps, "environment", "settings", "texture")) s.environment = env->id;
  s.environment_ambient = ps.boolean("environment_ambient", s.environment_ambient);
  if (s.environment_ambient && s.environment == kNoId)
    throw SceneError(loc_of(ps, "environment_ambient"), "environment_ambient needs an 'environment' texture");
  s.fog_distance = ps.number("fog_distance", s.fog_distance);
  require(ps, "fog_distance", s.fog_distance >= 0, ">= 0 (0: no fog)", s.fog_distance);
  s.fog_color = ps.color("fog_color", s.fog_color);
  non_negative_color(ps, "fog_color", s.fog_color);
  s.fog_filter = ps.number("fog_filter", s.fog_filter);
  require(ps, "fog_filter", s.fog_filter >= 0 && s.fog_filter <= 1, "from 0 to 1", s.fog_filter);
  s.fog_transmit = ps.number("fog_transmit", s.fog_transmit);
  require(ps, "fog_transmit", s.fog_transmit >= 0 && s.fog_transmit <= 1, "from 0 to 1", s.fog_transmit);
  s.fog_offset = ps.number("fog_offset", s.fog_offset);
  s.fog_altitude = ps.number("fog_altitude", s.fog_altitude);
  require(ps, "fog_altitude", s.fog_altitude >= 0, ">= 0 (0: constant fog)", s.fog_altitude);
  if (const ParamValue* v = ps.value("fog_turbulence")) {
    if (const double* x = std::get_if<double>(v))
      s.fog_turbulence = Vec3(*x);
    else
      s.fog_turbulence = ps.vec3("fog_turbulence", s.fog_turbulence);
    const Vec3& t = s.fog_turbulence;
    require(ps, "fog_turbulence", t.x >= 0 && t.y >= 0 && t.z >= 0 && std::isfinite(t.x + t.y + t.z),
            "finite and >= 0 in every component", std::min({t.x, t.y, t.z}));
  }
  s.fog_turb_depth = non_negative(ps, "fog_turb_depth", ps.number("fog_turb_depth", s.fog_turb_depth));
  s.fog_octaves = ps.integer("fog_octaves", s.fog_octaves);
  require(ps, "fog_octaves", s.fog_octaves >= 1 && s.fog_octaves <= 16, "from 1 to 16", s.fog_octaves);
  s.fog_omega = ps.number("fog_omega", s.fog_omega);
  require(ps, "fog_omega", std::isfinite(s.fog_omega) && std::abs(s.fog_omega) <= 16, "finite, |omega| <= 16", s.fog_omega);
  s.fog_lambda = ps.number("fog_lambda", s.fog_lambda);
  require(ps, "fog_lambda", std::isfinite(s.fog_lambda) && std::abs(s.fog_lambda) <= 16, "finite, |lambda| <= 16",
          s.fog_lambda);
  if (ps.has("seed")) {
    double seed = ps.number("seed", 0);
    constexpr double kMaxExactWhole = 9007199254740992.0;  // 2^53: larger doubles skip integers
    require(ps, "seed", seed >= 0 && seed <= kMaxExactWhole && std::floor(seed) == seed,
            "a whole number from 0 to 2^53", seed);
    s.seed = static_cast<uint64_t>(seed);
  }
  if (ps.has("sampler")) {
    std::string name = ps.string("sampler", "sobol");
    if (!parse_sampler(name, s.sampler))
      throw SceneError(loc_of(ps, "sampler"),
                       fmt::format("unknown sampler '{}' (expected random, stratified or sobol)", name));
  }
  if (ps.has("frames")) {
    double frames = ps.number("frames", 1);
    require(ps, "frames", frames >= 1 && frames <= kMaxFrames && std::floor(frames) == frames,
            fmt::format("a whole number from 1 to {}", kMaxFrames), frames);
    s.frames = static_cast<int64_t>(frames);
  }
  output_settings(ps, s);
  if (ps.has("integrator")) {
    std::string name = ps.string("integrator", "whitted");
    if (!parse_integrator(name, s.integrator))
      throw SceneError(loc_of(ps, "integrator"),
                       fmt::format("unknown integrator '{}' (expected whitted or path)", name));
  }
  if (ps.has("light_falloff")) s.light_falloff_attenuation = second_word(ps, "light_falloff", "inverse_square", "attenuation");
  if (const ParamValue* g = ps.value("output_gamma"); g && std::holds_alternative<double>(*g)) {
    s.output_power = ps.number("output_gamma", 1.0);
    require(ps, "output_gamma", std::isfinite(s.output_power) && s.output_power >= 0.1 && s.output_power <= 10.0,
            "\"srgb\", \"linear\" or a gamma from 0.1 to 10", s.output_power);
  } else if (ps.has("output_gamma")) {
    s.output_linear = second_word(ps, "output_gamma", "srgb", "linear");
  }
  if (MediumId id = medium(ps); id != kNoId) s.medium = id;
  if (ps.has("media_samples")) {
    const int n = ps.integer("media_samples", s.media_samples);
    require(ps, "media_samples", n >= 1 && n <= 4096, "a whole number from 1 to 4096", n);
    s.media_samples = n;
  }
  s.clamp = ps.number("clamp", s.clamp);
  require(ps, "clamp", s.clamp >= 0 && std::isfinite(s.clamp), ">= 0 (0: no clamping)", s.clamp);
  s.loc = ps.loc();
  ps.check_unused(kSettingsNames);
}

void SceneBuilder::camera(ParamSet& ps) {
  CameraDesc& c = scene_.camera;
  const std::string proj = ps.string("projection", projection_name(c.projection));
  bool known = false;
  for (int i = 0; i < static_cast<int>(std::size(kProjectionNames)); ++i)
    if (proj == kProjectionNames[i]) c.projection = static_cast<Projection>(i), known = true;
  if (!known)
    throw SceneError(loc_of(ps, "projection"),
                     fmt::format("property 'projection' of camera must be \"perspective\", \"orthographic\" or one of "
                                 "POV-Ray's \"fisheye\", \"ultra_wide_angle\", \"omnimax\", \"panoramic\", "
                                 "\"cylinder1\" to \"cylinder4\", \"spherical\"; got \"{}\"",
                                 proj));
  c.position = ps.vec3("position", c.position);
  if (pov_projection(c.projection)) {
    // POV-Ray's angle: its default 90 (the spherical camera's 360 by 180, or half the given
    // horizontal sweep upwards and downwards).
    const bool spherical = c.projection == Projection::Spherical;
    c.fov = ps.number("fov", spherical ? 360.0 : 90.0);
    require(ps, "fov", c.fov > 0 && c.fov <= 360.0, "between 0 and 360 (POV-Ray's angle)", c.fov);
    c.vertical_fov = ps.number("vertical_fov", ps.has("fov") ? c.fov / 2 : 180.0);
    require(ps, "vertical_fov", c.vertical_fov > 0 && c.vertical_fov <= 360.0, "between 0 and 360", c.vertical_fov);
    if (!spherical && ps.has("vertical_fov"))
      throw SceneError(loc_of(ps, "vertical_fov"), "property 'vertical_fov' of camera applies to the spherical projection");
  } else if (ps.has("vertical_fov")) {
    throw SceneError(loc_of(ps, "vertical_fov"), "property 'vertical_fov' of camera applies to the spherical projection");
  }
  if (ps.has("direction")) {
    given_vectors_camera(ps, c);
    return;
  }
  if (ps.has("right"))
    throw SceneError(loc_of(ps, "right"),
                     "property 'right' of camera applies only with 'direction' (POV-Ray's camera: the image plane "
                     "is direction + x·right + y·up); add 'direction' or remove 'right'");
  c.given_vectors = false;
  c.look_at = ps.vec3("look_at", c.look_at);
  c.up = direction(ps, "up", ps.vec3("up", c.up));
  if (!pov_projection(c.projection)) c.fov = ps.number("fov", c.fov);
  std::string axis = ps.string("fov_axis", c.fov_vertical ? "vertical" : "horizontal");
  if (axis != "horizontal" && axis != "vertical")
    throw SceneError(loc_of(ps, "fov_axis"),
                     fmt::format("property 'fov_axis' of camera must be \"horizontal\" or \"vertical\", got \"{}\"", axis));
  c.fov_vertical = axis == "vertical";
  std::string hand = ps.string("handedness", c.right_handed ? "right" : "left");
  if (hand != "left" && hand != "right")
    throw SceneError(loc_of(ps, "handedness"),
                     fmt::format("property 'handedness' of camera must be \"left\" or \"right\", got \"{}\"", hand));
  c.right_handed = hand == "right";
  if (!pov_projection(c.projection))
    require(ps, "fov", c.fov > 0 && c.fov < kMaxFovDegrees, "between 0 and 180 (exclusive)", c.fov);
  c.view_width = positive(ps, "view_width", ps.number("view_width", c.view_width));
  c.aperture = non_negative(ps, "aperture", ps.number("aperture", c.aperture));
  c.focus_distance = non_negative(ps, "focus_distance", ps.number("focus_distance", c.focus_distance));
  // Only equal points give no direction: a scene modelled at 1e-13 (or 1e-150) units has a
  // short view vector, and unit_vector below normalises it without underflow.
  if (!(scaled_length(c.look_at - c.position) > 0.0))
    ps.fail_block("camera position and look_at must differ");
  if (glm::length(glm::cross(unit_vector(c.look_at - c.position), unit_vector(c.up))) < kMinDirectionLength)
    ps.fail_block("camera up must not be parallel to the viewing direction");
  c.loc = ps.loc();
  scene_.has_camera = true;
  ps.check_unused(kCameraNames);
}

// POV-Ray's camera: direction, right and up as given (not orthogonalised; their lengths set
// the field of view and the aspect ratio). What only the look_at camera uses is an error here,
// so a scene says one thing.
void SceneBuilder::given_vectors_camera(ParamSet& ps, CameraDesc& c) {
  for (std::string_view name : {"look_at", "fov", "fov_axis", "handedness", "view_width"})
    if (ps.has(name) && !(name == "fov" && pov_projection(c.projection)))  // POV-Ray's angle
      throw SceneError(loc_of(ps, name),
                       fmt::format("property '{}' of camera does not apply with 'direction': the image plane is "
                                   "direction + x·right + y·up as given (their lengths set the view); "
                                   "remove '{}' or 'direction'",
                                   name, name));
  c.given_vectors = true;
  c.direction = direction(ps, "direction", ps.require_vec3("direction"));
  c.right = direction(ps, "right", ps.vec3("right", c.right));
  c.up = direction(ps, "up", ps.vec3("up", c.up));
  c.aperture = non_negative(ps, "aperture", ps.number("aperture", c.aperture));
  c.focus_distance = non_negative(ps, "focus_distance", ps.number("focus_distance", c.focus_distance));
  const Vec3 r = unit_vector(c.right), u = unit_vector(c.up), d = unit_vector(c.direction);
  if (glm::length(glm::cross(r, u)) < kMinDirectionLength)
    ps.fail_block("camera right and up must not be parallel: they span the image plane");
  if (std::abs(glm::dot(d, glm::cross(r, u))) < kMinDirectionLength)
    ps.fail_block("camera direction must not lie in the plane of right and up: the rays would not leave it");
  c.loc = ps.loc();
  scene_.has_camera = true;
  ps.check_unused(kCameraNames);
}

TextureId SceneBuilder::texture(std::string_view kind, ParamSet& ps, const Mat4& transform) {
  TextureDesc t;
  t.transform = transform;
  t.loc = ps.loc();
  auto image_options = [&] {
    std::string space = ps.string("color_space", "srgb");
    if (space != "srgb" && space != "linear")
      throw SceneError(loc_of(ps, "color_space"),
                       fmt::format("property 'color_space' of {} must be \"srgb\" or \"linear\", got \"{}\"", kind, space));
    t.linear = space == "linear";
    std::string filter = ps.string("filter", "bilinear");
    if (filter != "bilinear" && filter != "nearest")
      throw SceneError(loc_of(ps, "filter"),
                       fmt::format("property 'filter' of {} must be \"bilinear\" or \"nearest\", got \"{}\"", kind, filter));
    t.filter = filter == "nearest" ? TextureFilter::Nearest : TextureFilter::Bilinear;
  };
  if (kind == "latlong_map") {
    t.kind = TextureKind::LatLong;
    std::string file = ps.require_string("file");
    t.image_path = resolve_path(file, loc_of(ps, "file"));
    check_readable(t.image_path, file, "image", loc_of(ps, "file"));
    image_options();
    ps.check_unused(kLatLongNames);
  } else if (kind == "cube_map") {
    t.kind = TextureKind::CubeMap;
    std::string shown = ps.require_string("directory");
    std::string dir = resolve_path(shown, loc_of(ps, "directory"));
    // The folder itself is checked against the read rule (its faces lie inside it).
    if (!read_policy_.allows(dir)) throw SceneError(loc_of(ps, "directory"), read_policy_.refusal(shown, dir));
    t.face_paths = cube_map_faces(dir, shown, loc_of(ps, "directory"));
    for (const std::string& face : t.face_paths) check_readable(face, face, "cube_map face", loc_of(ps, "directory"));
    image_options();
    const std::string orientation = ps.string("orientation", "rts");
    if (orientation != "rts" && orientation != "mit")
      throw SceneError(loc_of(ps, "orientation"),
                       fmt::format("property 'orientation' of cube_map must be \"rts\" or \"mit\", got \"{}\"",
                                   orientation));
    t.cube_mit = orientation == "mit";
    ps.check_unused(kCubeMapNames);
  } else if (kind == "image_texture") {
    t.kind = TextureKind::Image;
    std::string file = ps.require_string("file");
    t.image_path = resolve_path(file, loc_of(ps, "file"));
    check_readable(t.image_path, file, "image", loc_of(ps, "file"));
    image_options();
    t.mapping = ps.string("mapping", "uv");
    if (t.mapping != "uv" && t.mapping != "planar" && t.mapping != "spherical")
      throw SceneError(
          loc_of(ps, "mapping"),
          fmt::format("property 'mapping' of image_texture must be \"uv\", \"planar\" or \"spherical\", got \"{}\"",
                      t.mapping));
    ps.check_unused(kImageTextureNames);
  } else if (is_pattern_kind(kind)) {
    build_pattern_texture(kind, ps, t);
  } else if (kind == "gradient" && ps.has("color_map")) {
    // POV-Ray's `gradient y color_map { ... }`: the pattern form, with turbulence and waves.
    const int axis = axis_of(ps);
    build_pattern_texture(kind, ps, t);
    t.pattern.axis = axis;
  } else if (kind == "sky_sphere") {
    sky_sphere(ps, t);
  } else {
    if (kind == "checker")
      t.kind = TextureKind::Checker;
    else if (kind == "stripes")
      t.kind = TextureKind::Stripes;
    else if (kind == "gradient")
      t.kind = TextureKind::Gradient;
    else
      ps.fail_block(fmt::format("'{}' is not a texture", kind));
    t.color1 = ps.color("color1", t.color1);
    t.color2 = ps.color("color2", t.color2);
    t.scale = positive(ps, "scale", ps.number("scale", t.scale));
    if (kind == "checker") {
      ps.check_unused(kCheckerNames);
    } else {
      t.axis = axis_of(ps);
      ps.check_unused(kPatternTextureNames);
    }
  }
  scene_.textures.push_back(std::move(t));
  return static_cast<TextureId>(scene_.textures.size() - 1);
}

void SceneBuilder::sky_sphere(ParamSet& ps, TextureDesc& t) {
  t.kind = TextureKind::SkySphere;
  ps.set_valid_names(&kSkySphereNames);   // a misspelt 'layers' is reported as such
  const ParamValue* v = ps.value("layers");
  if (!v) ps.fail_block("sky_sphere needs property 'layers' (its textures, bottom first: layers = [gradient { ... }])");
  LayersParam layers;
  if (auto* list = std::get_if<LayersParam>(v))
    layers = *list;
  else if (auto* one = std::get_if<TextureRef>(v))
    layers = LayersParam{{one->id}, {Color(0.0)}};
  else if (auto* colors = std::get_if<std::vector<Vec3>>(v)) {
    // A list of solid colours only (`layers = [rgb(0.8, 0.9, 1)]`): colours travel as vectors.
    for (const Vec3& c : *colors) {
      layers.textures.push_back(kNoId);
      layers.colors.emplace_back(c.x, c.y, c.z);
    }
  } else if (std::holds_alternative<Color>(*v) || std::holds_alternative<Vec3>(*v) || std::holds_alternative<double>(*v))
    layers = LayersParam{{kNoId}, {ps.color("layers", Color(0.0))}};
  else
    ps.fail(*ps.find("layers"), fmt::format("property 'layers' of sky_sphere expects a list of textures (and colors), "
                                            "got a {}", param_type_name(*v)));
  for (std::size_t i = 0; i < layers.textures.size(); ++i) {
    const TextureId id = layers.textures[i];
    if (id == kNoId) {
      non_negative_color(ps, "layers", layers.colors[i]);
      continue;
    }
    const TextureKind k = scene_.textures[id].kind;
    if (k != TextureKind::Pattern && k != TextureKind::Gradient && k != TextureKind::Checker &&
        k != TextureKind::Stripes)
      ps.fail(*ps.find("layers"),
              fmt::format("layer {} of sky_sphere is {}: a sky's layers are procedural textures (gradient, bozo, "
                          "granite, ...) and colors; for an image sky, set the environment to a latlong_map",
                          i + 1, k == TextureKind::SkySphere ? "a sky_sphere" : "an image texture"));
  }
  t.sky_layers = std::move(layers.textures);
  t.sky_layer_colors = std::move(layers.colors);
  ps.check_unused(kSkySphereNames);
  ps.set_valid_names(nullptr);
}

}  // namespace rts::render
