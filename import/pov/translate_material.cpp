// POV-Ray textures as rts materials: pigment, finish, normal and interior (and whole
// texture/material blocks) merged into one material with POV-Ray's default finish written
// out. Pigments (colours, patterns, maps and image maps) are in translate_pigment.cpp,
// objects in translate_object.cpp.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

bool text_number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}

namespace {

bool is_texture_part(const std::string& k) {
  return k == "texture" || k == "pigment" || k == "finish" || k == "normal" || k == "interior" || k == "material";
}

}  // namespace

void MaterialProps::set(const std::string& name, const std::string& value) {
  for (auto& p : props)
    if (p.first == name) {
      p.second = value;
      return;
    }
  props.emplace_back(name, value);
}

bool MaterialProps::has(const std::string& name) const {
  return std::any_of(props.begin(), props.end(), [&](const auto& p) { return p.first == name; });
}

void Translator::default_finish(MaterialProps& m) const {
  // POV-Ray's default texture: a black pigment, ambient 0.1, diffuse 0.6 (rts's own default
  // diffuse is 0.7), changed by #default.
  // A texture's own finish starts from #default's and changes what it names: its own values win.
  for (const auto& p : default_texture_.props)
    if (p.first != "color" && p.first != "texture" && !m.has(p.first)) m.set(p.first, p.second);
  if (!m.has("ambient")) m.set("ambient", "0.1");
  if (!m.has("diffuse")) m.set("diffuse", "0.6");
}

std::string Translator::material_text(const MaterialProps& m, bool with_defaults) {
  if (m.layered) {  // each layer carries POV-Ray's defaults; it takes nothing else
    for (const auto& p : m.props)
      if (p.first == "layers") return "material { layers = " + p.second + " }";
  }
  if (m.chosen) {  // its choices carry POV-Ray's defaults; it takes nothing else
    std::string s;
    for (const auto& p : m.props)
      if (p.first == "pattern" || p.first == "materials") s += (s.empty() ? "" : "  ") + p.first + " = " + p.second;
    return "material { " + s + " }";
  }
  MaterialProps full;
  if (with_defaults && m.base.empty()) {
    // #default's pigment, else POV-Ray's black; then the finish defaults, then this texture's.
    bool colored = m.has("color") || m.has("texture");
    if (!colored) {
      bool default_color = false;
      for (const auto& p : default_texture_.props)
        if (p.first == "color" || p.first == "texture") full.set(p.first, p.second), default_color = true;
      if (!default_color) full.set("color", "rgb(0)");
    }
    for (const auto& p : m.props) full.set(p.first, p.second);
    default_finish(full);
    if (m.opacity < 1.0) {
      for (auto& p : full.props) {
        if (p.first != "ambient" && p.first != "diffuse") continue;
        double v = 0;
        p.second = text_number(p.second, v) ? num(v * m.opacity) : fmt::format("{} * {}", p.second, num(m.opacity));
      }
    }
    // Keep the order readable: colour first, then the finish in POV-Ray's order.
    std::stable_sort(full.props.begin(), full.props.end(), [](const auto& a, const auto& b) {
      auto rank = [](const std::string& n) {
        static const std::vector<std::string> order = {"color", "texture", "ambient", "diffuse", "brilliance",
                                                       "specular", "shininess", "metallic", "reflect", "transmit",
                                                       "ior", "emission"};
        auto it = std::find(order.begin(), order.end(), n);
        return static_cast<int>(it - order.begin());
      };
      return rank(a.first) < rank(b.first);
    });
  } else {
    full = m;
  }
  std::string s;
  for (const auto& p : full.props) s += (s.empty() ? "" : "  ") + p.first + " = " + p.second;
  if (!m.base.empty()) return full.props.empty() ? m.base : m.base + " with { " + s + " }";
  return "material { " + s + " }";
}

void Translator::finish(const Block& b, MaterialProps& m) {
  std::string roughness;  // POV-Ray's default 0.05: a Blinn exponent of 20
  bool specular = false;
  for (const Item& it : b.items) {
    if (it.kind == Item::Value && it.args[0]->kind == Expr::Name) {
      if (Symbol* s = lookup(it.args[0]->text); s && s->type == Type::Finish) {
        for (const auto& p : s->props.props) m.set(p.first, p.second);
        continue;
      }
      // A library finish (Shiny, Phong_Glossy, F_MetalC ...): its properties, which the
      // items after it may change as in POV-Ray.
      MaterialProps part;
      if (library_part(it.args[0]->text, part)) {
        for (const auto& p : part.props) m.set(p.first, p.second);
        if (part.has("highlight")) {
          // A Blinn finish's exponent stays unless a later roughness changes it.
          for (const auto& p : part.props)
            if (p.first == "shininess") roughness = p.second;
        }
        continue;
      }
      missing_name(it.loc, it.args[0]->text, "finish");
      continue;
    }
    if (it.kind == Item::Nested && it.block->kind == "reflection") {
      // reflection { [rmin,] rmax fresnel falloff metallic }: rmax is `reflect`; a different
      // rmin is rts's variable reflection, reflect_min head-on rising to reflect (POV-Ray's).
      std::vector<const Expr*> values;
      for (const Item& v : it.block->items)
        if (v.kind == Item::Value) values.push_back(v.args[0].get());
      // A number stays one (rts reads it as a grey); a colour is a colour.
      auto amount = [&](const Expr& e) {
        double k;
        return literal_number(e, k) ? num(k) : color_value(e);
      };
      if (!values.empty()) m.set("reflect", amount(*values.back()));
      if (values.size() >= 2) {
        double lo = 0, hi = 0;
        const bool same = literal_number(*values[0], lo) && literal_number(*values.back(), hi) && lo == hi;
        if (!same) m.set("reflect_min", amount(*values[0]));
      }
      for (const Item& v : it.block->items) {
        if (v.kind == Item::Keyword && v.name == "fresnel" && (v.args.empty() || value(*v.args[0]) != "0"))
          m.set("fresnel", "true");
        if (v.kind == Item::Keyword && v.name == "falloff" && !v.args.empty()) m.set("reflect_falloff", value(*v.args[0]));
        if (v.kind == Item::Keyword && v.name == "metallic")  // `metallic` alone is 1
          m.set("reflect_metallic", v.args.empty() ? "1" : value(*v.args[0]));
        if (v.kind == Item::Keyword && v.name == "exponent")
          unsupported(v.loc, "reflection exponent", "reflect and reflect_min (the reflection's own brightness)", false);
      }
      continue;
    }
    if (it.kind != Item::Keyword) {
      if (it.kind == Item::Nested) unsupported(it.loc, it.block->kind, "rts's material properties", false);
      continue;
    }
    const std::string& k = it.name;
    std::string v = it.args.empty() ? "" : value(*it.args[0]);
    if (k == "ambient" && !v.empty()) {
      // A colour weighs each channel (rts's ambient = rgb(...)); golds.inc's finishes have one.
      double f;
      if (!literal_number(*it.args[0], f) && it.args[0]->kind == Expr::Color) v = color_value(*it.args[0]);
      m.set("ambient", v);
    } else if (k == "diffuse" && !v.empty()) {
      m.set("diffuse", v);
    } else if (k == "phong" && !v.empty()) {
      m.set("specular", v);
      if (!m.has("shininess")) m.set("shininess", "40");  // POV-Ray's default phong_size
    } else if (k == "phong_size" && !v.empty()) {
      m.set("shininess", v);
    } else if (k == "specular" && !v.empty()) {
      m.set("specular", v);
      specular = true;
    } else if (k == "roughness" && !v.empty()) {
      double r;
      roughness = literal_number(*it.args[0], r) && r > 0 ? num(1 / r) : "1 / (" + v + ")";  // roughness 1/300: 1 / (1 / 300)
    } else if (k == "reflection" && !v.empty()) {
      m.set("reflect", v);
    } else if (k == "emission" && !v.empty()) {
      m.set("emission", color_value(*it.args[0]));
    } else if (k == "conserve_energy" || k == "crand" || k == "reflection_exponent") {
      // no effect worth a warning in the Whitted image
    } else if (k == "brilliance" && !v.empty()) {
      m.set("brilliance", v);
    } else if (k == "metallic") {
      // `metallic` alone is metallic 1; `metallic on` / `off` (POV-Ray's booleans) 1 or 0
      const Expr* a = it.args.empty() ? nullptr : it.args[0].get();
      const std::string word = a && a->kind == Expr::Name ? a->text : "";
      if (word == "on" || word == "true" || word == "yes") m.set("metallic", "1");
      else if (word == "off" || word == "false" || word == "no") m.set("metallic", "0");
      else m.set("metallic", v.empty() ? "1" : v);
    } else if (k == "irid" || k == "subsurface") {
      unsupported(it.loc, k, "not in rts's material model", false);
    } else {
      unsupported(it.loc, k, "rts's material properties (docs/rendering.md#materials)", false);
    }
  }
  if (specular) {
    // POV-Ray's specular is a Blinn highlight, (N.H)^(1/roughness): rts's highlight = "blinn".
    m.set("highlight", "\"blinn\"");
    m.set("shininess", roughness.empty() ? "20" : roughness);
  }
}

bool Translator::library_part(const std::string& name, MaterialProps& m) {
  // Only the library's own name: a scene's #declare of the same name (a block) wins.
  Symbol* s = lookup(name);
  if (!s || s->block) return false;
  auto it = library_parts_.find(name);
  if (it == library_parts_.end()) return false;
  m = it->second;
  return true;
}

void Translator::interior(const Block& b, MaterialProps& m) {
  bool media_seen = false;
  std::string fade_distance, fade_power, fade_color;  // POV-Ray's fade: written when it has a distance
  for (const Item& it : b.items) {
    if (it.kind == Item::Value && it.args[0]->kind == Expr::Name) {
      if (Symbol* s = lookup(it.args[0]->text); s && s->type == Type::Interior) {
        for (const auto& p : s->props.props) m.set(p.first, p.second);
        continue;
      }
      MaterialProps part;  // a library interior (I_Glass ...): its index
      if (library_part(it.args[0]->text, part)) {
        for (const auto& p : part.props) m.set(p.first, p.second);
        continue;
      }
      missing_name(it.loc, it.args[0]->text, "interior");
      continue;
    }
    if (it.kind == Item::Value && it.args[0]->kind == Expr::Call && it.args[0]->args.size() == 1 &&
        (it.args[0]->text == "I_Glass_Exp" || it.args[0]->text == "I_Glass_Sqr") && library_names_.count(it.args[0]->text)) {
      // glass.inc's macros of a fade distance: glass's index, faded exponentially or by the
      // inverse square over that distance (glass.rts has them as macros of a material).
      m.set("ior", "1.5");
      fade_distance = value(*it.args[0]->args[0]);
      fade_power = it.args[0]->text == "I_Glass_Exp" ? "1001" : "2";
      continue;
    }
    if (it.kind == Item::Value) {
      unsupported(it.loc, "interior value", "an interior's ior, fade and media, or a declared interior", false);
      continue;
    }
    if (it.kind == Item::Keyword && it.name == "ior" && !it.args.empty()) {
      m.set("ior", value(*it.args[0]));
    } else if (it.kind == Item::Keyword && (it.name == "fade_distance" || it.name == "fade_power") &&
               !it.args.empty()) {
      (it.name == "fade_distance" ? fade_distance : fade_power) = value(*it.args[0]);
    } else if (it.kind == Item::Keyword && (it.name == "fade_color" || it.name == "fade_colour") &&
               !it.args.empty()) {
      fade_color = color_value(*it.args[0]);
    } else if (it.kind == Item::Keyword && (it.name == "dispersion" || it.name == "caustics")) {
      unsupported(it.loc, it.name, "media_absorption (Beer-Lambert absorption inside the object)", false);
    } else if (it.kind == Item::Nested && it.block->kind == "media") {
      if (media_seen) {
        unsupported(it.loc, "media", "one medium per object (POV-Ray adds several)", false);
        continue;
      }
      media_seen = true;
      for (const auto& p : media(*it.block)) m.set(p.first, p.second);
    }
  }
  // POV-Ray fades only with a fade_distance (its fade_power defaults to 0: light halved, what
  // rts's default gives too); a distance of 0 is none.
  double d = 1.0;
  const bool literal = !fade_distance.empty() && text_number(fade_distance, d);
  if (!fade_distance.empty() && !(literal && !(d > 0.0))) {
    m.set("fade_distance", fade_distance);
    if (!fade_power.empty()) m.set("fade_power", fade_power);
    if (!fade_color.empty()) m.set("fade_color", fade_color);
  }
}

void Translator::normal(const Block& b, MaterialProps& m) {
  static const std::set<std::string> patterns = {"bumps", "dents", "ripples", "waves", "wrinkles", "granite",
                                                 "marble", "wood", "agate", "bozo", "spotted", "crackle", "cells",
                                                 "leopard", "onion", "gradient", "radial", "boxed", "cylindrical",
                                                 "planar", "spherical"};
  std::string pattern, amount = "0.5";
  std::vector<std::string> props, xforms;
  for (const Item& it : b.items) {
    if (it.kind != Item::Keyword) {
      if (it.kind == Item::Nested) unsupported(it.loc, it.block->kind, "bump = <pattern> { }", false);
      continue;
    }
    if (patterns.count(it.name)) {
      pattern = it.name;
      std::size_t first = 0;
      std::vector<double> v;
      if (it.name == "gradient" && !it.args.empty() && literal_vector(*it.args[0], v) && v.size() == 3) {
        // `gradient x, 0.5`: the orientation first, then the amount.
        props.push_back(std::string("axis = ") + (v[0] != 0 ? "\"x\"" : v[2] != 0 ? "\"z\"" : "\"y\""));
        first = 1;
      }
      if (it.args.size() > first) amount = value(*it.args[first]);
      continue;
    }
    if (it.name == "turbulence" || it.name == "octaves" || it.name == "frequency" || it.name == "phase" ||
        it.name == "omega" || it.name == "lambda") {
      if (!it.args.empty()) props.push_back(it.name + " = " + value(*it.args[0]));
      continue;
    }
    if (it.name == "bump_size" && !it.args.empty()) {
      amount = value(*it.args[0]);
      continue;
    }
    std::vector<std::string> t = transforms(it);
    if (!t.empty()) {
      xforms.insert(xforms.end(), t.begin(), t.end());
      continue;
    }
    unsupported(it.loc, it.name, "bump = <pattern> { }  bump_scale = ...", false);
  }
  if (pattern.empty()) return;
  std::string body, suffix;
  for (const std::string& p : props) body += "  " + p;
  for (const std::string& t : xforms) suffix += " " + t;
  m.set("bump", pattern + " {" + body + (body.empty() ? "}" : " }") + suffix);
  // rts's strength is the slope's: about POV-Ray's amount times the pattern's scale
  // (docs/from-povray.md); 0.1 of the amount is the unscaled case.
  m.set("bump_scale", "0.2 * " + amount);
}

void Translator::layered_texture(const std::vector<const Item*>& layers, const std::vector<const Item*>& base_parts,
                                 MaterialProps& m) {
  // POV-Ray's layered texture: the first texture at the bottom, each later one over it. rts's
  // layered material reads a coat's transmit (its colour's, or its colour map's) as what shows
  // through it and weights the coat's diffuse and ambient by the rest itself, so a coat's
  // opacity is not written into it (MaterialProps::opacity).
  std::string list;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    MaterialProps layer;
    texture_part(*layers[i], layer);
    if (i == 0)
      for (const Item* part : base_parts) texture_part(*part, layer);  // the object's interior
    else
      layer.opacity = 1.0;
    list += (i ? ", " : "") + material_text(layer, true);
  }
  m = MaterialProps{};
  m.layered = true;
  m.set("layers", "[" + list + "]");
}

void Translator::texture_part(const Item& it, MaterialProps& m) {
  const Block& b = *it.block;
  if (b.kind == "pigment") return pigment(b, m);
  if (b.kind == "finish") return finish(b, m);
  if (b.kind == "interior") return interior(b, m);
  if (b.kind == "normal") return normal(b, m);
  if (b.kind == "layered_texture") {
    std::vector<const Item*> layers;
    for (const Item& layer : b.items) layers.push_back(&layer);
    return layered_texture(layers, {}, m);
  }
  if (b.kind == "texture" && texture_pattern(b, m)) return;
  if (b.kind == "texture" || b.kind == "material") {
    for (const Item& part : b.items) {
      if (part.kind == Item::Value && part.args[0]->kind == Expr::Name) {
        Symbol* s = lookup(part.args[0]->text);
        if (s && s->type == Type::Material && s->block) {
          m.base = rename(part.args[0]->text);
          continue;
        }
        if (!s) {  // a texture from an include (textures.inc): derived from
          if (!missing_name(part.loc, part.args[0]->text, "texture")) m.base = rename(part.args[0]->text);
          continue;
        }
        if (s->type == Type::Pigment) {
          // A pigment where a texture belongs (`texture { Jade }`, which POV-Ray refuses): its colour.
          m.set("color", rename(part.args[0]->text));
          continue;
        }
      }
      if (part.kind == Item::Value) {
        const Expr& e = *part.args[0];
        if (Symbol* s = e.kind == Expr::Call ? lookup(e.text) : nullptr;
            s && s->type == Type::Macro && (s->object_kind == "pigment" || s->object_kind == "pigment colour")) {
          // A macro giving a pigment: the material's pattern (or its colour).
          m.set(s->object_kind == "pigment" ? "texture" : "color", value(e));
          continue;
        }
        m.base = value(e);  // a macro call giving a texture
        continue;
      }
      if (part.kind == Item::Nested && is_texture_part(part.block->kind)) {
        texture_part(part, m);
        continue;
      }
      if (part.kind == Item::Nested && (part.block->kind == "texture_map" || part.block->kind == "material_map")) {
        unsupported(part.loc, part.block->kind, "one texture (or a pattern's color_map)", false);
        continue;
      }
      std::vector<std::string> t = transforms(part);
      if (!t.empty()) {
        // A transform of a whole texture moves its pattern, and a declared texture's
        // (`texture { T_Grnt0a scale 2 }`: rts moves a material's textures with it).
        std::string suffix;
        for (const std::string& x : t) suffix += " " + x;
        for (auto& p : m.props)
          if (p.first == "texture" || p.first == "bump") p.second = "(" + p.second + ")" + suffix;
        if (!m.base.empty()) m.base = "(" + m.base + suffix + ")";
        continue;
      }
      if (part.kind == Item::Keyword) unsupported(part.loc, part.name, "rts's material properties", false);
    }
  }
}

}  // namespace rts::import::pov
