// POV-Ray's lights, camera and global settings as rts statements (the camera's right/up/
// direction vectors, the light kinds and their falloff, the settings rts has).
#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "import/pov/reader.hpp"
#include "import/pov/translator.hpp"

namespace rts::import::pov {

namespace {

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

// A camera's literal transform as a matrix, as rts's own transforms build it (rotate about x,
// then y, then z, in degrees; matrix's 12 values row by row, then the translation); false when
// it is computed or a declared transform.
bool camera_transform(const Item& it, glm::dmat4& out) {
  if (it.args.empty()) return false;
  const glm::dmat4 one(1.0);
  if (it.name == "matrix") {
    std::vector<double> v;
    if (!Translator::literal_vector(*it.args[0], v) || v.size() != 12) return false;
    out = one;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) out[i][j] = v[static_cast<std::size_t>(i * 3 + j)];
    return true;
  }
  glm::dvec3 a;
  if (!literal3(it.args[0].get(), a)) return false;
  if (it.name == "translate") {
    out = glm::translate(one, a);
  } else if (it.name == "scale") {
    out = glm::scale(one, a);
  } else if (it.name == "rotate") {
    out = glm::rotate(one, glm::radians(a.z), glm::dvec3(0, 0, 1)) *
          glm::rotate(one, glm::radians(a.y), glm::dvec3(0, 1, 0)) *
          glm::rotate(one, glm::radians(a.x), glm::dvec3(1, 0, 0));
  } else {
    return false;
  }
  return true;
}

}  // namespace

void Translator::light(Writer& w, const Block& b, const std::string& prefix) {
  std::string position, color = "rgb(1)", point_at = "<0, 0, 0>", radius, falloff, kind = "point_light";
  std::string position_operand, point_at_operand = point_at;   // as `point_at - position`'s operands
  bool area = false;                    // area_light given: its u, v, samples and disc in area_props
  std::vector<std::string> area_props;
  std::vector<std::string> extra, xforms;
  std::string fade_distance;
  const Expr* fade_power = nullptr;
  const Item* location = nullptr;         // the light's location (the first value)
  const Item* looks_like = nullptr;       // looks_like { object }: placed at the light
  std::vector<const Item*> moves;         // the light's own transforms, in order
  int values = 0;
  for (const Item& it : b.items) {
    if (it.kind == Item::Value) {
      if (values == 0) location = &it;
      if (values == 0) {
        position = vector_value(*it.args[0]);
        position_operand = vector_operand(*it.args[0], 8);
      }
      else if (values == 1) color = color_value(*it.args[0]);
      ++values;
      continue;
    }
    if (it.kind == Item::Nested) {
      if (it.block->kind == "looks_like" && prefix.empty() && !looks_like) {
        looks_like = &it;
      } else if (it.block->kind == "looks_like" || it.block->kind == "projected_through") {
        unsupported(it.loc, it.block->kind, "an object placed at the light (with no shadows from the light)", false);
      } else if (it.block->kind != "photons" && it.block->kind != "media_interaction") {
        std::vector<std::string> t = transforms(it);
        if (!t.empty()) moves.push_back(&it);
        for (std::string& s : t) xforms.push_back(std::move(s));
      }
      continue;
    }
    if (it.kind != Item::Keyword) continue;
    const std::string& k = it.name;
    std::vector<std::string> t = transforms(it);
    if (!t.empty()) {
      moves.push_back(&it);
      xforms.insert(xforms.end(), t.begin(), t.end());
    } else if ((k == "color" || k == "colour") && !it.args.empty()) {
      color = color_value(*it.args[0]);
    } else if (k == "spotlight") {
      kind = "spot_light";
    } else if (k == "parallel") {
      kind = "directional_light";
    } else if (k == "point_at" && !it.args.empty()) {
      point_at = vector_value(*it.args[0]);
      point_at_operand = vector_operand(*it.args[0], 7);
    } else if (k == "radius" && !it.args.empty()) {
      double r;
      // POV-Ray takes the angles' cosines, so a negative angle is its opposite (`falloff -90`
      // in its samples).
      radius = literal_number(*it.args[0], r) ? fmt::format("{}", std::abs(r)) : "abs(" + value(*it.args[0]) + ")";
    } else if (k == "falloff" && !it.args.empty()) {
      double f;
      falloff = literal_number(*it.args[0], f) ? fmt::format("{}", std::abs(f)) : "abs(" + value(*it.args[0]) + ")";
    } else if (k == "tightness" && !it.args.empty()) {
      double v;
      if (!literal_number(*it.args[0], v) || v != 0)
        unsupported(it.loc, "tightness", "radius and falloff shape the spot's edge", false);
    } else if (k == "area_light" && it.args.size() >= 4) {
      area = true;
      area_props.push_back("u = " + vector_value(*it.args[0]));
      area_props.push_back("v = " + vector_value(*it.args[1]));
      area_props.push_back(fmt::format("samples = {} * {}", operand(*it.args[2], 8), operand(*it.args[3], 8)));
    } else if (k == "circular") {
      area_props.push_back("disc = true");
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
  // An area light's keywords may come before or after `spotlight`: a spotlight with an
  // area_light is rts's area_light with the spot's point_at, radius and falloff.
  const bool area_spot = area && kind == "spot_light";
  if (area && (kind == "point_light" || area_spot)) {
    kind = "area_light";
    extra.insert(extra.begin(), area_props.begin(), area_props.end());
  }
  std::vector<std::string> props;
  if (kind == "directional_light") {
    props.push_back(fmt::format("direction = {} - {}", point_at_operand, position_operand));
  } else {
    props.push_back("position = " + position);
  }
  if (color != "rgb(1)") props.push_back("color = " + color);
  if (kind == "spot_light" || area_spot) {
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
  if (looks_like) {
    // POV-Ray shows looks_like's object moved to the light's location (then by the light's
    // transforms), and it casts no shadow of its own light; rts's casts_shadow = false leaves
    // out its shadows from every light.
    Block placed;
    placed.kind = "object";
    placed.loc = looks_like->loc;
    for (const Item& inner : looks_like->block->items) placed.items.push_back(inner);
    Item no_shadow;
    no_shadow.kind = Item::Keyword;
    no_shadow.name = "no_shadow";
    no_shadow.loc = looks_like->loc;
    placed.items.push_back(no_shadow);
    Item to_light;
    to_light.kind = Item::Keyword;
    to_light.name = "translate";
    to_light.loc = location->loc;
    to_light.args.push_back(location->args[0]);
    placed.items.push_back(to_light);
    for (const Item* m : moves) placed.items.push_back(*m);
    w.line("// the light's looks_like object, at the light");
    object(w, placed, "", true);
  }
}

void Translator::camera(Writer& w, const Block& b) {
  const Expr *location = nullptr, *look_at = nullptr, *angle = nullptr, *right = nullptr, *up = nullptr,
             *direction = nullptr, *sky = nullptr;
  bool ortho = false;
  std::string projection;  // POV-Ray's other camera types: rts's projection of that name
  const Expr* vertical_angle = nullptr;  // the spherical camera's second angle
  std::vector<std::string> extra;
  std::vector<const Item*> moves;  // the camera's own transforms, in order
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
    else if (k == "angle") {
      angle = a;
      vertical_angle = it.args.size() > 1 ? it.args[1].get() : nullptr;
    }
    else if (k == "right") right = a;
    else if (k == "up") up = a;
    else if (k == "direction") direction = a;
    else if (k == "sky") sky = a;
    else if (k == "orthographic") ortho = true, projection.clear();
    else if (k == "perspective") ortho = false, projection.clear();
    else if (k == "aperture" && a) extra.push_back("aperture = " + value(*a));
    else if (k == "focal_point" && a) {
      extra.push_back(fmt::format("focus_distance = length({} - {})", vector_operand(*a, 7),
                                  location ? vector_operand(*location, 8) : "<0, 0, 0>"));
    } else if (k == "blur_samples" || k == "confidence" || k == "variance") {
      // rts's samples per pixel carry the blur: settings { samples }
    } else if (k == "translate" || k == "rotate" || k == "scale" || k == "matrix" || k == "transform") {
      moves.push_back(&it);  // applied to the camera's vectors below, when they are literal
    } else if (k == "fisheye" || k == "panoramic" || k == "spherical" || k == "omnimax" || k == "ultra_wide_angle") {
      projection = k;
      ortho = false;
    } else if (k == "cylinder") {
      double n = 0;
      if (a && literal_number(*a, n) && n >= 1 && n <= 4 && n == std::floor(n)) {
        projection = fmt::format("cylinder{}", static_cast<int>(n));
        ortho = false;
      } else {
        unsupported(it.loc, "cylinder camera of a computed or unknown type", "cylinder 1 to 4", false);
      }
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
  if (!projection.empty()) {
    // POV-Ray's angle is the projection's own (not the direction's length), its default 90.
    props.push_back("projection = \"" + projection + "\"");
    if (angle) props.push_back("fov = " + value(*angle));
    if (vertical_angle && projection == "spherical") props.push_back("vertical_fov = " + value(*vertical_angle));
  }
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
  const bool own_angle = !projection.empty();  // the angle is the projection's, not the direction's
  if (literal_view && !(ortho && angle) && (own_angle || !(angle && (angle_deg <= 0 || angle_deg >= 180)))) {
    if (angle && !own_angle) D = glm::normalize(D) * (0.5 * glm::length(R) / std::tan(angle_deg * M_PI / 360));
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
    // The camera's transforms move its position and turn its vectors (POV-Ray transforms the
    // camera it has built); literal ones are applied here.
    glm::dmat4 move(1.0);
    bool moved = true;
    for (const Item* it : moves) {
      glm::dmat4 m;
      if (!camera_transform(*it, m)) {
        moved = false;
        unsupported(it->loc, "camera " + it->name, "location and look_at written moved", false);
        break;
      }
      move = m * move;
    }
    if (moved && !moves.empty()) {
      L = glm::dvec3(move * glm::dvec4(L, 1.0));
      const glm::dmat3 turn(move);
      D = turn * D;
      R = turn * R;
      U = turn * U;
      props.back() = "position = " + vec(L);
      w.line("// POV-Ray's camera transforms applied to its position and vectors");
    }
    auto clean = [](glm::dvec3 v) {
      for (int i = 0; i < 3; ++i)
        if (std::abs(v[i]) < 1e-12) v[i] = 0;
      return vec(v);
    };
    props.push_back("direction = " + clean(D));
    props.push_back("right = " + clean(R));
    props.push_back("up = " + clean(U));
  } else if (projection.empty() && !ortho && !(image_aspect && lu && ld)) {
    // Vectors the scene computes (`direction z * CamZoom`): POV-Ray's own construction written
    // as rts, the helper pov_look_at turning them towards look_at as the literal case above does.
    // (`right x*image_width/image_height` alone keeps the look_at and fov below, which follow
    // the image's aspect; beside a computed direction or up it is 640/480 here.)
    for (const Item* it : moves) unsupported(it->loc, "camera " + it->name, "location and look_at written moved", false);
    helpers_.insert("pov_look_at");
    const std::string name = fmt::format("pov_camera_{}", ++computed_cameras_);
    w.line("// POV-Ray's camera vectors, computed: turned towards look_at as POV-Ray turns them");
    w.line(fmt::format("let {} = pov_look_at({}, {}, {}, {}, {}, {}, {})", name, pos,
                       look_at ? vector_value(*look_at) : "none", sky ? vector_value(*sky) : "<0, 1, 0>",
                       direction ? vector_value(*direction) : "<0, 0, 1>",
                       right ? vector_value(*right) : "<1.33, 0, 0>", up ? vector_value(*up) : "<0, 1, 0>",
                       angle ? value(*angle) : "0"));
    props.push_back(fmt::format("direction = {0}[0]  right = {0}[1]  up = {0}[2]", name));
  } else {
    for (const Item* it : moves) unsupported(it->loc, "camera " + it->name, "location and look_at written moved", false);
    if (look_at) props.push_back("look_at = " + vector_value(*look_at));
    else
      props.push_back(fmt::format("look_at = {} + {}", location ? vector_operand(*location, 7) : pos,
                                  direction ? vector_operand(*direction, 7) : "<0, 0, 1>"));
    if (sky) props.push_back("up = " + vector_value(*sky));
    if (lr && lu && ld) {
      // POV-Ray's look_at keeps the vectors' handedness, (up x direction) . right, and takes a
      // zero one (`up z` along the default direction z, as its prism samples write) as
      // mirrored: the picture is then right-handed.
      const bool mirrored = look_at ? !(glm::dot(glm::cross(U, D), R) > 0) : R.x < 0;
      if (mirrored) props.push_back("handedness = \"right\"");
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
  // A projection's own angle was written first: the perspective fov derived below it is dropped.
  std::set<std::string> keys;
  props.erase(std::remove_if(props.begin(), props.end(),
                             [&](const std::string& p) { return !keys.insert(p.substr(0, p.find(" ="))).second; }),
              props.end());
  w.open("camera");
  for (const std::string& p : props) w.line(p);
  w.close();
}

void Translator::global_settings(Writer& w, const Block& b) {
  std::vector<std::string> props;
  for (const Item& it : b.items) {
    if (it.kind == Item::Nested) {
      if (it.block->kind == "radiosity")
        radiosity_ = true;  // the path integrator (translate_files.cpp writes it; its settings have no use there)
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

}  // namespace rts::import::pov
