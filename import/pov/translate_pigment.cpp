// POV-Ray pigments as rts material properties: plain colours (filter and transmit become
// opacity), patterns with their colour maps and warps, pigment maps and image maps (the file
// found where POV-Ray would look). Called from the material translation in
// translate_material.cpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

namespace {

// The largest component of a literal `rgb(...)` colour; 1 when it is not one.
double max_component(const std::string& c) {
  if (c.rfind("rgb(", 0) != 0 || c.back() != ')') return 1.0;
  double best = 0.0;
  std::size_t pos = 4;
  int count = 0;
  while (pos < c.size() - 1) {
    std::size_t end = c.find_first_of(",)", pos);
    double v = 0;
    if (!text_number(c.substr(pos, end - pos), v)) return 1.0;
    best = std::max(best, v);
    ++count;
    pos = end + 1;
  }
  return count > 0 ? best : 1.0;
}

}  // namespace

std::string Translator::pigment_value(const Block& b) {
  MaterialProps m;
  pigment(b, m);
  for (const auto& p : m.props)
    if (p.first == "color" || p.first == "texture") return p.second;
  return "rgb(0)";
}

bool Translator::pigment_pattern(const std::string& k) {
  static const std::set<std::string> patterns = {"bozo",     "spotted", "granite", "marble",  "wood",    "agate",
                                                 "onion",    "leopard", "wrinkles", "crackle", "cells",   "bumps",
                                                 "dents",    "ripples", "waves",   "gradient", "radial", "spiral1",
                                                 "spiral2",  "boxed",   "cylindrical", "planar", "spherical"};
  return patterns.count(k) > 0;
}

void Translator::pigment(const Block& b, MaterialProps& m) {
  std::string pattern;       // a pattern block's name (checker, marble, ...)
  std::vector<std::string> colors, pattern_props, xforms;
  std::string map;           // color_map as an rts list
  std::string named_pattern;  // `pigment { P_WoodGrain1A color_map { ... } }`: a declared pigment
  std::string image;          // an image_map, moved by the pigment's transforms
  std::vector<std::string> warp_props;  // a `warp { turbulence }` before the transforms
  Loc warp_loc;
  double filter = 0, transmit = 0;
  static const std::set<std::string> unsupported_patterns = {
      "brick", "hexagon", "quilted", "facets", "average", "slope", "mandel",
      "julia", "magnet", "toroidal", "density_file", "object",
      "pigment_pattern", "image_pattern", "tiling", "function", "cubic", "square", "triangular"};
  // A colour given bare or after `color`: the pigment's colour, or the pattern's next entry.
  auto take_color = [&](const Expr& e) {
    double f = 0, t = 0;
    std::string c = color_value(e, &f, &t);
    if (pattern.empty()) {
      m.set("color", c);
      filter = f, transmit = t;
    } else {
      colors.push_back(c);
    }
  };
  for (const Item& it : b.items) {
    if (it.kind == Item::Value) {
      const Expr& e = *it.args[0];
      if (e.kind == Expr::Name) {
        if (Symbol* s = lookup(e.text); s && (s->type == Type::Pigment || s->type == Type::Material)) {
          // A name rts's library defines as a material (textures.inc's Jade, a pigment in
          // POV-Ray): the material is derived from it, its colour and pattern with it.
          if (s->type == Type::Material && library_names_.count(e.text) && m.base.empty()) m.base = rename(e.text);
          else m.set("color", rename(e.text));
          if (s->type == Type::Pigment) named_pattern = rename(e.text);
          continue;
        }
        if (missing_name(it.loc, e.text, "pigment or colour")) {
          m.set("color", "rgb(0.5)");
          continue;
        }
      }
      take_color(e);
      continue;
    }
    if (it.kind == Item::Keyword) {
      const std::string& k = it.name;
      if ((k == "color" || k == "colour") && !it.args.empty()) {
        take_color(*it.args[0]);
        continue;
      }
      if ((k == "filter" || k == "transmit") && !it.args.empty()) {
        double v;
        if (literal_number(*it.args[0], v)) (k == "filter" ? filter : transmit) = v;
        continue;
      }
      if (k == "checker") {
        pattern = k;
        for (const ExprPtr& a : it.args) colors.push_back(color_value(*a));
        continue;
      }
      if (pigment_pattern(k)) {
        pattern = k;
        if (k == "gradient" && !it.args.empty()) {
          std::vector<double> v;
          std::string axis = "\"y\"";
          if (literal_vector(*it.args[0], v) && v.size() == 3) {
            axis = v[0] != 0 ? "\"x\"" : v[2] != 0 ? "\"z\"" : "\"y\"";
            const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if ((v[0] != 0) + (v[1] != 0) + (v[2] != 0) != 1 && len > 0) {
              // POV-Ray's gradient along any vector (its direction; textures.inc's Candy_Cane
              // is gradient x+y): rts's along x, turned so x goes along it, before the
              // pigment's own transforms. The matrix's rows are the images of x, y and z.
              const glm::dvec3 u = glm::dvec3(v[0], v[1], v[2]) / len;
              const glm::dvec3 other = std::abs(u.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
              const glm::dvec3 w = glm::normalize(glm::cross(u, other)), t = glm::cross(u, w);
              xforms.insert(xforms.begin(), fmt::format("matrix [{}, {}, {}, {}, {}, {}, {}, {}, {}, 0, 0, 0]",
                                                        num(u.x), num(u.y), num(u.z), num(w.x), num(w.y),
                                                        num(w.z), num(t.x), num(t.y), num(t.z)));
              axis = "\"x\"";
            }
          }
          pattern_props.push_back("axis = " + axis);
        }
        if ((k == "spiral1" || k == "spiral2") && !it.args.empty()) pattern_props.push_back("arms = " + value(*it.args[0]));
        continue;
      }
      if (unsupported_patterns.count(k)) {
        unsupported(it.loc, k, "a pattern { function = ... } macro, or checker/gradient/marble", false);
        pattern = "unsupported";
        continue;
      }
      if (k == "turbulence" || k == "octaves" || k == "omega" || k == "lambda" || k == "frequency" ||
          k == "phase" || k == "agate_turb") {
        if (!it.args.empty()) pattern_props.push_back(k + " = " + value(*it.args[0]));
        continue;
      }
      if (k == "ramp_wave" || k == "triangle_wave" || k == "sine_wave" || k == "scallop_wave" || k == "cubic_wave") {
        pattern_props.push_back("wave = \"" + k.substr(0, k.find('_')) + "\"");
        continue;
      }
      std::vector<std::string> t = transforms(it);
      if (!t.empty()) {
        xforms.insert(xforms.end(), t.begin(), t.end());
        continue;
      }
      if (k == "quick_color" || k == "quick_colour") continue;
      unsupported(it.loc, k, "see docs/textures.md for rts's pattern properties", false);
      continue;
    }
    if (it.kind == Item::Nested) {
      const Block& n = *it.block;
      if (n.kind == "color_map" || n.kind == "colour_map") {
        std::string list;
        for (const Item& e : n.items) {
          if (e.kind == Item::Value && e.args[0]->kind == Expr::Name) {
            list = rename(e.args[0]->text);  // a declared color map
            break;
          }
          if (e.kind != Item::MapEntry) continue;
          std::vector<std::string> vals;
          std::vector<double> clear;  // each value's filter + transmit (a colour's; 0 for numbers)
          for (const Item& v : e.block->items) {
            if (v.kind == Item::Value) {
              const Text t = expr(*v.args[0]);
              vals.push_back(t.s);
              clear.push_back(t.filter + t.transmit);
            }
            if (v.kind == Item::Keyword && (v.name == "color" || v.name == "colour") && !v.args.empty()) {
              double f = 0, t = 0;
              vals.push_back(color_value(*v.args[0], &f, &t));
              clear.push_back(f + t);
            }
          }
          // POV-Ray's filter and transmit as the entry's transmit, the third number of an rts
          // colour map entry: a sky_sphere's layers show what is behind them through it (rts has
          // no filter there: the light passes untinted); surfaces ignore it.
          auto entry = [&](std::size_t at, std::size_t color) {
            const double t = std::min(1.0, clear[color]);
            return "[" + vals[at] + ", " + vals[color] + (t > 0 ? ", " + num(t) : "") + "]";
          };
          if (vals.size() < 2) continue;
          list += list.empty() ? "[" : ", ";
          if (vals.size() == 4) {
            // The old form [a b color A color B]: A at a, B at b.
            list += entry(0, 2) + ", " + entry(1, 3);
          } else {
            list += entry(0, 1);
          }
        }
        map = list.empty() || list[0] != '[' ? list : list + "]";
        continue;
      }
      if (n.kind == "image_map") {
        image = image_map(n);
        continue;
      }
      if (n.kind == "pigment_map") {
        map = pigment_map(n);
        continue;
      }
      if (n.kind == "warp") {
        // POV-Ray applies a pattern's warps and transforms to the point from the last written
        // to the first: `warp { turbulence T }` written before every transform displaces the
        // point in the pattern's own space, which is what rts's `turbulence` does.
        std::vector<std::string> props;
        bool turbulence = false, other = false;
        for (const Item& w : n.items) {
          if (w.kind == Item::Keyword && !w.args.empty() &&
              (w.name == "turbulence" || w.name == "octaves" || w.name == "omega" || w.name == "lambda")) {
            props.push_back(w.name + " = " + value(*w.args[0]));
            turbulence |= w.name == "turbulence";
          } else {
            other = true;
          }
        }
        if (!turbulence || other || !xforms.empty() || !warp_props.empty()) {
          unsupported(n.loc, n.kind,
                      "turbulence on the pattern (a warp { turbulence } written before the pigment's transforms)", false);
          continue;
        }
        warp_props = props;
        warp_loc = n.loc;
        continue;
      }
      if (n.kind == "pigment") {
        MaterialProps inner;
        pigment(n, inner);
        if (pattern == "checker") {
          // `checker pigment { A } pigment { B }`: the two pigments' colours. rts's checker takes
          // colours: a patterned pigment (a pattern block, or a declared one such as Jade, an
          // rts texture) is reported and stands as grey.
          std::string c = "rgb(0)";
          for (const auto& p : inner.props)
            if (p.first == "color") c = p.second;
          Symbol* named = lookup(c);
          if (inner.has("texture") || (named && named->type == Type::Pigment)) {
            unsupported(n.loc, "checker of patterned pigments", "a checker of two colours", false);
            c = "rgb(0.5)";
          }
          colors.push_back(c);
          continue;
        }
        for (const auto& p : inner.props) m.set(p.first, p.second);
        continue;
      }
      std::vector<std::string> t = transforms(it);
      if (!t.empty()) {
        xforms.insert(xforms.end(), t.begin(), t.end());
        continue;
      }
      unsupported(n.loc, n.kind, "see docs/textures.md", false);
    }
  }
  if (!warp_props.empty()) {
    // Marble and wood take a classic turbulence inside the pattern (POV-Ray's and rts's), so
    // only other patterns, without a turbulence of their own, carry the warp as theirs.
    const bool classic = std::any_of(pattern_props.begin(), pattern_props.end(),
                                     [](const std::string& p) { return p.rfind("turbulence", 0) == 0; });
    if (classic || pattern == "marble" || pattern == "wood" || pattern == "agate" || pattern == "spiral1" ||
        pattern == "spiral2" || !pigment_pattern(pattern))
      unsupported(warp_loc, "warp", "turbulence on a pattern without its own turbulence", false);
    else
      pattern_props.insert(pattern_props.end(), warp_props.begin(), warp_props.end());
  }
  if (!pattern_map_override_.empty()) map = pattern_map_override_;
  std::string suffix;
  for (const std::string& t : xforms) suffix += " " + t;
  if (pattern == "checker") {
    std::string c1 = colors.size() > 0 ? colors[0] : "rgb(0, 0, 1)";  // POV-Ray's default: blue and green
    std::string c2 = colors.size() > 1 ? colors[1] : "rgb(0, 1, 0)";
    m.set("color", xforms.empty() ? fmt::format("checker({}, {}, 1)", c1, c2)
                                  : fmt::format("checker {{ color1 = {}  color2 = {} }}{}", c1, c2, suffix));
  } else if (pattern == "unsupported") {
    m.set("color", colors.empty() ? "rgb(0.5)" : colors[0]);
  } else if (pattern == "gradient" && map.empty()) {
    // Without a color_map: rts's two-colour gradient, color1 -> color2 (with one, the pattern below).
    std::string body;
    for (const std::string& p : pattern_props)
      if (p.rfind("axis", 0) == 0) body += "  " + p;
      else unsupported(b.loc, "gradient " + p.substr(0, p.find(' ')), "a plain gradient { axis color1 color2 }", false);
    if (colors.size() >= 2) body += fmt::format("  color1 = {}  color2 = {}", colors[0], colors[1]);
    m.set("texture", "gradient {" + body + (body.empty() ? "}" : " }") + suffix);
    m.props.erase(std::remove_if(m.props.begin(), m.props.end(), [](const auto& p) { return p.first == "color"; }),
                  m.props.end());
  } else if (!pattern.empty()) {
    std::string body;
    for (const std::string& p : pattern_props) body += "  " + p;
    if (!map.empty()) body += "  color_map = " + map;
    else if (colors.size() >= 2) body += fmt::format("  color_map = [[0, {}], [1, {}]]", colors[0], colors[1]);
    m.set("texture", pattern + " {" + body + (body.empty() ? "}" : " }") + suffix);
    m.props.erase(std::remove_if(m.props.begin(), m.props.end(), [](const auto& p) { return p.first == "color"; }),
                  m.props.end());
  } else if (!image.empty()) {
    m.set("texture", xforms.empty() ? image : "(" + image + ")" + suffix);
    m.props.erase(std::remove_if(m.props.begin(), m.props.end(), [](const auto& p) { return p.first == "color"; }),
                  m.props.end());
  } else if (!named_pattern.empty() && !map.empty()) {
    // A declared pattern given its colour map here (woods.inc's T_Wood1: P_WoodGrain1A with
    // M_Wood1A): the pattern with that map, then the transforms written here.
    m.set("texture", named_pattern + " with { color_map = " + map + " }" + suffix);
    m.props.erase(std::remove_if(m.props.begin(), m.props.end(), [](const auto& p) { return p.first == "color"; }),
                  m.props.end());
  } else if (!xforms.empty() && m.has("color")) {
    // A transformed plain colour is the same colour.
  }
  m.opacity = 1.0;
  if (filter > 0 || transmit > 0) {
    // POV-Ray: filtered light takes the surface's colour, transmitted light passes as it is.
    std::string c;
    for (const auto& p : m.props)
      if (p.first == "color") c = p.second;
    m.opacity = std::max(0.0, 1.0 - (filter * max_component(c) + transmit));
    std::string t = filter > 0 && !c.empty()
                        ? (transmit > 0 ? fmt::format("{} * {} + rgb({})", c, num(filter), num(transmit))
                                        : fmt::format("{} * {}", c, num(filter)))
                        : num(filter + transmit);
    m.set("transmit", t);
  }
}

std::string Translator::pigment_map(const Block& n) {
  // pigment_map { [v pigment-body] ... }: rts's colour map with a texture (or a colour) per
  // entry. Each entry's pigment is translated as a pigment of its own; its transforms stay its own
  // (rts evaluates an entry at the map's point, after the entry's transform, as POV-Ray does).
  std::string list;
  const std::string outer_override = pattern_map_override_;   // a texture_map's, not the entries'
  pattern_map_override_.clear();
  for (const Item& e : n.items) {
    if (e.kind == Item::Value && e.args[0]->kind == Expr::Name) {
      list = rename(e.args[0]->text);   // a declared pigment_map
      break;
    }
    if (e.kind != Item::MapEntry || e.block->items.empty() || e.block->items[0].kind != Item::Value) continue;
    Block body;
    body.kind = "pigment";
    body.loc = e.loc;
    body.items.assign(e.block->items.begin() + 1, e.block->items.end());
    MaterialProps inner;
    pigment(body, inner);
    std::string entry = "rgb(0)";   // POV-Ray's default pigment: black
    bool textured = false;
    for (const auto& [name, text] : inner.props) {
      if (name == "texture") entry = text, textured = true;
      if (name == "color" && !textured) entry = text;
    }
    const double clear = textured ? 0.0 : std::min(1.0, 1.0 - inner.opacity);
    list += (list.empty() ? "[[" : ", [") + value(*e.block->items[0].args[0]) + ", " + entry +
            (clear > 0 ? ", " + num(clear) : "") + "]";
  }
  pattern_map_override_ = outer_override;
  return list.empty() || list[0] != '[' ? list : list + "]";
}

std::string Translator::image_map(const Block& n) {
  // image_map { [png] "file" [map_type 0] [interpolate 2] [once] }: POV-Ray's planar map spans x
  // and y from 0 to 1 (projected along z), repeating; rts's planar image spans x and z, so the
  // texture is turned a quarter about x. No interpolate is POV-Ray's nearest texel.
  std::string file;
  double map_type = 0, interpolate = 0;
  // The file: a string, or a declared string's name (`png TestMap`, as POV-Ray's samples write).
  auto file_name = [&](const Expr& e) {
    if (e.kind == Expr::String) return value(e);
    if (e.kind == Expr::Name)
      if (Symbol* s = lookup(e.text); s && s->type == Type::String) return rename(e.text);
    return std::string();
  };
  for (const Item& v : n.items) {
    if (v.kind == Item::Value && !file_name(*v.args[0]).empty()) file = file_name(*v.args[0]);
    if (v.kind == Item::Keyword && !v.args.empty() && !file_name(*v.args[0]).empty()) file = file_name(*v.args[0]);
    if (v.kind == Item::Keyword && v.name == "map_type" && !v.args.empty()) literal_number(*v.args[0], map_type);
    if (v.kind == Item::Keyword && v.name == "interpolate" && !v.args.empty()) literal_number(*v.args[0], interpolate);
    if (v.kind == Item::Keyword && (v.name == "once" || v.name == "filter" || v.name == "transmit" ||
                                    v.name == "use_color" || v.name == "use_index" || v.name == "gamma"))
      unsupported(v.loc, "image_map " + v.name, "the image's own colours, repeating", false);
  }
  if (file.empty()) {
    // Nothing to write as a texture: the pigment keeps its colour (a texture of a colour is
    // not one: interp.pov stopped at `texture = rgb(0.5)`).
    unsupported(n.loc, "image_map", "image_texture { file = \"...\" }", false);
    return "";
  }
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path found_dir;  // where POV-Ray finds the file: beside the scene, -I, its library folder
  if (file.size() > 2 && file.front() == '"') {
    // No extension: POV-Ray tries its image types, the first found.
    const std::string bare = file.substr(1, file.size() - 2);
    std::vector<std::string> names = {bare};
    if (bare.find('.') == std::string::npos)
      for (const char* ext : {".png", ".jpg", ".jpeg", ".tga", ".bmp", ".hdr"}) names.push_back(bare + ext);
    for (const std::string& d : search_dirs()) {
      for (const std::string& nm : names)
        if (fs::is_regular_file(fs::path(d) / nm, ec)) {
          file = "\"" + nm + "\"";
          found_dir = d;
          break;
        }
      if (!found_dir.empty()) break;
    }
  }
  // Written where the translation does not find it by the same name (elsewhere with -o, or
  // found in another folder): named from the translation's folder instead.
  const fs::path out =
      fs::weakly_canonical(!opt_.output_dir.empty() ? opt_.output_dir : dir_.empty() ? std::string(".") : dir_, ec);
  if (!found_dir.empty() && fs::weakly_canonical(found_dir, ec) != out) {
    const fs::path image = found_dir / file.substr(1, file.size() - 2);
    {
      const fs::path rel = fs::relative(fs::weakly_canonical(image, ec), out, ec);
      if (!ec && !rel.empty()) {
        file = "\"";
        for (char c : rel.generic_string()) file += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
        file += "\"";
      }
    }
  }
  const std::string filter = interpolate > 0 ? "" : "  filter = \"nearest\"";
  if (map_type == 1) return "image_texture { file = " + file + "  mapping = \"spherical\"" + filter + " }";
  if (map_type != 0)
    unsupported(n.loc, fmt::format("image_map map_type {}", num(map_type)), "the planar map (map_type 0) or the spherical (1)",
                false);
  return "(image_texture { file = " + file + "  mapping = \"planar\"" + filter + " } rotate <-90, 0, 0>)";
}

}  // namespace rts::import::pov
