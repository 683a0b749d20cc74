// MIT 6.837's scene format: named blocks of keyword/value lines
//   PerspectiveCamera { center 0 0 10  direction 0 0 -1  up 0 1 0  angle 30 }
//   Lights { numLights 1  DirectionalLight { direction -0.5 -0.5 -1  color 0.8 0.8 0.8 } }
//   Background { color 0.2 0 0.6  ambientLight 0.2 0.2 0.2  cubeMap tex/church }
//   Materials { numMaterials 1  PhongMaterial { diffuseColor 1 0 0 ... } }
//   Group { numObjects 1  MaterialIndex 0  Sphere { center 0 0 0  radius 1 } }
// Shading: ambientLight * diffuse + Σ light * (diffuse (N·L) + specular (R·V)^exponent), so a
// material becomes color = diffuseColor, ambient = 1, diffuse = 1.
// The a2 starter's conventions (MIT 6.837, as reused by Fudan COMP130018): a PointLight's
// `falloff` divides by falloff·d²; shadow rays only with -shadows; -bounces N adds
// ks · I_reflected (the cube map is what reflected rays see); TriangleMesh vertex normals are
// the mean of the faces' unit normals; the camera's image plane is built from the raw `up`;
// no Background means a gray one and no ambient light; no lights means ambient white.
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "import/convert_util.hpp"
#include "import/tokens.hpp"
#include "import/writer.hpp"

namespace rts::import {
namespace {

struct Mit {
  Mit(Tokens& t, const ImportOptions& o, SceneText& s) : tk(t), opt(o), out(s) {}
  Tokens& tk;
  const ImportOptions& opt;
  SceneText& out;
  int materials = 0;
  int lights_seen = 0;
  // The Background block's parts (a2's defaults: gray, no ambient light), written with the
  // options as one settings line at the end.
  glm::dvec3 background_color{0.5}, ambient{0.0};
  std::string environment;

  int width() const { return opt.width > 0 ? opt.width : 256; }     // MIT renders square images
  int height() const { return opt.height > 0 ? opt.height : 256; }

  void camera(const std::string& kind) {
    tk.expect("{");
    glm::dvec3 center(0, 0, 10), direction(0, 0, -1), up(0, 1, 0);
    double angle = 30, size = 5;
    while (!tk.accept("}")) {
      Token key = tk.next();
      if (key.text == "center") center = tk.vec3();
      else if (key.text == "direction") direction = tk.vec3();
      else if (key.text == "up") up = tk.vec3();
      else if (key.text == "angle" && kind == "PerspectiveCamera") angle = tk.number();
      else if (key.text == "size" && kind == "OrthographicCamera") size = tk.number();
      else tk.fail(key, fmt::format("unknown {} field '{}'", kind, key.text));
    }
    if (kind == "PerspectiveCamera") {
      perspective(center, direction, up, angle);
    } else {
      out.top.line(fmt::format("camera {{ projection = \"orthographic\"  position = {}  look_at = {}  up = {}  "
                               "view_width = {}  handedness = \"right\" }}",
                               vec(center), vec(center + direction), vec(up), num(size)));
    }
  }

  // a2's camera: the ray through (x, y) in [-1, 1]² points along
  //   ŵ / tan(angle/2) + x·normalize(direction × up) + y·up
  // with `up` as written, so an up not perpendicular to the direction (or not of length 1)
  // shears (or stretches) the image, and a non-square image is stretched. The same view as a
  // look_at camera when none of that happens; else direction, right and up as given.
  void perspective(const glm::dvec3& center, const glm::dvec3& direction, const glm::dvec3& up, double angle) {
    const glm::dvec3 w = glm::normalize(direction);
    const bool plain = std::abs(glm::dot(w, up)) <= 1e-12 * glm::length(up) &&
                       std::abs(glm::length(up) - 1.0) <= 1e-12 && width() == height();
    if (plain) {
      write_camera(out.top, center, center + direction, up, angle, FovAxis::Vertical,
                   "MIT's angle spans the (square) image from top to bottom");
      return;
    }
    const double t = 2.0 * std::tan(angle * std::numbers::pi / 360.0);
    const glm::dvec3 right = t * glm::normalize(glm::cross(direction, up));
    out.top.line("// MIT a2's image plane from the raw up (not made perpendicular to the direction) and");
    out.top.line(fmt::format("// [-1, 1] across each side of the {}x{} image: direction, right and up as given", width(),
                             height()));
    out.top.line(fmt::format("camera {{ position = {}  direction = {}  right = {}  up = {} }}", vec(center), vec(w),
                             vec(right), vec(t * up)));
  }

  void background() {
    tk.expect("{");
    while (!tk.accept("}")) {
      Token key = tk.next();
      if (key.text == "color") background_color = tk.vec3();
      else if (key.text == "ambientLight") ambient = tk.vec3();
      else if (key.text == "cubeMap")
        // a2 reads the faces' bytes / 255, as the rest of its images, and orients them its own way.
        environment = "environment = cube_map { directory = " + rts_string(relocate(tk.word(), opt)) +
                      "  color_space = \"linear\"  orientation = \"mit\" }";
      else tk.fail(key, fmt::format("unknown Background field '{}'", key.text));
    }
  }

  // One settings line: the image size, the Background block and what the options imply.
  void settings() {
    std::string line = fmt::format("settings {{ width = {}  height = {}  background = {}  ambient_light = {}", width(),
                                   height(), rgb(background_color), rgb(lights_seen == 0 ? glm::dvec3(1) : ambient));
    if (!environment.empty()) line += "  " + environment;
    line += fmt::format("  max_depth = {}", opt.bounces);
    line += aov_settings(opt, 127.0 / 255.0);   // a2's normal image: background gray 127
    out.top.line(line + "  output_gamma = \"linear\" }");
  }

  void lights() {
    tk.expect("{");
    if (tk.accept("numLights")) tk.integer();
    while (!tk.accept("}")) {
      Token kind = tk.next();
      out.world.comments(kind.comments);
      tk.expect("{");
      glm::dvec3 color(1), position(0), direction(0, 0, -1), attenuation(1, 0, 0);
      bool has_attenuation = false;
      while (!tk.accept("}")) {
        Token key = tk.next();
        if (key.text == "color") color = tk.vec3();
        else if (key.text == "position" && kind.text == "PointLight") position = tk.vec3();
        else if (key.text == "direction" && kind.text == "DirectionalLight") direction = tk.vec3();
        else if (key.text == "attenuation" && kind.text == "PointLight") attenuation = tk.vec3(), has_attenuation = true;
        else if (key.text == "falloff" && kind.text == "PointLight") {
          // a2: intensity = color / (falloff · d²).
          const Token at = tk.peek();
          const double falloff = tk.number();
          if (!(falloff > 0)) tk.fail(at, fmt::format("PointLight falloff must be > 0 (intensity = color / (falloff "
                                                      "· d²)), got {}", num(falloff)));
          attenuation = glm::dvec3(0, 0, falloff);
          has_attenuation = true;
        } else tk.fail(key, fmt::format("unknown {} field '{}'", kind.text, key.text));
      }
      // a2 casts shadow rays only with -shadows (--shadows).
      const std::string shadows = opt.shadows ? "" : "  shadows = false";
      if (kind.text == "DirectionalLight")
        out.world.line(fmt::format("directional_light {{ direction = {}  color = {}{} }}", vec(direction), rgb(color),
                                   shadows));
      else if (kind.text == "PointLight")
        out.world.line(fmt::format("point_light {{ position = {}  color = {}{}{} }}", vec(position), rgb(color),
                                   has_attenuation ? "  attenuation = " + vec(attenuation) : "", shadows));
      else
        tk.fail(kind, fmt::format("unknown light '{}' (expected DirectionalLight or PointLight)", kind.text));
      ++lights_seen;
    }
  }

  void material_block(const Token& kind) {
    tk.expect("{");
    std::vector<std::string> parts = {"ambient = 1", "diffuse = 1"};
    std::string color = "color = rgb(1)";
    glm::dvec3 specular(0);
    bool reflective = false;
    while (!tk.accept("}")) {
      Token key = tk.next();
      if (key.text == "diffuseColor") color = "color = " + rgb(tk.vec3());
      else if (key.text == "specularColor") {
        specular = tk.vec3();
        // A gray specularColor is a plain weight; a tinted one becomes a colored highlight.
        parts.push_back("specular = " + specular_value(specular));
      } else if (key.text == "exponent" || key.text == "shininess") parts.push_back("shininess = " + num(tk.number()));
      else if (key.text == "reflectiveColor") parts.push_back("reflect = " + rgb(tk.vec3())), reflective = true;
      else if (key.text == "transparentColor") parts.push_back("transmit = " + rgb(tk.vec3()));
      else if (key.text == "indexOfRefraction") parts.push_back("ior = " + num(tk.number()));
      else if (key.text == "texture")
        color = "texture = image_texture { file = " + rts_string(relocate(tk.word(), opt)) +
                "  color_space = \"linear\"  filter = \"nearest\" }";
      else if (key.text == "bump")
        parts.push_back("bump = image_texture { file = " + rts_string(relocate(tk.word(), opt)) + "  color_space = \"linear\" }");
      else tk.fail(key, fmt::format("unknown {} field '{}'", kind.text, key.text));
    }
    // a2's -bounces: the mirror term is ks · I_reflected, ks the specular color.
    if (opt.bounces > 0 && !reflective && specular != glm::dvec3(0)) parts.push_back("reflect = " + rgb(specular));
    out.top.comments(kind.comments);
    std::string line = fmt::format("let material{} = material {{ {}", materials++, color);
    std::string trailing;
    for (const std::string& p : parts) {
      std::size_t c = p.find("  //");
      line += "  " + p.substr(0, c);
      if (c != std::string::npos) trailing = p.substr(c);
    }
    out.top.line(line + " }" + trailing);
  }

  void materials_block() {
    tk.expect("{");
    if (tk.accept("numMaterials")) tk.integer();
    while (!tk.accept("}")) {
      Token kind = tk.next();
      if (kind.text != "Material" && kind.text != "PhongMaterial")
        tk.fail(kind, fmt::format("unsupported material '{}' (expected Material or PhongMaterial)", kind.text));
      material_block(kind);
    }
  }

  std::string material_ref(int index, const Token& at) {
    if (index < 0) return "";
    if (index >= materials) tk.fail(at, fmt::format("MaterialIndex {} but only {} materials", index, materials));
    return fmt::format("  material = material{}", index);
  }

  // One object, written with `suffix` (its transforms) after it.
  void object(int material, const std::string& suffix) {
    Token kind = tk.next();
    Nesting nesting(tk, kind);
    Writer& w = out.world;
    w.comments(kind.comments);
    if (kind.text == "Group") {
      tk.expect("{");
      if (tk.accept("numObjects")) tk.integer();
      w.open("group");
      while (!tk.accept("}")) {
        if (tk.peek_is("MaterialIndex")) {
          Token at = tk.next();
          material = tk.integer();
          material_ref(material, at);
          continue;
        }
        object(material, "");
      }
      w.close(suffix);
      return;
    }
    if (kind.text == "Transform") {
      tk.expect("{");
      std::vector<std::string> ops;
      while (true) {
        const Token& key = tk.peek();
        if (key.text == "Scale") tk.next(), ops.push_back("scale " + vec(tk.vec3()));
        else if (key.text == "UniformScale") tk.next(), ops.push_back("scale " + num(tk.number()));
        else if (key.text == "Translate") tk.next(), ops.push_back("translate " + vec(tk.vec3()));
        else if (key.text == "XRotate") tk.next(), ops.push_back("rotate <" + num(tk.number()) + ", 0, 0>");
        else if (key.text == "YRotate") tk.next(), ops.push_back("rotate <0, " + num(tk.number()) + ", 0>");
        else if (key.text == "ZRotate") tk.next(), ops.push_back("rotate <0, 0, " + num(tk.number()) + ">");
        else if (key.text == "Rotate") {  // Rotate { axis degrees }
          tk.next();
          tk.expect("{");
          const glm::dvec3 axis = tk.vec3();
          const double degrees = tk.number();
          tk.expect("}");
          double m[4][4];
          axis_angle(axis, degrees * std::numbers::pi / 180.0, m);
          ops.push_back("matrix " + matrix_list(m));
        } else if (key.text == "Matrix4f") {  // column by column (a2's parser fills m(i, j) with i fastest)
          tk.next();
          tk.expect("{");
          double m[4][4];
          for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) m[i][j] = tk.number();
          tk.expect("}");
          // a2 multiplies it on the left of what came before (the others go on the right), so
          // it applies after them: it goes before them in `ops`, which is reversed below.
          ops.insert(ops.begin(), "matrix " + matrix_list(m));
        } else if (key.text == "Matrix") {
          tk.next();
          tk.expect("{");
          double m[4][4];
          for (auto& row : m)
            for (double& x : row) x = tk.number();
          tk.expect("}");
          ops.push_back("matrix " + matrix_list(m));
        } else break;
      }
      // MIT multiplies the operations in the order written (the last applies first); rts
      // applies transforms in the order written: reverse them.
      std::string mine;
      for (auto it = ops.rbegin(); it != ops.rend(); ++it) mine += " " + *it;
      object(material, mine + suffix);
      tk.expect("}");
      return;
    }
    tk.expect("{");
    const std::string mat = material_ref(material, kind);
    if (kind.text == "Sphere") {
      glm::dvec3 c(0);
      double r = 1;
      while (!tk.accept("}")) {
        Token key = tk.next();
        if (key.text == "center") c = tk.vec3();
        else if (key.text == "radius") r = tk.number();
        else tk.fail(key, fmt::format("unknown Sphere field '{}'", key.text));
      }
      w.line(fmt::format("sphere {{ center = {}  radius = {}{} }}{}", vec(c), num(r), mat, suffix));
    } else if (kind.text == "Plane") {
      glm::dvec3 n(0, 1, 0);
      double d = 0;
      while (!tk.accept("}")) {
        Token key = tk.next();
        if (key.text == "normal") n = tk.vec3();
        else if (key.text == "offset") d = tk.number();
        else tk.fail(key, fmt::format("unknown Plane field '{}'", key.text));
      }
      w.line(fmt::format("plane {{ normal = {}  offset = {}{} }}{}", vec(n), num(d), mat, suffix));
    } else if (kind.text == "Triangle") {
      glm::dvec3 v[3] = {};
      while (!tk.accept("}")) {
        Token key = tk.next();
        if (key.text == "vertex0") v[0] = tk.vec3();
        else if (key.text == "vertex1") v[1] = tk.vec3();
        else if (key.text == "vertex2") v[2] = tk.vec3();
        else tk.fail(key, fmt::format("unknown Triangle field '{}'", key.text));
      }
      w.line(fmt::format("triangle {{ v0 = {}  v1 = {}  v2 = {}{} }}{}", vec(v[0]), vec(v[1]), vec(v[2]), mat, suffix));
    } else if (kind.text == "TriangleMesh") {
      std::string file;
      while (!tk.accept("}")) {
        Token key = tk.next();
        if (key.text == "obj_file") file = tk.word();
        else tk.fail(key, fmt::format("unknown TriangleMesh field '{}'", key.text));
      }
      if (file.empty()) tk.fail(kind, "TriangleMesh needs obj_file");
      // a2 shades meshes smoothly with vertex normals averaged from the faces' unit normals.
      w.line(fmt::format("mesh {{ file = {}  smooth_weights = \"equal\"{} }}{}", rts_string(relocate(file, opt)), mat,
                         suffix));
    } else {
      tk.fail(kind, fmt::format("unknown object '{}' (expected Group, Transform, Sphere, Plane, Triangle or "
                                "TriangleMesh)", kind.text));
    }
  }

  void run() {
    while (!tk.done()) {
      Token kind = tk.peek();
      if (kind.text == "PerspectiveCamera" || kind.text == "OrthographicCamera") {
        tk.next();
        out.top.comments(kind.comments);
        camera(kind.text);
      } else if (kind.text == "Background") {
        tk.next();
        out.top.comments(kind.comments);
        background();
      } else if (kind.text == "Lights") {
        tk.next();
        out.world.comments(kind.comments);
        lights();
      } else if (kind.text == "Materials") {
        tk.next();
        out.top.comments(kind.comments);
        materials_block();
      } else if (kind.text == "Group") {
        object(-1, "");
      } else {
        tk.fail(kind, fmt::format("unknown block '{}' (expected PerspectiveCamera, OrthographicCamera, Lights, "
                                  "Background, Materials or Group)", kind.text));
      }
    }
    settings();
    out.world.comments(tk.trailing_comments());
  }
};

}  // namespace

void import_mit(const std::string& text, const ImportOptions& opt, SceneText& out) {
  Tokens tk(text);
  Mit(tk, opt, out).run();
}

}  // namespace rts::import
