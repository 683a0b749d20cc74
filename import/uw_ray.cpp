// UW CSE 457's "SBT-raytracer 1.0" .ray format, parsed into a generic tree first (values are
// numbers, strings, names, tuples (a, b), blocks { key = value; } and calls f(args)), then
// written out, so declarations may come in any order:
//   camera { position = (0, 0, -4); viewdir = (0, 0, 1); updir = (0, 1, 0); fov = 45; }
//   point_light { position = (1, 1, 1); colour = (1, 1, 1); constant_attenuation_coeff = 0.25; }
//   translate(0, 1, 0, scale(2, sphere { material = { diffuse = (0.8, 0.3, 0.1); } }))
// Shading: ke + ka * ambient + Σ light * atten * (kd (N·L) + ks (R·V)^shininess) + reflection
// and refraction: a material becomes color = kd, diffuse = 1, ambient = 0 and the constant
// ke + ka * ambient as its emission.
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "import/convert_util.hpp"
#include "import/tokens.hpp"
#include "import/writer.hpp"

namespace rts::import {
namespace {

struct Prop;

struct Value {
  enum Kind { Num, Str, Name, Tuple, Block, Call } kind = Num;
  double num = 0;
  std::string text;                                   // Str, Name, Call (the function / block name)
  std::vector<Value> items;                           // Tuple, Call arguments
  // Block (and named blocks: sphere { ... }). Not std::pair: a pair of the still-incomplete
  // Value is ill-formed (libstdc++ asserts it under clang); a vector of a declared struct is not.
  std::vector<Prop> props;
  Token at;

  const Value* prop(const std::string& key) const;
};

struct Prop {
  std::string key;
  Value value;
};

const Value* Value::prop(const std::string& key) const {
  const Value* found = nullptr;
  for (const auto& [k, v] : props)
    if (k == key) found = &v;   // the last one wins
  return found;
}

struct Parser {
  Tokens& tk;

  Value block(Token at, std::string name) {
    Value v;
    v.kind = Value::Block;
    v.text = std::move(name);
    v.at = std::move(at);
    tk.expect("{");
    while (!tk.accept("}")) {
      if (tk.accept(";")) continue;
      Token key = tk.next();
      if (tk.peek_is("{") || tk.peek_is("(")) {   // a nested object or call without a key
        tk.fail(key, fmt::format("expected 'name = value' in the block, got '{}'", key.text));
      }
      tk.expect("=");
      v.props.push_back(Prop{key.text, value()});
      tk.accept(";");
    }
    return v;
  }

  Value value() {
    Token t = tk.peek();
    Nesting nesting(tk, t);
    if (tk.accept("(")) {
      Value v;
      v.kind = Value::Tuple;
      v.at = t;
      if (!tk.accept(")")) {
        do v.items.push_back(value());
        while (tk.accept(","));
        tk.expect(")");
      }
      return v;
    }
    if (tk.peek_is("{")) return block(t, "");
    tk.next();
    if (t.string) {
      Value v;
      v.kind = Value::Str;
      v.text = t.text;
      v.at = t;
      return v;
    }
    char* end = nullptr;
    double x = std::strtod(t.text.c_str(), &end);
    if (!t.text.empty() && end == t.text.c_str() + t.text.size()) {
      if (!std::isfinite(x)) tk.fail(t, fmt::format("'{}' is not a finite number", t.text));
      Value v;
      v.num = x;
      v.at = t;
      return v;
    }
    if (tk.peek_is("{")) return block(t, t.text);
    if (tk.accept("(")) {
      Value v;
      v.kind = Value::Call;
      v.text = t.text;
      v.at = t;
      if (!tk.accept(")")) {
        do v.items.push_back(value());
        while (tk.accept(","));
        tk.expect(")");
      }
      return v;
    }
    Value v;
    v.kind = Value::Name;
    v.text = t.text;
    v.at = t;
    return v;
  }
};

struct Uw {
  Uw(Tokens& t, const ImportOptions& o, SceneText& s) : tk(t), opt(o), out(s) {}
  Tokens& tk;
  const ImportOptions& opt;
  SceneText& out;
  glm::dvec3 ambient_light{0};
  std::map<std::string, std::string> materials;     // written text → let name
  std::map<std::string, std::string> named;         // UW material name → let name
  int meshes = 0;

  [[noreturn]] void fail(const Value& v, const std::string& message) { tk.fail(v.at, message); }

  double number(const Value& v) {
    if (v.kind != Value::Num) fail(v, "expected a number");
    return v.num;
  }
  glm::dvec3 triple(const Value& v) {
    if (v.kind == Value::Num) return glm::dvec3(v.num);
    if (v.kind != Value::Tuple || v.items.size() != 3) fail(v, "expected (x, y, z)");
    return {number(v.items[0]), number(v.items[1]), number(v.items[2])};
  }
  bool boolean(const Value& v) {
    if (v.kind == Value::Name && (v.text == "true" || v.text == "false")) return v.text == "true";
    if (v.kind == Value::Num) return v.num != 0;
    fail(v, "expected true or false");
  }
  // map("file") → an image texture; std::nullopt for plain colors.
  std::optional<std::string> map_texture(const Value& v) {
    if (v.kind != Value::Call || v.text != "map") return std::nullopt;
    if (v.items.size() != 1 || v.items[0].kind != Value::Str) fail(v, "expected map(\"file\")");
    return "image_texture { file = " + rts_string(relocate(v.items[0].text, opt)) +
           "  color_space = \"linear\"  filter = \"nearest\" }";
  }

  // The rts text of a material block (without `let`).
  std::string material_text(const Value& m) {
    std::string color = "rgb(1)";
    std::vector<std::string> parts;
    glm::dvec3 emission(0), ka(0);
    glm::dvec3 specular(0);
    std::string specular_tex;
    for (const auto& [key, v] : m.props) {
      auto tex = map_texture(v);
      if (key == "name") continue;
      if (key == "diffuse") color = tex ? *tex : rgb(triple(v));
      else if (key == "emissive") {
        if (tex) fail(v, "a texture on 'emissive' is not supported by the import");
        emission = triple(v);
      } else if (key == "ambient") {
        if (tex) fail(v, "a texture on 'ambient' is not supported by the import");
        ka = triple(v);
      } else if (key == "specular") {
        if (tex) specular_tex = *tex;
        else specular = triple(v);
      } else if (key == "reflective") parts.push_back("reflect = " + (tex ? *tex : rgb(triple(v))));
      else if (key == "transmissive") parts.push_back("transmit = " + (tex ? *tex : rgb(triple(v))));
      else if (key == "shininess") parts.push_back("shininess = " + num(number(v)));
      else if (key == "index") parts.push_back("ior = " + num(number(v)));
      else fail(v, fmt::format("unknown material property '{}'", key));
    }
    glm::dvec3 e = emission + ka * ambient_light;
    std::string text = fmt::format("material {{ color = {}  ambient = 0  diffuse = 1", color);
    if (!specular_tex.empty()) text += "  specular = " + specular_tex;
    else if (specular != glm::dvec3(0)) text += "  specular = " + specular_value(specular);
    for (const std::string& p : parts) text += "  " + p;
    if (e != glm::dvec3(0)) text += "  emission = " + rgb(e);
    return text + " }";
  }

  // A `let` name for the material value `m` (a block, or a name/string naming one).
  std::string material(const Value& m) {
    if (m.kind == Value::Str || m.kind == Value::Name) {
      auto it = named.find(m.text);
      if (it == named.end()) fail(m, fmt::format("no material named '{}'", m.text));
      return it->second;
    }
    if (m.kind != Value::Block) fail(m, "expected a material { ... }");
    std::string text = material_text(m);
    auto it = materials.find(text);
    std::string name;
    if (it != materials.end()) {
      name = it->second;
    } else {
      const Value* uw_name = m.prop("name");
      name = uw_name && uw_name->kind == Value::Str ? sanitize(uw_name->text) : fmt::format("material{}", materials.size());
      out.top.comments(m.at.comments);
      out.top.line(fmt::format("let {} = {}", name, text));
      materials.emplace(text, name);
    }
    if (const Value* uw_name = m.prop("name"); uw_name && uw_name->kind == Value::Str) named[uw_name->text] = name;
    return name;
  }

  static std::string sanitize(const std::string& s) {
    std::string out;
    for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "m_" + out;
    return out;
  }

  std::string op_for(const Value& call) {
    const auto& a = call.items;
    auto n = [&](std::size_t i) { return number(a[i]); };
    if (call.text == "translate" && a.size() == 4) return fmt::format(" translate <{}, {}, {}>", num(n(0)), num(n(1)), num(n(2)));
    if (call.text == "scale" && a.size() == 2) return " scale " + num(n(0));
    if (call.text == "scale" && a.size() == 4) return fmt::format(" scale <{}, {}, {}>", num(n(0)), num(n(1)), num(n(2)));
    if (call.text == "rotate" && a.size() == 5) {
      glm::dvec3 axis(n(0), n(1), n(2));
      double deg = n(3) * 180.0 / std::numbers::pi;
      if (axis == glm::dvec3(1, 0, 0)) return " rotate <" + num(deg) + ", 0, 0>";
      if (axis == glm::dvec3(0, 1, 0)) return " rotate <0, " + num(deg) + ", 0>";
      if (axis == glm::dvec3(0, 0, 1)) return " rotate <0, 0, " + num(deg) + ">";
      double m[4][4];
      axis_angle(axis, n(3), m);
      return " matrix " + matrix_list(m);
    }
    if (call.text == "transform" && a.size() == 5) {
      double m[4][4];
      for (int r = 0; r < 4; ++r) {
        if (a[r].kind != Value::Tuple || a[r].items.size() != 4) fail(a[r], "expected a row (a, b, c, d)");
        for (int c = 0; c < 4; ++c) m[r][c] = number(a[r].items[c]);
      }
      return " matrix " + matrix_list(m);
    }
    fail(call, fmt::format("unexpected arguments to {}(...)", call.text));
  }

  std::string material_of(const Value& obj, const std::string& current) {
    const Value* m = obj.prop("material");
    std::string name = m ? material(*m) : current;
    return name.empty() ? "" : "  material = " + name;
  }

  void check_props(const Value& obj, std::initializer_list<const char*> allowed) {
    for (const auto& [key, v] : obj.props) {
      bool ok = key == "material" || key == "name";
      for (const char* a : allowed) ok = ok || key == a;
      if (!ok) fail(v, fmt::format("unknown {} property '{}'", obj.text, key));
    }
  }

  void mesh(const Value& obj, const std::string& mat, const std::string& suffix) {
    check_props(obj, {"points", "faces", "normals", "materials", "gennormals"});
    const Value* points = obj.prop("points");
    const Value* faces = obj.prop("faces");
    if (!points || !faces || points->kind != Value::Tuple || faces->kind != Value::Tuple)
      fail(obj, obj.text + " needs points = (...) and faces = (...)");
    std::vector<glm::dvec3> p;
    for (const Value& v : points->items) p.push_back(triple(v));
    std::vector<std::array<int, 3>> tris;
    for (const Value& f : faces->items) {
      if (f.kind != Value::Tuple || f.items.size() < 3) fail(f, "a face needs at least three vertex indices");
      std::vector<int> idx;
      for (const Value& i : f.items) {
        double x = number(i);
        if (x != std::floor(x) || x < 0 || x >= static_cast<double>(p.size()))
          fail(i, fmt::format("face index {} out of range ({} points)", num(x), p.size()));
        idx.push_back(static_cast<int>(x));
      }
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) tris.push_back({idx[0], idx[k], idx[k + 1]});   // a fan
    }
    std::vector<glm::dvec3> normals;
    if (const Value* n = obj.prop("normals")) {
      if (n->kind != Value::Tuple || n->items.size() != p.size()) fail(*n, "expected one normal per point");
      for (const Value& v : n->items) normals.push_back(triple(v));
    }
    const Value* per_vertex = obj.prop("materials");
    Writer& w = out.world;
    w.comments(obj.at.comments);
    if (per_vertex) {
      // Per-vertex materials: an inline mesh carrying them (an OBJ file cannot).
      if (per_vertex->kind != Value::Tuple || per_vertex->items.size() != p.size())
        fail(*per_vertex, "expected one material per point");
      std::vector<std::string> colors, shin;
      std::vector<glm::dvec3> spec;
      for (const Value& m : per_vertex->items) {
        if (m.kind != Value::Block) fail(m, "expected a material { ... }");
        const Value* d = m.prop("diffuse");
        const Value* s = m.prop("specular");
        const Value* sh = m.prop("shininess");
        colors.push_back(rgb(d ? triple(*d) : glm::dvec3(1)));
        spec.push_back(s ? triple(*s) : glm::dvec3(0));
        shin.push_back(num(sh ? number(*sh) : 32.0));
      }
      auto join = [](const std::vector<std::string>& v) {
        std::string s;
        for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
        return "[" + s + "]";
      };
      w.open("mesh");
      std::vector<std::string> pv, fv, nv;
      for (const auto& x : p) pv.push_back(vec(x));
      for (const auto& t : tris) fv.push_back(fmt::format("<{}, {}, {}>", t[0], t[1], t[2]));
      for (const auto& x : normals) nv.push_back(vec(x));
      w.line("vertices = " + join(pv));
      w.line("faces = " + join(fv));
      if (!nv.empty()) w.line("normals = " + join(nv));
      else w.line("smooth = false");
      w.line("vertex_colors = " + join(colors));
      w.line("vertex_specular = " + specular_list(spec));
      w.line("vertex_shininess = " + join(shin));
      if (!mat.empty()) w.line(mat.substr(2));
      w.close(suffix);
      return;
    }
    std::string name = fmt::format("{}_mesh{}.obj", opt.mesh_prefix, meshes++);
    std::string obj_text = fmt::format("# {} from {}\n", obj.text, opt.source_name);
    for (const auto& x : p) obj_text += fmt::format("v {} {} {}\n", num(x.x), num(x.y), num(x.z));
    for (const auto& x : normals) obj_text += fmt::format("vn {} {} {}\n", num(x.x), num(x.y), num(x.z));
    for (const auto& t : tris) {
      if (normals.empty())
        obj_text += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
      else
        obj_text += fmt::format("f {0}//{0} {1}//{1} {2}//{2}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    meshes_out.push_back({name, obj_text});
    w.line(fmt::format("mesh {{ file = {}  smooth = {}{} }}{}", rts_string(name), normals.empty() ? "false" : "true", mat,
                       suffix));
  }
  std::vector<MeshFile> meshes_out;

  void object(const Value& v, const std::string& suffix, const std::string& current) {
    Writer& w = out.world;
    if (v.kind == Value::Call) {
      if (v.items.empty()) fail(v, fmt::format("{}(...) needs an object as its last argument", v.text));
      object(v.items.back(), op_for(v) + suffix, current);
      return;
    }
    if (v.kind != Value::Block || v.text.empty()) fail(v, "expected an object");
    const std::string& k = v.text;
    if (k == "camera" || k == "point_light" || k == "directional_light" || k == "ambient_light") {
      fail(v, fmt::format("{} inside a transform is not supported by the import", k));
    }
    std::string mat = material_of(v, current);
    w.comments(v.at.comments);
    if (k == "sphere") {
      check_props(v, {});
      w.line(fmt::format("sphere {{ radius = 1{} }}{}", mat, suffix));
    } else if (k == "box") {
      check_props(v, {});
      w.line(fmt::format("box {{ min = <-0.5, -0.5, -0.5>  max = <0.5, 0.5, 0.5>{} }}{}", mat, suffix));
    } else if (k == "square") {
      check_props(v, {});
      w.line(fmt::format("quad {{{} }}{}", mat.empty() ? "" : mat.substr(1), suffix));
    } else if (k == "cylinder") {
      check_props(v, {"capped"});
      const Value* c = v.prop("capped");
      w.line(fmt::format("cylinder {{ from = <0, 0, 0>  to = <0, 0, 1>  radius = 1  capped = {}{} }}{}",
                         c && !boolean(*c) ? "false" : "true", mat, suffix));
    } else if (k == "cone") {
      check_props(v, {"capped", "height", "bottom_radius", "top_radius"});
      auto get = [&](const char* name, double def) {
        const Value* x = v.prop(name);
        return x ? number(*x) : def;
      };
      const Value* c = v.prop("capped");
      w.line(fmt::format("cone {{ from = <0, 0, 0>  to = <0, 0, {}>  radius_from = {}  radius_to = {}  capped = {}{} }}{}",
                         num(get("height", 1)), num(get("bottom_radius", 1)), num(get("top_radius", 0)),
                         c && !boolean(*c) ? "false" : "true", mat, suffix));
    } else if (k == "trimesh" || k == "polymesh") {
      mesh(v, mat, suffix);
    } else {
      fail(v, fmt::format("unknown object '{}'", k));
    }
  }

  void camera(const Value& c) {
    glm::dvec3 position(0), viewdir(0, 0, -1), up(0, 1, 0);
    std::optional<glm::dvec3> look_at;
    double aspect = 1, fov = 30;
    for (const auto& [key, v] : c.props) {
      if (key == "position") position = triple(v);
      else if (key == "viewdir") viewdir = triple(v);
      else if (key == "updir") up = triple(v);
      else if (key == "look_at") look_at = triple(v);
      else if (key == "aspectratio") aspect = number(v);
      else if (key == "fov") fov = number(v);
      else fail(v, fmt::format("unknown camera property '{}'", key));
    }
    if (!(aspect > 0)) fail(c, "aspectratio must be > 0");
    out.top.comments(c.at.comments);
    out.top.line(fmt::format("settings {{ width = 512  height = {} }}", static_cast<int>(std::lround(512 / aspect))));
    write_camera(out.top, position, look_at ? *look_at : position + viewdir, up, fov, FovAxis::Vertical,
                 fmt::format("UW's fov is vertical; the image keeps its aspect ratio {}", num(aspect)));
  }

  void light(const Value& l) {
    glm::dvec3 color(1), position(0), direction(0, 0, -1), atten(1, 0, 0);
    bool has_atten = false;
    for (const auto& [key, v] : l.props) {
      if (key == "colour" || key == "color") color = triple(v);
      else if (key == "position" && l.text == "point_light") position = triple(v);
      else if (key == "direction" && l.text == "directional_light") direction = triple(v);
      else if (key == "constant_attenuation_coeff" && l.text == "point_light") atten.x = number(v), has_atten = true;
      else if (key == "linear_attenuation_coeff" && l.text == "point_light") atten.y = number(v), has_atten = true;
      else if (key == "quadratic_attenuation_coeff" && l.text == "point_light") atten.z = number(v), has_atten = true;
      else fail(v, fmt::format("unknown {} property '{}'", l.text, key));
    }
    // All three zero: UW's min(1, 1/0) is 1, no falloff at all.
    if (atten == glm::dvec3(0)) has_atten = false;
    out.world.comments(l.at.comments);
    if (l.text == "directional_light") {
      out.world.line(fmt::format("directional_light {{ direction = {}  color = {} }}", vec(direction), rgb(color)));
    } else {
      // UW's falloff is min(1, 1 / (a + b d + c d^2)): rts's attenuation with the clamp.
      out.world.line(fmt::format("point_light {{ position = {}  color = {}{} }}", vec(position), rgb(color),
                                 has_atten ? "  attenuation = " + vec(atten) + "  attenuation_clamp = true" : ""));
    }
  }

  void run() {
    Token head = tk.peek();
    if (!tk.accept("SBT-raytracer")) tk.fail(head, "a .ray file starts with 'SBT-raytracer 1.0'");
    Token version = tk.peek();
    if (tk.number() != 1.0) tk.fail(version, "only version 1.0 of the .ray format is known");
    out.header.insert(out.header.end(), head.comments.begin(), head.comments.end());
    Parser parser{tk};
    std::vector<std::pair<std::optional<std::string>, Value>> all;   // (assigned key, value)
    while (!tk.done()) {
      if (tk.accept(";")) continue;
      Token t = tk.peek();
      Value v = parser.value();
      if (v.kind == Value::Name && tk.accept("=")) {
        Value rhs = parser.value();
        rhs.at.comments = t.comments;
        all.emplace_back(v.text, std::move(rhs));
      } else {
        all.emplace_back(std::nullopt, std::move(v));
      }
      tk.accept(";");
    }
    // The ambient light first: every material's emission depends on it.
    for (const auto& [key, v] : all)
      if (!key && v.kind == Value::Block && v.text == "ambient_light") {
        const Value* c = v.prop("color");
        if (!c) c = v.prop("colour");
        if (c) ambient_light = triple(*c);
      }
    bool has_camera = false;
    std::string current;   // the material `material = {...}` set for the objects after it
    for (const auto& [key, v] : all) {
      if (key) {
        if (*key != "material") fail(v, fmt::format("unknown top-level setting '{}'", *key));
        current = material(v);
        continue;
      }
      if (v.kind == Value::Block && v.text == "camera") {
        camera(v);
        has_camera = true;
      } else if (v.kind == Value::Block && (v.text == "point_light" || v.text == "directional_light")) {
        light(v);
      } else if (v.kind == Value::Block && v.text == "ambient_light") {
        out.world.comments(v.at.comments);
        out.world.line("// ambient_light " + rgb(ambient_light) + ": folded into each material's emission");
      } else {
        object(v, "", current);
      }
    }
    if (!has_camera) {
      out.top.line("settings { width = 512  height = 512 }");
      write_camera(out.top, glm::dvec3(0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), 30, FovAxis::Vertical,
                   "UW's default camera");
    }
    out.world.comments(tk.trailing_comments());
  }
};

}  // namespace

std::vector<MeshFile> import_uw(const std::string& text, const ImportOptions& opt, SceneText& out) {
  Tokens tk(text);
  Uw uw{tk, opt, out};
  uw.run();
  return std::move(uw.meshes_out);
}

}  // namespace rts::import
