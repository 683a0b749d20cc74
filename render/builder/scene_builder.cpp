// SceneBuilder: validates block parameters and fills the SceneDesc.
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
#include "render/geometry/tolerances.hpp"

namespace rts::render {

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
    {"pattern", BlockCategory::Texture},
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
};

// The property names each block kind accepts (for unknown-name checks and suggestions), from
// the tables in block_properties.cpp.
std::vector<std::string_view> names_of_block(std::string_view kind) {
  return property_names(find_block_info(kind)->properties);
}
const std::vector<std::string_view> kSettingsNames = names_of_block("settings");
const std::vector<std::string_view> kCameraNames = names_of_block("camera");
const std::vector<std::string_view> kImageTextureNames = names_of_block("image_texture");
const std::vector<std::string_view> kLatLongNames = names_of_block("latlong_map");
const std::vector<std::string_view> kCubeMapNames = names_of_block("cube_map");
const std::vector<std::string_view> kSkySphereNames = names_of_block("sky_sphere");
const std::vector<std::string_view> kCheckerNames = names_of_block("checker");
const std::vector<std::string_view> kPatternTextureNames = names_of_block("stripes");
const std::vector<std::string_view> kMaterialNames = names_of_block("material");
// "material" and each shape kind's own properties, by ShapeGeometry index.
const std::array<std::vector<std::string_view>, kShapeKindCount>& shape_property_names() {
  static const auto table = [] {
    std::array<std::vector<std::string_view>, kShapeKindCount> names;
    for (std::size_t k = 0; k < kShapeKindCount; ++k) {
      names[k].push_back("material");
      for (const PropertyInfo& p : kShapeInfos[k].properties) names[k].push_back(p.name);
    }
    return names;
  }();
  return table;
}
template <class T>
const std::vector<std::string_view>& names_of() {
  return shape_property_names()[shape_index<T>()];
}
const std::vector<std::string_view> kPointLightNames = names_of_block("point_light");
const std::vector<std::string_view> kSpotLightNames = names_of_block("spot_light");
const std::vector<std::string_view> kDirectionalLightNames = names_of_block("directional_light");
const std::vector<std::string_view> kAreaLightNames = names_of_block("area_light");

const std::vector<std::string_view> kCsgNames = names_of_block("union");
const std::vector<std::string_view> kGroupNames = names_of_block("group");

// The names a shape, light or CSG kind takes, or null for other kinds.
const std::vector<std::string_view>* names_of(std::string_view kind) {
  for (std::size_t k = 0; k < kShapeKindCount; ++k)
    if (kShapeInfos[k].name == kind) return &shape_property_names()[k];
  static const std::pair<std::string_view, const std::vector<std::string_view>*> kTable[] = {
      {"point_light", &kPointLightNames},  {"spot_light", &kSpotLightNames}, {"area_light", &kAreaLightNames},
      {"directional_light", &kDirectionalLightNames}, {"union", &kCsgNames}, {"intersection", &kCsgNames},
      {"difference", &kCsgNames},          {"merge", &kCsgNames},         {"group", &kGroupNames}};
  for (const auto& [name, names] : kTable)
    if (name == kind) return names;
  return nullptr;
}

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

// Paths in a scene are relative to the file that names them.
std::string resolve_path(const std::string& path, SourceRef where) {
  namespace fs = std::filesystem;
  fs::path p(path);
  if (p.is_absolute() || where.file == nullptr || where.file[0] == '\0') return path;
  return (fs::path(where.file).parent_path() / p).lexically_normal().string();
}

// The same file however a scene spells it ("a/../m.obj", "./m.obj", through a symlink).
std::string cache_key(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::path(path), ec);
  if (ec) p = fs::absolute(fs::path(path), ec).lexically_normal();
  return ec ? path : p.string();
}

bool is_obj_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj";
}

// The reference in property `name` (a shape's material, a material's texture), or null when
// it is absent: "property 'material' of sphere expects a material, got a number".
template <typename Ref>
const Ref* reference(ParamSet& ps, std::string_view name, std::string_view block, std::string_view what) {
  const ParamValue* v = ps.value(name);
  if (!v) return nullptr;
  auto* ref = std::get_if<Ref>(v);
  if (!ref)
    ps.fail(*ps.find(name),
            fmt::format("property '{}' of {} expects a {}, got a {}", name, block, what, param_type_name(*v)));
  return ref;
}

// Appends a scene node for the shape, light or group at `index`; returns its id.
NodeId add_node(SceneDesc& scene, NodeKind kind, std::size_t index, SourceRef loc) {
  scene.nodes.push_back(Node{kind, static_cast<uint32_t>(index), loc});
  return static_cast<NodeId>(scene.nodes.size() - 1);
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
  s.fog_offset = ps.number("fog_offset", s.fog_offset);
  s.fog_altitude = ps.number("fog_altitude", s.fog_altitude);
  require(ps, "fog_altitude", s.fog_altitude >= 0, ">= 0 (0: constant fog)", s.fog_altitude);
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
  if (ps.has("output_gamma")) {
    std::string name = ps.string("output_gamma", "srgb");
    if (name != "srgb" && name != "linear")
      throw SceneError(loc_of(ps, "output_gamma"),
                       fmt::format("unknown output_gamma '{}' (expected srgb or linear)", name));
    s.output_linear = name == "linear";
  }
  s.clamp = ps.number("clamp", s.clamp);
  require(ps, "clamp", s.clamp >= 0 && std::isfinite(s.clamp), ">= 0 (0: no clamping)", s.clamp);
  s.loc = ps.loc();
  ps.check_unused(kSettingsNames);
}

void SceneBuilder::camera(ParamSet& ps) {
  CameraDesc& c = scene_.camera;
  std::string proj = ps.string("projection", c.projection == Projection::Perspective ? "perspective" : "orthographic");
  if (proj == "perspective")
    c.projection = Projection::Perspective;
  else if (proj == "orthographic")
    c.projection = Projection::Orthographic;
  else
    throw SceneError(
        loc_of(ps, "projection"),
        fmt::format("property 'projection' of camera must be \"perspective\" or \"orthographic\", got \"{}\"", proj));
  c.position = ps.vec3("position", c.position);
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
  c.fov = ps.number("fov", c.fov);
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
  require(ps, "fov", c.fov > 0 && c.fov < kMaxFovDegrees, "between 0 and 180 (exclusive)", c.fov);
  c.view_width = positive(ps, "view_width", ps.number("view_width", c.view_width));
  c.aperture = non_negative(ps, "aperture", ps.number("aperture", c.aperture));
  c.focus_distance = non_negative(ps, "focus_distance", ps.number("focus_distance", c.focus_distance));
  if (glm::length(c.look_at - c.position) < kMinDirectionLength)
    ps.fail_block("camera position and look_at must differ");
  if (glm::length(glm::cross(glm::normalize(c.look_at - c.position), glm::normalize(c.up))) < kMinDirectionLength)
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
    if (ps.has(name))
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
  const Vec3 r = glm::normalize(c.right), u = glm::normalize(c.up), d = glm::normalize(c.direction);
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
  else if (std::holds_alternative<Color>(*v) || std::holds_alternative<Vec3>(*v) || std::holds_alternative<double>(*v))
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

MaterialId SceneBuilder::material(ParamSet& ps) {
  MaterialDesc m;
  m.loc = ps.loc();
  for (const Param& p : ps.params())
    if (auto* t = std::get_if<TextureRef>(&p.value); t && t->id < scene_.textures.size() &&
                                                      scene_.textures[t->id].kind == TextureKind::SkySphere)
      ps.fail(p, fmt::format("property '{}' of material holds a sky_sphere: a sky is the background, set it as "
                             "settings {{ environment = ... }}",
                             p.name));
  if (const ParamValue* c = ps.value("color")) {
    if (auto* t = std::get_if<TextureRef>(c))
      m.texture = t->id;
    else
      m.color = ps.color("color", m.color);
  }
  if (const TextureRef* ref = reference<TextureRef>(ps, "texture", "material", "texture")) m.texture = ref->id;
  // A channel holding a texture takes its value from the texture at each point.
  auto channel_texture = [&](std::string_view name, TextureId& id) {
    const ParamValue* v = ps.value(name);
    if (auto* t = v ? std::get_if<TextureRef>(v) : nullptr) {
      id = t->id;
      return true;
    }
    return false;
  };
  if (!channel_texture("emission", m.emission_texture)) {
    m.emission = ps.color("emission", m.emission);
    non_negative_color(ps, "emission", m.emission);
  }
  m.ambient = non_negative(ps, "ambient", ps.number("ambient", m.ambient));
  if (channel_texture("diffuse", m.diffuse_texture))
    m.diffuse = 1.0;
  else
    m.diffuse = non_negative(ps, "diffuse", ps.number("diffuse", m.diffuse));
  if (channel_texture("specular", m.specular_texture)) {
    m.specular = 1.0;
  } else if (const ParamValue* sv = ps.value("specular")) {
    if (const double* d = std::get_if<double>(sv)) {
      m.specular = non_negative(ps, "specular", *d);
    } else {
      // A color tints the highlight (the courses' `specularColor`): weight 1, that color.
      m.specular = 1.0;
      m.specular_color = ps.color("specular", m.specular_color);
      non_negative_color(ps, "specular", m.specular_color);
    }
  }
  m.shininess = non_negative(ps, "shininess", ps.number("shininess", m.shininess));
  if (ps.has("highlight")) {
    std::string lobe = ps.string("highlight", "phong");
    if (lobe != "phong" && lobe != "blinn")
      throw SceneError(loc_of(ps, "highlight"), fmt::format("unknown highlight '{}' (expected phong or blinn)", lobe));
    m.blinn = lobe == "blinn";
  }
  if (!channel_texture("reflect", m.reflect_texture)) {
    m.reflect = ps.color("reflect", m.reflect);
    non_negative_color(ps, "reflect", m.reflect);
  }
  if (!channel_texture("transmit", m.transmit_texture)) {
    m.transmit = ps.color("transmit", m.transmit);
    non_negative_color(ps, "transmit", m.transmit);
  } else {
    // Where the texture is black the surface is opaque, but shadow rays must still test it.
    m.transmit = Color(1.0);
  }
  if (const TextureRef* b = reference<TextureRef>(ps, "bump", "material", "texture")) m.bump = b->id;
  m.bump_scale = ps.number("bump_scale", m.bump_scale);
  if (!std::isfinite(m.bump_scale)) require(ps, "bump_scale", false, "finite", m.bump_scale);
  if (const TextureRef* n = reference<TextureRef>(ps, "normal_map", "material", "texture")) m.normal_map = n->id;
  if (m.bump != kNoId && m.normal_map != kNoId) ps.fail_block("material takes 'bump' or 'normal_map', not both");
  m.ior = positive(ps, "ior", ps.number("ior", m.ior));
  m.ior_relative = ps.boolean("ior_relative", m.ior_relative);
  m.fresnel = ps.boolean("fresnel", m.fresnel);
  m.roughness = non_negative(ps, "roughness", ps.number("roughness", m.roughness));
  ps.check_unused(kMaterialNames);
  scene_.materials.push_back(std::move(m));
  return static_cast<MaterialId>(scene_.materials.size() - 1);
}

namespace {

uint32_t mesh_index(ParamSet& ps, double v, std::size_t vertex_count) {
  if (std::floor(v) != v || v < 0 || v >= static_cast<double>(vertex_count))
    throw SceneError(loc_of(ps, "faces"),
                     fmt::format("mesh face index {} out of range ({} vertices)", v, vertex_count));
  return static_cast<uint32_t>(v);
}

// `vertices`/`faces`/`normals` are lists of vectors; an empty list arrives as numbers.
std::vector<Vec3> vector_list(ParamSet& ps, std::string_view name) {
  const ParamValue* v = ps.value(name);
  if (!v) return {};
  if (auto* l = std::get_if<std::vector<Vec3>>(v)) return *l;
  if (auto* l = std::get_if<std::vector<double>>(v); l && l->empty()) return {};
  throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} expects a list of vectors, got a {}", name,
                                                 ps.kind(), param_type_name(*v)));
}

// Per-vertex material lists of a triangle or mesh (`vertex_colors`, `vertex_diffuse`,
// `vertex_specular`, `vertex_shininess`), each absent or one entry per vertex; false when the
// block has none of them.
bool vertex_material(ParamSet& ps, std::size_t vertex_count, MeshData& mesh) {
  bool any = false;
  auto count_check = [&](std::string_view name, std::size_t n) {
    if (n != vertex_count)
      throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} has {} entries for {} vertices", name,
                                                     ps.kind(), n, vertex_count));
    any = true;
  };
  // A list of colors, one per vertex, none negative.
  auto colors_into = [&](std::string_view name, std::vector<glm::vec3>& out) {
    std::vector<Vec3> colors = vector_list(ps, name);
    count_check(name, colors.size());
    for (const Vec3& c : colors) {
      if (!(c.x >= 0 && c.y >= 0 && c.z >= 0) || !std::isfinite(c.x + c.y + c.z))
        throw SceneError(loc_of(ps, name), fmt::format("property '{}' must not be negative", name));
      out.emplace_back(c);
    }
  };
  if (ps.has("vertex_colors")) colors_into("vertex_colors", mesh.colors);
  // `vertex_specular`: numbers (white highlights of that weight) or colors (tinted ones, as
  // CSCI 420's per-vertex `spe` and UW's per-vertex `specular`).
  if (ps.has("vertex_specular")) {
    const ParamValue* v = ps.value("vertex_specular");
    if (const auto* numbers = std::get_if<std::vector<double>>(v)) {
      count_check("vertex_specular", numbers->size());
      for (double x : *numbers) {
        require(ps, "vertex_specular", x >= 0 && std::isfinite(x), ">= 0", x);
        mesh.specular.emplace_back(static_cast<float>(x));
      }
    } else if (std::get_if<std::vector<Vec3>>(v)) {
      colors_into("vertex_specular", mesh.specular);
    } else {
      throw SceneError(loc_of(ps, "vertex_specular"),
                       fmt::format("property 'vertex_specular' of {} expects a list of numbers or colors, got a {}",
                                   ps.kind(), param_type_name(*v)));
    }
  }
  for (auto [name, out] : {std::pair<std::string_view, std::vector<float>*>{"vertex_diffuse", &mesh.diffuse},
                           {"vertex_shininess", &mesh.shininess}}) {
    if (!ps.has(name)) continue;
    const ParamValue* v = ps.value(name);
    auto* list = std::get_if<std::vector<double>>(v);
    if (!list)
      throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} expects a list of numbers, got a {}", name,
                                                     ps.kind(), param_type_name(*v)));
    count_check(name, list->size());
    for (double x : *list) {
      require(ps, name, x >= 0 && std::isfinite(x), ">= 0", x);
      out->push_back(static_cast<float>(x));
    }
  }
  return any;
}

// Zero area by the renderer's own test (the angle between the edges below
// tol::kTriangleDeterminant): such triangles are never hit.
bool degenerate_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 e1 = b - a, e2 = c - a;
  Vec3 n = glm::cross(e1, e2);
  double k = tol::kTriangleDeterminant;
  return !(glm::dot(n, n) > k * k * glm::dot(e1, e1) * glm::dot(e2, e2));
}

// One warning per mesh: how many faces are skipped and how many vertex normals cannot be
// used (zero length or NaN: the face normal shades there instead).
void warn_degenerate(const MeshData& mesh, SourceRef where, std::vector<Warning>& warnings) {
  std::size_t faces = mesh.indices.size() / 3, skipped = 0, first = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    const uint32_t* i = &mesh.indices[f * 3];
    if (i[0] >= mesh.positions.size() || i[1] >= mesh.positions.size() || i[2] >= mesh.positions.size()) continue;
    if (degenerate_triangle(Vec3(mesh.positions[i[0]]), Vec3(mesh.positions[i[1]]), Vec3(mesh.positions[i[2]])) &&
        skipped++ == 0)
      first = f;
  }
  if (skipped > 0)
    warnings.push_back({where, fmt::format("mesh: {} of {} faces have zero area (collinear or repeated vertices; "
                                           "first: face {}): they are skipped",
                                           skipped, faces, first)});
  std::size_t bad_normals = 0;
  for (const glm::vec3& n : mesh.normals) {
    float len2 = glm::dot(n, n);
    if (!(len2 > 0.0f) || !std::isfinite(len2)) ++bad_normals;
  }
  if (bad_normals > 0)
    warnings.push_back({where, fmt::format("mesh: {} of {} vertex normals are zero or not finite: the face normal "
                                           "is used there",
                                           bad_normals, mesh.normals.size())});
}

// The kinds whose descriptor builds them from their parameters alone (ShapeTraits<T>::build):
// true when `kind` is one of them and `out` is built. Triangles and meshes, which may create
// MeshData, are built by SceneBuilder::shape itself.
template <std::size_t... I>
bool build_described(std::index_sequence<I...>, std::string_view kind, ParamSet& ps, ShapeGeometry& out) {
  return ((kShapeInfos[I].name == kind && [&] {
            using T = ShapeKind<I>;
            if constexpr (requires { ShapeTraits<T>::build(ps); }) {
              out = ShapeTraits<T>::build(ps);
              ps.check_unused(names_of<T>());
              return true;
            } else {
              return false;
            }
          }()) ||
          ...);
}

}  // namespace

NodeId SceneBuilder::shape(std::string_view kind, ParamSet& ps) {
  ShapeDesc s;
  s.loc = ps.loc();
  ps.set_valid_names(names_of(kind));  // a missing property is first checked for a misspelling
  if (const MaterialRef* ref = reference<MaterialRef>(ps, "material", kind, "material")) s.material = ref->id;
  // `inverse` (for CSG) is read first, on solids only: an open shape's `inverse` stays an
  // unknown property, and the names each kind lists stay its descriptor's.
  if (const ShapeInfo* info = find_shape(kind); info && info->closure != Closure::Open)
    s.inverse = ps.boolean("inverse", false);
  if (build_described(std::make_index_sequence<kShapeKindCount>(), kind, ps, s.geometry)) {
    // built by its descriptor
  } else if (kind == "triangle") {
    Triangle g;
    g.v0 = ps.require_vec3("v0");
    g.v1 = ps.require_vec3("v1");
    g.v2 = ps.require_vec3("v2");
    int normals = ps.has("n0") + ps.has("n1") + ps.has("n2");
    if (normals != 0 && normals != 3) ps.fail_block("triangle needs all of n0, n1, n2 or none of them");
    if (normals == 3) {
      g.has_normals = true;
      g.n0 = ps.vec3("n0", Vec3(0.0));
      g.n1 = ps.vec3("n1", Vec3(0.0));
      g.n2 = ps.vec3("n2", Vec3(0.0));
    }
    auto mesh = std::make_shared<MeshData>();
    if (vertex_material(ps, 3, *mesh)) {
      // A triangle whose vertices carry material values is traced as a one-triangle mesh,
      // which knows how to interpolate them.
      for (const Vec3& v : {g.v0, g.v1, g.v2}) mesh->positions.emplace_back(v);
      if (g.has_normals)
        for (const Vec3& n : {g.n0, g.n1, g.n2}) mesh->normals.emplace_back(glm::normalize(n));
      mesh->indices = {0, 1, 2};
      scene_.meshes.push_back(std::move(mesh));
      s.geometry = MeshRef{static_cast<MeshId>(scene_.meshes.size() - 1), g.has_normals};
    } else {
      if (degenerate_triangle(g.v0, g.v1, g.v2))
        scene_.warnings.push_back({ps.loc(), "triangle has zero area (collinear or repeated vertices): it is skipped"});
      s.geometry = g;
    }
    ps.check_unused(names_of<Triangle>());
  } else if (kind == "height_field") {
    std::string path;
    if (ps.has("file")) {
      SourceRef where = loc_of(ps, "file");
      std::string file = ps.string("file", "");
      path = resolve_path(file, where);
      check_readable(path, file, "height_field image", where);
    }
    s.geometry = build_height_field(ps, path, limits_.max_memory);
    ps.check_unused(names_of<HeightField>());
  } else if (kind == "mesh") {
    MeshRef g;
    g.smooth = ps.boolean("smooth", g.smooth);
    const std::string weights = ps.string("smooth_weights", "area");
    if (weights != "area" && weights != "equal")
      throw SceneError(loc_of(ps, "smooth_weights"),
                       fmt::format("property 'smooth_weights' of mesh must be \"area\" or \"equal\", got \"{}\"",
                                   weights));
    const bool equal_weights = weights == "equal";
    std::shared_ptr<MeshData> mesh;
    std::optional<std::pair<std::string, int>> obj_key;
    if (ps.has("file")) {
      if (ps.has("vertices") || ps.has("faces"))
        ps.fail_block("mesh takes either 'file' or 'vertices' and 'faces', not both");
      SourceRef where = loc_of(ps, "file");
      std::string file = ps.string("file", "");
      std::string path = resolve_path(file, where);
      check_readable(path, file, "mesh file", where);
      obj_key = std::make_pair(cache_key(path), g.smooth ? (equal_weights ? 2 : 1) : 0);
      // Errors quote lines of a malformed OBJ, so no other kind of file is read as one
      // (`file = "/etc/shadow"` must not show its lines). Checked after links are resolved.
      if (!is_obj_name(obj_key->first))
        throw SceneError(where, fmt::format("cannot read mesh file '{}': mesh files must be Wavefront OBJ files named "
                                            "*.obj",
                                            file));
      if (auto it = obj_meshes_.find(*obj_key); it != obj_meshes_.end()) {
        g.mesh = it->second;  // already loaded (and counted against the triangle limit): share it
      } else {
        ObjLimits limits;
        limits.max_triangles = limits_.max_mesh_triangles - std::min(mesh_triangles_, limits_.max_mesh_triangles);
        limits.max_memory = limits_.max_memory;
        mesh = load_obj(path, file, g.smooth && !equal_weights, where, limits);
        if (g.smooth && equal_weights && mesh->normals.empty()) compute_smooth_normals(*mesh, true);
      }
      for (std::string_view name : {"vertex_colors", "vertex_diffuse", "vertex_specular", "vertex_shininess"})
        if (ps.has(name))
          throw SceneError(loc_of(ps, name), fmt::format("property '{}' of mesh needs inline 'vertices' (OBJ files "
                                                         "carry their own vertex colors: v x y z r g b)", name));
    } else {
      if (!ps.has("vertices")) ps.fail_block("mesh needs property 'file' or 'vertices' and 'faces'");
      if (!ps.has("faces")) ps.fail_block("mesh needs property 'faces'");
      std::vector<Vec3> vertices = vector_list(ps, "vertices");
      std::vector<Vec3> faces = vector_list(ps, "faces");
      std::vector<Vec3> normals = vector_list(ps, "normals");
      if (faces.empty()) throw SceneError(loc_of(ps, "faces"), "mesh needs at least one face");
      if (!normals.empty() && normals.size() != vertices.size())
        throw SceneError(loc_of(ps, "normals"),
                         fmt::format("mesh has {} vertices but {} normals", vertices.size(), normals.size()));
      mesh = std::make_shared<MeshData>();
      // Stored as float relative to the centre of the vertices' bounds (MeshData::origin).
      AABB box;
      for (const Vec3& v : vertices) box.extend(v);
      if (box.valid() && box.finite()) mesh->origin = box.centroid();
      for (const Vec3& v : vertices) mesh->positions.emplace_back(v - mesh->origin);
      for (const Vec3& n : normals) mesh->normals.emplace_back(glm::normalize(n));
      for (const Vec3& f : faces)
        for (int k = 0; k < 3; ++k) mesh->indices.push_back(mesh_index(ps, f[k], vertices.size()));
      if (normals.empty() && g.smooth) compute_smooth_normals(*mesh, equal_weights);
      vertex_material(ps, vertices.size(), *mesh);
    }
    if (mesh) warn_degenerate(*mesh, ps.loc(), scene_.warnings);
    if (mesh) {  // newly built or loaded
      mesh_triangles_ += mesh->indices.size() / 3;
      if (mesh_triangles_ > limits_.max_mesh_triangles)
        ps.fail_block(fmt::format("meshes have more than {} triangles in total (raise with --max-mesh-triangles)",
                                  limits_.max_mesh_triangles));
      scene_.meshes.push_back(std::move(mesh));
      g.mesh = static_cast<MeshId>(scene_.meshes.size() - 1);
      if (obj_key) obj_meshes_.emplace(std::move(*obj_key), g.mesh);
    }
    s.geometry = g;
    ps.check_unused(names_of<MeshRef>());
  } else {
    ps.fail_block(fmt::format("'{}' is not a shape", kind));
  }
  scene_.shapes.push_back(std::move(s));
  return add_node(scene_, NodeKind::Shape, scene_.shapes.size() - 1, ps.loc());
}

NodeId SceneBuilder::light(std::string_view kind, ParamSet& ps) {
  LightDesc l;
  l.loc = ps.loc();
  ps.set_valid_names(names_of(kind));  // a missing property is first checked for a misspelling
  l.color = ps.color("color", l.color);
  non_negative_color(ps, "color", l.color);
  l.intensity = non_negative(ps, "intensity", ps.number("intensity", l.intensity));
  l.shadows = ps.boolean("shadows", l.shadows);
  auto attenuation = [&] {
    l.attenuation = ps.vec3("attenuation", l.attenuation);
    const Vec3& a = l.attenuation;
    if (a.x < 0 || a.y < 0 || a.z < 0 || a.x + a.y + a.z <= 0)
      throw SceneError(loc_of(ps, "attenuation"),
                       "property 'attenuation' must have non-negative components, not all zero");
    l.attenuation_clamp = ps.boolean("attenuation_clamp", l.attenuation_clamp);
  };
  if (kind == "point_light") {
    l.kind = LightKind::Point;
    l.position = ps.require_vec3("position");
    attenuation();
    ps.check_unused(kPointLightNames);
  } else if (kind == "spot_light") {
    l.kind = LightKind::Spot;
    l.position = ps.require_vec3("position");
    l.point_at = ps.require_vec3("point_at");
    direction(ps, "point_at", l.point_at - l.position);
    l.radius = ps.number("radius", l.radius);
    // 90: full intensity over the whole front half-space (POV-Ray scenes use it).
    require(ps, "radius", l.radius > 0 && l.radius <= 90, "above 0 and at most 90 degrees", l.radius);
    l.falloff = ps.number("falloff", std::max(l.falloff, l.radius));
    require(ps, "falloff", l.falloff >= l.radius && l.falloff <= 90, ">= radius and <= 90 degrees", l.falloff);
    attenuation();
    ps.check_unused(kSpotLightNames);
  } else if (kind == "directional_light") {
    l.kind = LightKind::Directional;
    l.direction = glm::normalize(direction(ps, "direction", ps.require_vec3("direction")));
    ps.check_unused(kDirectionalLightNames);
  } else if (kind == "area_light") {
    l.kind = LightKind::Area;
    l.position = ps.require_vec3("position");
    l.u = direction(ps, "u", ps.require_vec3("u"));
    l.v = direction(ps, "v", ps.require_vec3("v"));
    l.auto_samples = !ps.has("samples");
    l.samples = ps.integer("samples", l.samples);
    require(ps, "samples", l.samples >= 1, ">= 1", l.samples);
    if (l.samples > kMaxAreaSamples) {
      warnings_.push_back(SceneWarning{loc_of(ps, "samples"),
                                       fmt::format("area_light samples {} is more than {}; {} are used",
                                                   l.samples, kMaxAreaSamples, kMaxAreaSamples)});
      l.samples = kMaxAreaSamples;
    }
    l.disc = ps.boolean("disc", l.disc);
    attenuation();
    ps.check_unused(kAreaLightNames);
  } else {
    ps.fail_block(fmt::format("'{}' is not a light", kind));
  }
  scene_.lights.push_back(std::move(l));
  return add_node(scene_, NodeKind::Light, scene_.lights.size() - 1, ps.loc());
}

NodeId SceneBuilder::group(std::vector<Child> children, SourceRef loc) {
  scene_.groups.push_back(GroupDesc{std::move(children), kNoId});
  return add_node(scene_, NodeKind::Group, scene_.groups.size() - 1, loc);
}

NodeId SceneBuilder::group(std::vector<Child> children, ParamSet& ps) {
  ps.set_valid_names(&kGroupNames);
  GroupDesc g{std::move(children), kNoId};
  if (const MaterialRef* ref = reference<MaterialRef>(ps, "material", "group", "material")) g.material = ref->id;
  ps.check_unused(kGroupNames);
  scene_.groups.push_back(std::move(g));
  return add_node(scene_, NodeKind::Group, scene_.groups.size() - 1, ps.loc());
}

namespace {

// Why `id` (a child of a CSG block of kind `op`) cannot take part, or "" when it can: CSG
// combines solids, so a light, an open surface (no inside) or a mesh (not known to be
// closed) is refused. Blocks inside were checked when they were built.
std::string csg_refusal(const SceneDesc& scene, NodeId id, std::string_view op, int depth = 0) {
  const Node& node = scene.nodes[id];
  if (node.kind == NodeKind::Light) return "a light cannot be part of a CSG block (place it beside the block)";
  if (node.kind == NodeKind::Csg) return "";
  if (node.kind == NodeKind::Group) {
    if (depth > tol::kMaxGroupDepth) return "groups nested too deep";
    for (const Child& c : scene.groups[node.index].children)
      if (std::string why = csg_refusal(scene, c.node, op, depth + 1); !why.empty()) return why;
    return "";
  }
  const ShapeDesc& s = scene.shapes[node.index];
  const ShapeInfo& info = kShapeInfos[s.geometry.index()];
  if (std::holds_alternative<MeshRef>(s.geometry))
    return fmt::format("a mesh cannot be part of '{}' yet: CSG needs solids with an inside (use a group for a union "
                       "of meshes)",
                       op);
  bool open = info.closure == Closure::Open;
  if (const auto* c = std::get_if<Cylinder>(&s.geometry)) open = !c->capped;
  if (const auto* c = std::get_if<Cone>(&s.geometry)) open = !c->capped;
  if (const auto* c = std::get_if<Sor>(&s.geometry)) open = c->open;
  if (const auto* c = std::get_if<Lathe>(&s.geometry)) open = !c->closed;
  if (const auto* c = std::get_if<Prism>(&s.geometry)) open = c->open;
  if (open) {
    bool capped_kind = info.closure == Closure::WhenCapped;
    std::string what = fmt::format("{} {}", capped_kind ? "an uncapped" : "a", info.name);
    return fmt::format("{} cannot be part of '{}': it is an open surface with no inside, and CSG combines solids "
                       "(use a group to place it beside the block, or a closed shape: box, sphere, capped cylinder)",
                       what, op);
  }
  return "";
}

}  // namespace

NodeId SceneBuilder::csg(std::string_view kind, std::vector<Child> children, ParamSet& ps) {
  ps.set_valid_names(names_of(kind));
  CsgDesc d;
  d.op = kind == "intersection" ? CsgOp::Intersection
         : kind == "difference" ? CsgOp::Difference
         : kind == "merge"      ? CsgOp::Merge
                                : CsgOp::Union;
  if (children.empty()) ps.fail_block(fmt::format("{} needs at least one shape", kind));
  for (const Child& c : children)
    if (std::string why = csg_refusal(scene_, c.node, kind); !why.empty()) throw SceneError(c.loc, why);
  if (const MaterialRef* ref = reference<MaterialRef>(ps, "material", kind, "material")) d.material = ref->id;
  d.inverse = ps.boolean("inverse", false);
  ps.check_unused(kCsgNames);
  d.children = std::move(children);
  scene_.csgs.push_back(std::move(d));
  return add_node(scene_, NodeKind::Csg, scene_.csgs.size() - 1, ps.loc());
}

void SceneBuilder::place(const Child& instance) { scene_.roots.push_back(instance); }

void SceneBuilder::check_readable(const std::string& path, const std::string& shown, std::string_view what,
                                  SourceRef where) const {
  if (!read_policy_.allows(path)) throw SceneError(where, read_policy_.refusal(shown, path));
  if (std::string kind = non_regular_kind(path); !kind.empty())
    throw SceneError(where, fmt::format("cannot read {} '{}': it is {}, not a file", what, shown, kind));
}

}  // namespace rts::render
