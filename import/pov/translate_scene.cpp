// POV-Ray statements as rts statements: directives, placements, lights, the camera, global
// settings, includes; and the entry point, import_pov.
#include <cmath>
#include <functional>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "import/pov/reader.hpp"
#include "import/pov/translator.hpp"

namespace rts::import::pov {

namespace fs = std::filesystem;

namespace {

// The standard include files and the rts library file each maps to ("" : rts's built-ins
// cover it, nothing to include).
const std::map<std::string, std::string>& standard_includes() {
  static const std::map<std::string, std::string> m = {
      {"colors.inc", "colors.inc"},   {"colours.inc", "colors.inc"}, {"consts.inc", "consts.inc"},
      {"ior.inc", "consts.inc"},      {"metals.inc", "metals.inc"},  {"golds.inc", "metals.inc"},
      {"glass.inc", "glass.inc"},     {"textures.inc", "textures.inc"}, {"shapes.inc", "shapes.inc"},
      {"skies.inc", "skies.inc"},     {"math.inc", ""},              {"transforms.inc", ""},
      {"functions.inc", ""},          {"rand.inc", ""},              {"strings.inc", ""},
      {"arrays.inc", ""},             {"debug.inc", ""},             {"finish.inc", "finish.inc"},
      {"woods.inc", "woods.inc"},     {"stones.inc", "stones.inc"},  {"stones1.inc", "stones.inc"},
      {"stones2.inc", "stones.inc"}};
  return m;
}
const std::set<std::string>& unshipped_includes() {
  static const std::set<std::string> s = {"stars.inc",
                                          "shapes2.inc", "shapesq.inc", "shapes_old.inc", "chars.inc",
                                          "skies.inc.old", "sunpos.inc", "screen.inc", "logo.inc", "rad_def.inc",
                                          "glass_old.inc", "meshmaker.inc", "makegrass.inc", "stdcam.inc",
                                          "stdinc.inc", "potions.inc", "fonts.inc"};
  return s;
}

// POV-Ray's camera vectors as literals, when they are.
bool literal3(const Expr* e, glm::dvec3& out) {
  std::vector<double> v;
  double k;
  if (e && Translator::literal_number(*e, k)) {  // a float where a vector belongs: <k, k, k>
    out = glm::dvec3(k);
    return true;
  }
  if (!e || !Translator::literal_vector(*e, v) || v.size() != 3) return false;
  out = glm::dvec3(v[0], v[1], v[2]);
  return true;
}

}  // namespace

// ---- diagnostics ----

void Translator::unsupported(Loc at, const std::string& keyword, const std::string& alternative, bool planned) {
  warn(at, fmt::format("POV-Ray's '{}' is not translated; closest in rts: {} ({})", keyword, alternative,
                       planned ? "planned" : "not planned"));
}

void Translator::warn(Loc at, const std::string& message) {
  Diagnostic d{file_, at.line, at.col, message};
  if (opt_.strict) throw PovError{d};
  for (const Diagnostic& w : result_.warnings)
    if (w.file == d.file && w.line == d.line && w.col == d.col && w.message == d.message) return;
  result_.warnings.push_back(d);
}

void Translator::error(Loc at, const std::string& message) const { throw PovError{Diagnostic{file_, at.line, at.col, message}}; }

bool Translator::missing_name(Loc at, const std::string& name, const std::string& what) {
  if (!library_known_ || lookup(name) || reader_names_.count(name)) return false;
  unsupported(at, name, fmt::format("rts's standard library has no {} of that name (docs/library.md); {}", what,
                                    what == "object" ? "it is left out" : "a default is used"),
              false);
  return true;
}

// ---- statements ----

void Translator::items(Writer& w, const std::vector<Item>& list, bool top) {
  for (const Item& it : list) item(w, it, top);
}

// Names a loop or if body declares before the code after it uses them: POV-Ray's #declare is
// global, rts's `let` lives in its body, so they are declared (as none) before the statement.
void Translator::hoist(Writer& w, const std::vector<Item>& body) {
  std::vector<const std::vector<Item>*> todo = {&body};
  while (!todo.empty()) {
    const std::vector<Item>* list = todo.back();
    todo.pop_back();
    for (const Item& it : *list) {
      if (it.kind == Item::Declare && !it.local && it.args.size() == 1 && !declared(it.name)) {
        w.line(fmt::format("let {} = none  // declared inside the {} below", rename(it.name),
                           "block"));
        define(it.name, Symbol{Type::Unknown, nullptr, ""});
      }
      if (it.kind == Item::If || it.kind == Item::While || it.kind == Item::For || it.kind == Item::Switch ||
          it.kind == Item::Case) {
        todo.push_back(&it.body);
        todo.push_back(&it.else_body);
      }
    }
  }
}

void Translator::item(Writer& w, const Item& it, bool top) {
  w.comments(it.comments);
  switch (it.kind) {
    case Item::Value: {
      // A macro call is a statement in rts too (it places what the macro makes); any other
      // value standing alone (`#declare A = A y+ x;` reads as A, then `y + x`) is not one.
      if (it.args[0]->kind != Expr::Call) {
        warn(it.loc, "a value where POV-Ray expects an object, a directive or a declaration; it is dropped");
        return;
      }
      Text t = expr(*it.args[0]);
      w.line(t.s);
      return;
    }
    case Item::Keyword:
      unsupported(it.loc, it.name, "a statement such as an object, a light or settings { }", false);
      return;
    case Item::MapEntry: return;
    case Item::Nested: place_block(w, *it.block); return;
    case Item::Declare: declare(w, it); return;
    case Item::Macro: {
      define(it.name, Symbol{Type::Macro, nullptr, ""});
      std::string params;
      for (const std::string& p : it.params) params += (params.empty() ? "" : ", ") + rename(p);
      w.open(fmt::format("macro {}({})", rename(it.name), params));
      scopes_.emplace_back();
      for (const std::string& p : it.params) define(p, Symbol{Type::Unknown, nullptr, ""});
      // A body that is one value (an object, a texture, an expression) gives it back.
      std::vector<const Item*> real;
      for (const Item& b : it.body)
        if (b.kind != Item::Declare) real.push_back(&b);
      bool one_value = real.size() == 1 && (real[0]->kind == Item::Value ||
                                            (real[0]->kind == Item::Nested && is_object_kind(real[0]->block->kind)));
      if (one_value) {
        for (const Item& b : it.body)
          if (&b != real[0]) item(w, b, false);
        w.comments(real[0]->comments);
        if (real[0]->kind == Item::Value) w.line("return " + value(*real[0]->args[0]));
        else object(w, *real[0]->block, "return ", false);
      } else if (real.size() == 1 && real[0]->kind == Item::Nested &&
                 (real[0]->block->kind == "texture" || real[0]->block->kind == "pigment" ||
                  real[0]->block->kind == "finish")) {
        for (const Item& b : it.body)
          if (&b != real[0]) item(w, b, false);
        MaterialProps m;
        texture_part(*real[0], m);
        w.line("return " + (real[0]->block->kind == "pigment" ? pigment_value(*real[0]->block) : material_text(m, true)));
      } else {
        items(w, it.body, false);
      }
      scopes_.pop_back();
      w.close();
      return;
    }
    case Item::While: {
      hoist(w, it.body);
      w.open("while " + condition(*it.args[0]));
      scopes_.emplace_back();
      items(w, it.body, false);
      scopes_.pop_back();
      w.close();
      return;
    }
    case Item::For: {
      hoist(w, it.body);
      std::string step = it.args.size() > 2 ? " step " + value(*it.args[2]) : "";
      w.open(fmt::format("for {} in {} ..= {}{}", rename(it.name), value(*it.args[0]), value(*it.args[1]), step));
      scopes_.emplace_back();
      define(it.name, Symbol{Type::Float, nullptr, ""});
      items(w, it.body, false);
      scopes_.pop_back();
      w.close();
      return;
    }
    case Item::If: {
      if (it.ifdef) {
        // #ifdef: whether the name is declared at this point of the translation.
        bool d = declared(it.args[0]->text) != it.negate;
        w.line(fmt::format("// #{}({}): {} when translated", it.negate ? "ifndef" : "ifdef", it.args[0]->text,
                           d ? "true" : "false"));
        items(w, d ? it.body : it.else_body, top);
        return;
      }
      hoist(w, it.body);
      hoist(w, it.else_body);
      w.open("if " + condition(*it.args[0]));
      scopes_.emplace_back();
      items(w, it.body, false);
      scopes_.pop_back();
      if (!it.else_body.empty()) {
        w.middle("else");
        scopes_.emplace_back();
        items(w, it.else_body, false);
        scopes_.pop_back();
      }
      w.close();
      return;
    }
    case Item::Switch: {
      hoist(w, it.body);
      Text v = expr(*it.args[0]);
      std::string sel = "pov_switch";
      w.line(fmt::format("let {} = {}  // #switch", sel, v.s));
      bool first = true;
      for (const Item& c : it.body) {
        std::string cond;
        if (c.name == "case") cond = fmt::format("{} == {}", sel, value(*c.args[0]));
        else if (c.name == "range")
          cond = fmt::format("{0} >= {1} and {0} <= {2}", sel, value(*c.args[0]), value(*c.args[1]));
        if (c.name == "else") {
          if (first) w.open("if true");
          else w.middle("else");
        } else if (first) {
          w.open("if " + cond);
        } else {
          w.middle("else if " + cond);
        }
        first = false;
        scopes_.emplace_back();
        items(w, c.body, false);
        scopes_.pop_back();
      }
      if (!first) w.close();
      return;
    }
    case Item::Include: include(w, it); return;
    case Item::Version: {
      double v;
      if (literal_number(*it.args[0], v)) version_ = v;
      w.line("// #version " + value(*it.args[0]));
      return;
    }
    case Item::Default: {
      for (const Item& d : it.block->items) {
        if (d.kind == Item::Nested && (d.block->kind == "finish" || d.block->kind == "pigment" ||
                                       d.block->kind == "texture" || d.block->kind == "normal")) {
          texture_part(d, default_texture_);
        } else {
          unsupported(d.loc, "#default", "the value written where it is used", false);
        }
      }
      w.line("// #default: POV-Ray's defaults changed; written into each material below");
      return;
    }
    case Item::Message: {
      if (it.name == "error") w.line("error(" + value(*it.args[0]) + ")");
      else if (it.name == "debug" || it.name == "warning") w.line("print(" + value(*it.args[0]) + ")");
      return;
    }
    case Item::Ignored:
      if (it.name != "undef") unsupported(it.loc, "#" + it.name, "values written into the scene", false);
      return;
    case Item::Case: return;
  }
}

void Translator::declare(Writer& w, const Item& it) {
  const std::string n = rename(it.name);
  if (it.args.size() == 2) {  // #declare A[i] = v
    // rts's lists are values: an element is not assigned on its own.
    w.line(fmt::format("// not translated: {}[{}] = {}", n, value(*it.args[1]), value(*it.args[0])));
    unsupported(it.loc, "#declare " + it.name + "[...]", "a list built with its values", false);
    return;
  }
  const Expr& e = *it.args[0];
  bool exists = lookup(it.name) != nullptr && (!it.local || scopes_.back().count(it.name));
  std::string head = exists ? n + " = " : "let " + n + " = ";
  if (e.kind == Expr::BlockValue) {
    const Block& b = *e.block;
    Symbol s;
    s.block = e.block;
    if (is_object_kind(b.kind)) {
      s.type = Type::Object;
      s.object_kind = b.kind == "object" ? "object" : b.kind;
      if (b.kind == "object")
        for (const Item& r : b.items)
          if (r.kind == Item::Value && r.args[0]->kind == Expr::Name) {
            if (Symbol* inner = lookup(r.args[0]->text)) s.object_kind = inner->object_kind;
            break;
          }
      s.textured = has_texture(b);  // before N is redefined: `object { N texture { } }` names the old N
      object(w, b, head, false);
      if (b.kind != "object") s.object_kind = last_kind_;
    } else if (b.kind == "texture" || b.kind == "material") {
      s.type = Type::Material;
      MaterialProps m;
      Item part;
      part.kind = Item::Nested;
      part.block = e.block;
      texture_part(part, m);
      w.line(head + material_text(m, true));
    } else if (b.kind == "pigment") {
      s.type = Type::Pigment;
      w.line(head + pigment_value(b));
    } else if (b.kind == "finish") {
      s.type = Type::Finish;
      finish(b, s.props);
      w.line(fmt::format("// finish {}: written into each material that uses it", it.name));
      define(it.name, s);
      return;
    } else if (b.kind == "interior" || b.kind == "transform" || b.kind == "normal") {
      s.type = b.kind == "interior" ? Type::Interior : b.kind == "normal" ? Type::Normal : Type::Transform;
      if (s.type == Type::Interior) interior(b, s.props);
      if (s.type == Type::Transform) {
        Item whole;
        whole.kind = Item::Nested;
        whole.block = e.block;
        s.steps = transforms(whole);
      }
      w.line(fmt::format("// {} {}: written where it is used", b.kind, it.name));
    } else if (b.kind == "light_source") {
      s.type = Type::Light;
      light(w, b, head);
    } else if (b.kind == "color_map" || b.kind == "colour_map") {
      s.type = Type::List;
      Block p;
      p.kind = "pigment";
      Item gi;
      gi.kind = Item::Keyword;
      gi.name = "gradient";
      p.items.push_back(gi);
      Item mi;
      mi.kind = Item::Nested;
      mi.block = e.block;
      p.items.push_back(mi);
      std::string g = pigment_value(p);
      auto at = g.find("color_map = ");
      w.line(head + (at == std::string::npos ? "[]" : g.substr(at + 12, g.size() - at - 12 - 2)));
    } else if (b.kind == "camera") {
      s.type = Type::Camera;
      w.line(fmt::format("// camera {}: written where it is placed", it.name));
    } else {
      unsupported(b.loc, b.kind, "a value rts has (docs/from-povray.md)", false);
      w.line(head + "none  // POV-Ray's " + b.kind + " is not translated");
    }
    define(it.name, s);
    return;
  }
  Text t = expr(e);
  w.line(head + t.s);
  if (!exists || lookup(it.name)->type == Type::Unknown) {
    Symbol s;
    s.type = t.type;
    if (e.kind == Expr::Name)
      if (Symbol* src = lookup(e.text)) s = *src;
    if (it.local || !exists) define(it.name, s);
    else *lookup(it.name) = s;
  }
}

void Translator::place_block(Writer& w, const Block& b) {
  const std::string& k = b.kind;
  if (is_object_kind(k)) return object(w, b, "", true);
  if (k == "light_source") return light(w, b, "");
  if (k == "camera") return camera(w, b);
  if (k == "global_settings") return global_settings(w, b);
  if (k == "background") {
    for (const Item& it : b.items) {
      const Expr* c = it.kind == Item::Value ? it.args[0].get()
                      : (it.kind == Item::Keyword && !it.args.empty()) ? it.args[0].get() : nullptr;
      if (c) {
        w.line("settings { background = " + color_value(*c) + " }");
        return;
      }
    }
    return;
  }
  if (k == "fog") {
    std::string props;
    for (const Item& it : b.items) {
      if (it.kind == Item::Keyword && !it.args.empty()) {
        if (it.name == "distance") props += "  fog_distance = " + value(*it.args[0]);
        else if (it.name == "color" || it.name == "colour") props += "  fog_color = " + color_value(*it.args[0]);
        else if (it.name == "fog_offset") props += "  fog_offset = " + value(*it.args[0]);
        else if (it.name == "fog_alt") props += "  fog_altitude = " + value(*it.args[0]);
        else if (it.name != "fog_type") unsupported(it.loc, it.name, "fog_distance, fog_color, fog_offset, fog_altitude", false);
      } else if (it.kind == Item::Value) {
        props += "  fog_color = " + color_value(*it.args[0]);
      } else if (it.kind == Item::Nested) {
        unsupported(it.loc, it.block->kind, "constant or ground fog", false);
      }
    }
    w.line("settings {" + props.substr(1) + " }");
    return;
  }
  if (k == "sky_sphere") return sky_sphere(w, b);
  if (k == "radiosity") {
    unsupported(b.loc, "radiosity", "settings { integrator = \"path\" }", true);
    return;
  }
  if (k == "media" || k == "photons" || k == "rainbow") {
    unsupported(b.loc, k, k == "media" ? "fog (settings { fog_distance })" : "none", false);
    return;
  }
  unsupported(b.loc, k, "see docs/from-povray.md", false);
}

void Translator::light(Writer& w, const Block& b, const std::string& prefix) {
  std::string position, color = "rgb(1)", point_at = "<0, 0, 0>", radius, falloff, kind = "point_light";
  std::vector<std::string> extra, xforms;
  std::string fade_distance;
  const Expr* fade_power = nullptr;
  int values = 0;
  for (const Item& it : b.items) {
    if (it.kind == Item::Value) {
      if (values == 0) position = vector_value(*it.args[0]);
      else if (values == 1) color = color_value(*it.args[0]);
      ++values;
      continue;
    }
    if (it.kind == Item::Nested) {
      if (it.block->kind == "looks_like" || it.block->kind == "projected_through")
        unsupported(it.loc, it.block->kind, "an object placed at the light (with no shadows from the light)", false);
      else if (it.block->kind == "photons" || it.block->kind == "media_interaction") {}
      else for (std::string& t : transforms(it)) xforms.push_back(std::move(t));
      continue;
    }
    if (it.kind != Item::Keyword) continue;
    const std::string& k = it.name;
    std::vector<std::string> t = transforms(it);
    if (!t.empty()) {
      xforms.insert(xforms.end(), t.begin(), t.end());
    } else if ((k == "color" || k == "colour") && !it.args.empty()) {
      color = color_value(*it.args[0]);
    } else if (k == "spotlight") {
      kind = "spot_light";
    } else if (k == "parallel") {
      kind = "directional_light";
    } else if (k == "point_at" && !it.args.empty()) {
      point_at = vector_value(*it.args[0]);
    } else if (k == "radius" && !it.args.empty()) {
      double r;
      // POV-Ray allows a hot spot of 0 degrees; rts's radius must be above 0.
      radius = literal_number(*it.args[0], r) && r <= 0 ? "0.01" : value(*it.args[0]);
    } else if (k == "falloff" && !it.args.empty()) {
      falloff = value(*it.args[0]);
    } else if (k == "tightness" && !it.args.empty()) {
      double v;
      if (!literal_number(*it.args[0], v) || v != 0)
        unsupported(it.loc, "tightness", "radius and falloff shape the spot's edge", false);
    } else if (k == "area_light" && it.args.size() >= 4) {
      kind = kind == "spot_light" ? "spot_area" : "area_light";
      extra.push_back("u = " + vector_value(*it.args[0]));
      extra.push_back("v = " + vector_value(*it.args[1]));
      extra.push_back(fmt::format("samples = {} * {}", value(*it.args[2]), value(*it.args[3])));
    } else if (k == "circular") {
      extra.push_back("disc = true");
    } else if (k == "adaptive" || k == "jitter" || k == "orient" || k == "media_attenuation" ||
               k == "media_interaction") {
      // sampling refinements: rts samples area lights stratified
    } else if (k == "shadowless") {
      extra.push_back("shadows = false");
    } else if (k == "fade_distance" && !it.args.empty()) {
      fade_distance = value(*it.args[0]);
    } else if (k == "fade_power" && !it.args.empty()) {
      fade_power = it.args[0].get();
    } else if (k == "cylinder") {
      unsupported(it.loc, "cylinder (light)", "spot_light", false);
      kind = "spot_light";
    } else {
      unsupported(it.loc, k, "see docs/rendering.md#lights", false);
    }
  }
  // POV-Ray's light_source begins with its location; without one there is nothing to write
  // (fuzz_pov: `light_source { nt { ... } }` gave `position =` with no value).
  if (position.empty())
    error(b.loc, "a light_source begins with its location vector: light_source { <x, y, z> color rgb <r, g, b> }");
  if (kind == "spot_area") {
    unsupported(b.loc, "spotlight area_light", "area_light or spot_light", false);
    kind = "spot_light";
    extra.clear();
  }
  std::vector<std::string> props;
  if (kind == "directional_light") {
    props.push_back(fmt::format("direction = {} - {}", point_at, position));
  } else {
    props.push_back("position = " + position);
  }
  if (color != "rgb(1)") props.push_back("color = " + color);
  if (kind == "spot_light") {
    props.push_back("point_at = " + point_at);
    if (!radius.empty()) props.push_back("radius = " + radius);
    if (!falloff.empty()) props.push_back("falloff = " + falloff);
  }
  for (const std::string& e : extra) props.push_back(e);
  if (!fade_distance.empty() && kind != "directional_light") {
    // POV-Ray: 2 / (1 + (d / fade_distance)^fade_power); exact in rts's c + l d + q d^2 for
    // powers 1 and 2.
    double p = 0;
    if (!fade_power) {
      // no fade_power: POV-Ray does not fade
    } else if (literal_number(*fade_power, p) && (p == 1 || p == 2)) {
      props.push_back(p == 1 ? fmt::format("attenuation = <0.5, 0.5 / ({}), 0>", fade_distance)
                             : fmt::format("attenuation = <0.5, 0, 0.5 / ({}) ^ 2>", fade_distance));
    } else {
      unsupported(b.loc, "fade_power " + value(*fade_power), "attenuation = <c, l, q> (powers 1 and 2 are exact)", false);
    }
  }
  std::string s;
  for (const std::string& p : props) s += (s.empty() ? " " : "  ") + p;
  std::string suffix;
  for (const std::string& t : xforms) suffix += " " + t;
  w.line(fmt::format("{}{} {{{} }}{}", prefix, kind, s, suffix));
}

void Translator::camera(Writer& w, const Block& b) {
  const Expr *location = nullptr, *look_at = nullptr, *angle = nullptr, *right = nullptr, *up = nullptr,
             *direction = nullptr, *sky = nullptr;
  bool ortho = false;
  std::vector<std::string> extra;
  const Block* src = &b;
  // camera { Declared modifiers }: the declared camera's items first.
  std::vector<Item> all;
  for (const Item& it : src->items) {
    if (it.kind == Item::Value && it.args[0]->kind == Expr::Name)
      if (Symbol* s = lookup(it.args[0]->text); s && s->type == Type::Camera && s->block) {
        all.insert(all.end(), s->block->items.begin(), s->block->items.end());
        continue;
      }
    all.push_back(it);
  }
  for (const Item& it : all) {
    if (it.kind != Item::Keyword) continue;
    const Expr* a = it.args.empty() ? nullptr : it.args[0].get();
    const std::string& k = it.name;
    if (k == "location") location = a;
    else if (k == "look_at") look_at = a;
    else if (k == "angle") angle = a;
    else if (k == "right") right = a;
    else if (k == "up") up = a;
    else if (k == "direction") direction = a;
    else if (k == "sky") sky = a;
    else if (k == "orthographic") ortho = true;
    else if (k == "perspective") ortho = false;
    else if (k == "aperture" && a) extra.push_back("aperture = " + value(*a));
    else if (k == "focal_point" && a) {
      extra.push_back(fmt::format("focus_distance = length({} - {})", vector_value(*a),
                                  location ? vector_value(*location) : "<0, 0, 0>"));
    } else if (k == "blur_samples" || k == "confidence" || k == "variance") {
      // rts's samples per pixel carry the blur: settings { samples }
    } else if (k == "translate" || k == "rotate" || k == "scale" || k == "matrix" || k == "transform") {
      unsupported(it.loc, "camera " + k, "location and look_at written moved", false);
    } else if (k == "fisheye" || k == "panoramic" || k == "spherical" || k == "cylinder" || k == "omnimax" ||
               k == "ultra_wide_angle") {
      unsupported(it.loc, k, "a perspective camera", false);
    } else {
      unsupported(it.loc, k, "see docs/rendering.md#cameras", false);
    }
  }
  glm::dvec3 R(1.33, 0, 0), U(0, 1, 0), D(0, 0, 1);
  bool lr = !right || literal3(right, R), lu = !up || literal3(up, U), ld = !direction || literal3(direction, D);
  bool image_aspect = false;  // right x*image_width/image_height: the image's own aspect
  if (right && !lr) {
    std::function<bool(const Expr&)> mentions = [&](const Expr& e) {
      if (e.kind == Expr::Name && (e.text == "image_width" || e.text == "image_height")) return true;
      for (const ExprPtr& c : e.args)
        if (mentions(*c)) return true;
      return false;
    };
    if (mentions(*right)) {
      image_aspect = true;
      R = glm::dvec3(4.0 / 3.0, 0, 0);
      lr = true;
    }
  }
  camera_seen_ = true;
  std::vector<std::string> props;
  if (ortho) props.push_back("projection = \"orthographic\"");
  std::string pos = location ? vector_value(*location) : "<0, 0, 0>";
  props.push_back("position = " + pos);
  // POV-Ray's camera is its three vectors: rts's camera takes them as given, so the picture is
  // POV-Ray's, its 1.33 (not 4/3) default aspect included. With look_at they are first turned
  // towards it, as POV-Ray does, keeping their lengths; `angle` sets direction's length.
  glm::dvec3 L(0), A(0), S(0, 1, 0);
  double angle_deg = 0;
  const bool literal_view = lr && lu && ld && !image_aspect && (!location || literal3(location, L)) &&
                            (!look_at || literal3(look_at, A)) && (!sky || literal3(sky, S)) &&
                            (!angle || literal_number(*angle, angle_deg));
  if (literal_view && !(ortho && angle) && !(angle && (angle_deg <= 0 || angle_deg >= 180))) {
    if (angle) D = glm::normalize(D) * (0.5 * glm::length(R) / std::tan(angle_deg * M_PI / 360));
    if (look_at && glm::length(A - L) > 1e-9) {
      const double dl = glm::length(D), ul = glm::length(U), rl = glm::length(R);
      const double handedness = glm::dot(glm::cross(U, D), R);
      glm::dvec3 d = glm::normalize(A - L), r = glm::cross(S, d);
      if (glm::length(r) < 1e-9) r = R;  // looking along the sky: POV-Ray keeps its right vector
      r = glm::normalize(r);
      glm::dvec3 u = glm::cross(d, r);
      D = d * dl;
      R = r * (handedness > 0 ? rl : -rl);
      U = u * ul;
      w.line(fmt::format("// POV-Ray's look_at {}: its direction, right and up turned towards it", vec(A)));
    }
    auto clean = [](glm::dvec3 v) {
      for (int i = 0; i < 3; ++i)
        if (std::abs(v[i]) < 1e-12) v[i] = 0;
      return vec(v);
    };
    props.push_back("direction = " + clean(D));
    props.push_back("right = " + clean(R));
    props.push_back("up = " + clean(U));
  } else {
    if (look_at) props.push_back("look_at = " + vector_value(*look_at));
    else props.push_back(fmt::format("look_at = {} + {}", pos, direction ? vector_value(*direction) : "<0, 0, 1>"));
    if (sky) props.push_back("up = " + vector_value(*sky));
    if (lr && lu && ld) {
      if (R.x < 0) props.push_back("handedness = \"right\"");
      double rl = glm::length(R), ul = glm::length(U), dl = glm::length(D);
      if (ortho) {
        props.push_back("view_width = " + num(rl));
        if (angle) unsupported(b.loc, "orthographic angle", "view_width", false);
      } else if (angle) {
        double a;
        if (literal_number(*angle, a) && a >= 180) {
          unsupported(b.loc, fmt::format("angle {}", num(a)), "a perspective camera's fov below 180 (179 is used)",
                      false);
          props.push_back("fov = 179");
        } else {
          props.push_back("fov = " + value(*angle));
        }
      } else if (image_aspect) {
        props.push_back("fov = " + num(2 * std::atan(ul / (2 * dl)) * 180 / M_PI));
        props.push_back("fov_axis = \"vertical\"");
      } else {
        props.push_back("fov = " + num(2 * std::atan(rl / (2 * dl)) * 180 / M_PI));
      }
      if (!image_aspect && std::abs(rl / ul - 4.0 / 3.0) > 0.01 && !ortho)
        warn(b.loc, fmt::format("the camera's right/up ratio is {} (POV-Ray's default 1.33); rts follows the "
                                "image's aspect ratio (render at {}:1 for the same picture)",
                                num(rl / ul), num(rl / ul)));
    } else {
      unsupported(b.loc, "computed right/up/direction", "fov written as a number", false);
      if (angle) props.push_back("fov = " + value(*angle));
    }
  }
  props.insert(props.end(), extra.begin(), extra.end());
  w.open("camera");
  for (const std::string& p : props) w.line(p);
  w.close();
}

void Translator::global_settings(Writer& w, const Block& b) {
  std::vector<std::string> props;
  for (const Item& it : b.items) {
    if (it.kind == Item::Nested) {
      if (it.block->kind == "radiosity")
        unsupported(it.loc, "radiosity", "settings { integrator = \"path\" }", true);
      else if (it.block->kind != "photons")
        unsupported(it.loc, it.block->kind, "see docs/rendering.md", false);
      continue;
    }
    if (it.kind != Item::Keyword || it.args.empty()) continue;
    const std::string& k = it.name;
    if (k == "assumed_gamma") {
      double g;
      gamma_seen_ = true;
      if (literal_number(*it.args[0], g)) assumed_gamma_ = g;
      else unsupported(it.loc, "assumed_gamma (computed)", "output_gamma = \"srgb\" or \"linear\"", false);
    } else if (k == "ambient_light") {
      props.push_back("ambient_light = " + color_value(*it.args[0]));
    } else if (k == "max_trace_level") {
      props.push_back("max_depth = " + value(*it.args[0]));
    } else if (k == "adc_bailout" || k == "number_of_waves" || k == "noise_generator" || k == "charset" ||
               k == "max_intersections" || k == "hf_gray_16") {
      // no effect on rts's picture (rts's noise is its own)
    } else {
      unsupported(it.loc, k, "see docs/rendering.md#settings", false);
    }
  }
  if (!props.empty()) {
    std::string s;
    for (const std::string& p : props) s += (s.empty() ? " " : "  ") + p;
    w.line("settings {" + s + " }");
  }
}

void Translator::declare_library_file(const std::string& file) {
  if (!library_files_.insert(file).second) return;
  std::ifstream lib(fs::path(opt_.stdlib_dir) / file);
  std::string line;
  while (std::getline(lib, line)) {
    if (line.rfind("include \"", 0) == 0) {
      // rts's include makes the included file's names visible too (textures.rts: metals, glass,
      // finish ...).
      std::size_t e = line.find('"', 9);
      if (e != std::string::npos) declare_library_file(line.substr(9, e - 9));
    } else if (line.rfind("let ", 0) == 0) {
      std::size_t e = line.find_first_of(" =", 4);
      std::string n = line.substr(4, e == std::string::npos ? std::string::npos : e - 4);
      library_names_.insert(n);
      Symbol s{line.find("rgb(") != std::string::npos ? Type::Color : Type::Unknown, nullptr, ""};
      if (line.find("material") != std::string::npos) s.type = Type::Material;
      // `let Cube = box { ...`, `let Cone_Y = cone { ...`, `let Ellipsoid = Sphere`: an object of
      // that kind (a texture on it then derives the shape, or wraps a CSG block).
      std::size_t eq = line.find('=');
      std::size_t w0 = eq == std::string::npos ? std::string::npos : line.find_first_not_of(' ', eq + 1);
      if (w0 != std::string::npos) {
        std::size_t w1 = line.find_first_of(" {", w0);
        std::string word = line.substr(w0, w1 == std::string::npos ? std::string::npos : w1 - w0);
        if (is_object_kind(word) && line.find('{', w0) != std::string::npos) {
          s = Symbol{Type::Object, nullptr, word};
        } else if (auto known = scopes_.front().find(word);
                   known != scopes_.front().end() && known->second.type == Type::Object) {
          s = known->second;
        }
      }
      scopes_.front()[n] = s;
      // A one-line material of literal properties: kept for finish { N } and interior { N }.
      std::size_t open = line.find("= material { "), close = line.find(" }");
      if (open != std::string::npos && close != std::string::npos && close > open) {
        std::string body = line.substr(open + 13, close - open - 13);
        MaterialProps props;
        std::size_t at = 0;
        while (at < body.size()) {
          std::size_t next = body.find("  ", at);
          std::string pair = body.substr(at, next == std::string::npos ? std::string::npos : next - at);
          std::size_t eq = pair.find(" = ");
          if (eq != std::string::npos) props.set(pair.substr(0, eq), pair.substr(eq + 3));
          if (next == std::string::npos) break;
          at = next + 2;
        }
        library_parts_[n] = props;
      }
    } else if (line.rfind("macro ", 0) == 0) {
      std::size_t e = line.find('(', 6);
      std::string n = line.substr(6, e == std::string::npos ? std::string::npos : e - 6);
      library_names_.insert(n);
      scopes_.front()[n] = Symbol{Type::Macro, nullptr, ""};
    }
  }
}

void Translator::include(Writer& w, const Item& it) {
  const std::string& name = it.name;
  fs::path found;
  std::error_code ec;
  std::vector<std::string> dirs = {dir_};
  dirs.insert(dirs.end(), opt_.include_dirs.begin(), opt_.include_dirs.end());
  for (const std::string& d : dirs) {
    fs::path p = fs::path(d.empty() ? "." : d) / name;
    if (fs::is_regular_file(p, ec)) {
      found = p;
      break;
    }
  }
  std::string base = fs::path(name).filename().string();
  auto std_it = standard_includes().find(base);
  if (found.empty() || std_it != standard_includes().end() || unshipped_includes().count(base)) {
    if (std_it != standard_includes().end()) {
      if (std_it->second.empty()) {
        w.line(fmt::format("// #include \"{}\": rts's built-ins cover it", name));
        return;
      }
      w.line(fmt::format("include \"{}\"", std_it->second));
      // The names the library file defines: declared for the translation.
      if (!opt_.stdlib_dir.empty()) declare_library_file(fs::path(std_it->second).stem().string() + ".rts");
      return;
    }
    if (unshipped_includes().count(base)) {
      unsupported(it.loc, "#include \"" + name + "\"", "rts's standard library has no " + base +
                  " yet (docs/library.md); its names must be written in the scene", true);
      w.line(fmt::format("// #include \"{}\": not in rts's standard library", name));
      return;
    }
    error(it.loc, fmt::format("cannot find include file '{}' (searched {} and the -I folders)", name,
                              dir_.empty() ? "." : dir_));
  }
  // The user's own include: translated to its own .rts beside the scene, once.
  std::string canonical = fs::weakly_canonical(found, ec).string();
  std::string out_name = fs::path(name).stem().string() + ".rts";
  if (!included_.count(canonical)) {
    included_.insert(canonical);
    if (++include_depth_ > 50) error(it.loc, "includes nested more than 50 deep");
    std::ifstream in(found, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::string saved_file = file_, saved_dir = dir_;
    Program p;
    try {
      p = read_program(text.str(), name, reader_names_);
    } catch (const SyntaxError& e) {
      throw PovError{Diagnostic{found.string(), e.loc.line, e.loc.col, e.message}};
    }
    Writer iw;
    iw.line(fmt::format("// Imported by `rts import` from {} (a POV-Ray include file).", name));
    iw.blank();
    this->file(p, found.string(), iw);
    file_ = saved_file;
    dir_ = saved_dir;
    --include_depth_;
    result_.includes.push_back(PovOutputFile{out_name, iw.text()});
  }
  w.line(fmt::format("include \"{}\"", out_name));
}

// ---- files ----

void Translator::file(const Program& p, const std::string& path, Writer& w) {
  file_ = path;
  dir_ = fs::path(path).parent_path().string();
  items(w, p.items, true);
  w.comments(p.trailing_comments);
}

void Translator::header(Writer& w, const std::string& source_name) {
  w.line(fmt::format("// Imported by `rts import` from {} (POV-Ray scene language).", source_name));
  w.line("// POV-Ray's conventions are written out: its default finish (ambient 0.1, diffuse 0.6), its black");
  w.line("// default pigment, its camera and its output gamma. See docs/from-povray.md.");
}

void Translator::footer(Writer& w) {
  // POV-Ray 3.7: a scene with assumed_gamma 1.0 (or #version 3.7 without assumed_gamma) is
  // written with the sRGB curve; an older scene (no #version, no assumed_gamma) with none.
  bool srgb = gamma_seen_ ? std::abs(assumed_gamma_ - 1.0) < 1e-9 : version_ >= 3.7;
  if (gamma_seen_ && !srgb && std::abs(assumed_gamma_ - 2.2) > 1e-6)
    warn(Loc{}, fmt::format("assumed_gamma {} is taken as 2.2 (no output gamma encoding)", num(assumed_gamma_)));
  if (opt_.width > 0 || opt_.height > 0 || opt_.antialias_threshold >= 0) {
    // POV-Ray's render options (an .ini file): the image size, and +A as a fixed sample count.
    std::string s;
    if (opt_.width > 0) s += fmt::format("  width = {}", opt_.width);
    if (opt_.height > 0) s += fmt::format("  height = {}", opt_.height);
    w.blank();
    if (opt_.antialias_threshold >= 0) {
      s += "  samples = 9";
      w.line(fmt::format("// POV-Ray's +A{}: it supersamples a pixel that differs from its neighbours by more than {}",
                         num(opt_.antialias_threshold), num(opt_.antialias_threshold)));
      w.line("// with up to 3x3 rays (Antialias_Depth 3); here 9 samples in every pixel (or --target-error).");
    } else {
      w.line("// POV-Ray's render options (its .ini file).");
    }
    w.line("settings {" + s.substr(1) + " }");
  }
  if (!camera_seen_) {
    w.blank();
    w.line("// POV-Ray's default camera: at the origin looking along +z, its 1.33 wide right vector.");
    w.line("camera { position = <0, 0, 0>  direction = <0, 0, 1>  right = <1.33, 0, 0>  up = <0, 1, 0> }");
  }
  w.blank();
  w.line(srgb ? "// POV-Ray 3.7 with assumed_gamma 1.0: the image is sRGB-encoded."
              : "// POV-Ray without #version 3.7 / assumed_gamma 1.0 writes the image without gamma encoding.");
  w.line(fmt::format("settings {{ output_gamma = \"{}\" }}", srgb ? "srgb" : "linear"));
}

// The names the user's include files declare, before the main file is read: the reader needs
// them to tell a lower-case name that is a value from a keyword. Each file is read once: a file
// that includes itself twice would otherwise be read 2^20 times.
void collect_declared(const std::string& text, const std::string& dir, const PovOptions& options,
                      std::set<std::string>& names, std::set<std::string>& seen, int depth) {
  if (depth > 20) return;
  std::vector<Token> toks;
  try {
    toks = tokenize(text);
  } catch (const SyntaxError&) {
    return;  // reported when the file itself is read
  }
  for (std::size_t i = 0; i + 1 < toks.size(); ++i) {
    if (toks[i].kind != Token::Directive) continue;
    const std::string& d = toks[i].text;
    if ((d == "declare" || d == "local" || d == "macro") && toks[i + 1].kind == Token::Name)
      names.insert(toks[i + 1].text);
    if (d == "include" && toks[i + 1].kind == Token::String) {
      std::vector<std::string> dirs = {dir};
      dirs.insert(dirs.end(), options.include_dirs.begin(), options.include_dirs.end());
      for (const std::string& folder : dirs) {
        fs::path p = fs::path(folder.empty() ? "." : folder) / toks[i + 1].text;
        std::error_code ec;
        if (!fs::is_regular_file(p, ec) || standard_includes().count(p.filename().string())) continue;
        if (!seen.insert(fs::weakly_canonical(p, ec).string()).second) break;
        std::ifstream in(p, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        collect_declared(buffer.str(), p.parent_path().string(), options, names, seen, depth + 1);
        break;
      }
    }
  }
}

bool looks_like_pov(const std::string& text) {
  std::string head = text.substr(0, 1 << 16);
  for (const char* marker : {"#include", "#declare", "#version", "#local", "#macro"})
    if (head.find(marker) != std::string::npos) return true;
  for (const char* block : {"camera", "light_source"}) {
    std::size_t at = 0;
    while ((at = head.find(block, at)) != std::string::npos) {
      std::size_t i = at + std::string(block).size();
      while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
      if (i < head.size() && head[i] == '{') return true;
      at = i;
    }
  }
  return false;
}

PovResult import_pov(const std::string& text, const PovOptions& options) {
  PovResult result;
  Translator t(options, result);
  t.library_known_ = !options.stdlib_dir.empty() && fs::is_directory(options.stdlib_dir);
  Program p;
  try {
    std::set<std::string> seen;
    collect_declared(text, fs::path(options.source_path).parent_path().string(), options, t.reader_names_, seen, 0);
    p = read_program(text, options.source_path, t.reader_names_);
  } catch (const SyntaxError& e) {
    throw PovError{Diagnostic{options.source_path, e.loc.line, e.loc.col, e.message}};
  }
  Writer body;
  t.file(p, options.source_path, body);
  Writer out;
  t.header(out, fs::path(options.source_path).filename().string());
  if (t.helpers_.count("pov_int")) {
    out.blank();
    out.line("// POV-Ray's int(): rounds towards zero.");
    out.line("macro pov_int(x) { if x < 0 { return ceil(x) }  return floor(x) }");
  }
  out.blank();
  std::string s = out.text() + body.text();
  Writer tail;
  t.footer(tail);
  result.rts = s + tail.text();
  return result;
}

}  // namespace rts::import::pov
