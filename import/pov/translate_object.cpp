// POV-Ray objects as rts blocks: positional values become named properties, transforms
// postfix operators, CSG and meshes their members (the materials they carry:
// translate_material.cpp and translate_pigment.cpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

bool Translator::is_object_kind(const std::string& k) {
  static const std::set<std::string> kinds = {"sphere", "box", "plane", "cylinder", "cone", "torus", "disc",
                                              "triangle", "smooth_triangle", "mesh", "mesh2", "superellipsoid", "sor", "lathe", "prism",
                                              "height_field", "isosurface", "poly", "quartic", "cubic", "quadric", "text", "union",
                                              "intersection", "difference", "merge", "object"};
  return kinds.count(k) > 0 || k == "blob" || is_unsupported_shape(k);
}

bool Translator::is_solid_kind(const std::string& k) {
  return k == "sphere" || k == "box" || k == "plane" || k == "cylinder" || k == "cone" || k == "torus" ||
         k == "superellipsoid" || k == "sor" || k == "lathe" || k == "prism" || k == "blob" || k == "height_field" ||
         k == "isosurface" || k == "poly" || k == "quartic" || k == "cubic" || k == "quadric" || k == "text" || k == "union" || k == "intersection" ||
         k == "difference" || k == "merge" || k == "clip";
}

bool Translator::is_unsupported_shape(const std::string& k) {
  static const std::set<std::string> kinds = {"sphere_sweep", "polygon", "bicubic_patch", "julia_fractal",
                                              "parametric", "ovus", "lemon",
                                              "polynomial"};
  return kinds.count(k) > 0;
}

namespace {

// A declared transform's steps are copied where it is used; a chain of declarations naming the
// last one twice doubles at each step, so the count is bounded (a located error past it).
constexpr std::size_t kMaxTransformSteps = 10000;

// The closest rts alternative for an unsupported shape, and whether it is planned.
std::pair<std::string, bool> shape_alternative(const std::string& k) {
  if (k == "sphere_sweep" || k == "polygon") return {"a mesh (planned after issue 20)", true};
  return {"a mesh from an OBJ file", false};
}

// POV-Ray's spline keywords for a lathe's profile or a prism's outline: rts's `spline` property.
bool is_spline_keyword(const std::string& k) {
  return k == "linear_spline" || k == "quadratic_spline" || k == "cubic_spline" || k == "bezier_spline";
}

bool is_texture_part(const std::string& k) {
  return k == "texture" || k == "pigment" || k == "finish" || k == "normal" || k == "interior" || k == "material";
}

}  // namespace

bool Translator::has_texture(const Block& b) const {
  bool children = false, all_children = true;
  for (const Item& it : b.items) {
    if (it.kind == Item::Nested && is_texture_part(it.block->kind) && it.block->kind != "interior") return true;
    if (it.kind == Item::Nested && is_object_kind(it.block->kind)) {
      children = true;
      all_children = all_children && has_texture(*it.block);
    }
    if (it.kind == Item::Value && b.kind == "object" && it.args[0]->kind == Expr::Name) {
      auto* self = const_cast<Translator*>(this);
      if (Symbol* s = self->lookup(it.args[0]->text); s && s->textured) return true;
    }
    if (it.kind != Item::Nested && it.kind != Item::Keyword && b.kind != "object") all_children = false;
  }
  return children && all_children;
}

std::vector<std::string> Translator::transforms(const Item& it) {
  if (it.kind == Item::Keyword && !it.args.empty()) {
    if (it.name == "translate" || it.name == "rotate") return {it.name + " " + vector_value(*it.args[0])};
    if (it.name == "scale") {
      double k;
      if (literal_number(*it.args[0], k)) return {"scale " + num(k)};
      return {"scale " + vector_value(*it.args[0])};
    }
    if (it.name == "matrix") {
      const Expr& m = *it.args[0];
      if (m.kind == Expr::Vector && m.args.size() == 12) {
        std::string s = "matrix [";
        for (std::size_t i = 0; i < 12; ++i) s += (i ? ", " : "") + value(*m.args[i]);
        return {s + "]"};
      }
      error(it.loc, "'matrix' takes 12 values: <a, b, c, d, e, f, g, h, i, j, k, l>");
    }
    if (it.name == "transform") {
      // transform T, a declared transform: its steps (written out when it was declared).
      if (it.args[0]->kind == Expr::Name)
        if (Symbol* s = lookup(it.args[0]->text); s && s->type == Type::Transform) return s->steps;
      unsupported(it.loc, "transform", "translate/rotate/scale/matrix written out", false);
    }
  }
  if (it.kind == Item::Nested && it.block->kind == "transform") {
    std::vector<std::string> out;
    for (const Item& step : it.block->items) {
      if (step.kind == Item::Value && step.args[0]->kind == Expr::Name) {
        Item ref = step;
        ref.kind = Item::Keyword;
        ref.name = "transform";
        for (std::string& t : transforms(ref)) out.push_back(std::move(t));
      } else if (step.kind == Item::Keyword && step.name == "inverse") {
        unsupported(step.loc, "inverse", "the inverse transform written out", false);
      } else {
        for (std::string& t : transforms(step)) out.push_back(std::move(t));
      }
      // Declared transforms that each name the last one twice double at every step.
      if (out.size() > kMaxTransformSteps)
        error(step.loc, fmt::format("this transform expands to more than {} steps", kMaxTransformSteps));
    }
    return out;
  }
  return {};
}

void Translator::object(Writer& w, const Block& b, const std::string& prefix, bool place) {
  const std::string& k = b.kind;
  if (!blob_lists_.empty() && (k == "sphere" || k == "cylinder")) {
    // A blob's component inside the loop that places it: appended to the blob's list.
    bool sphere = true;
    const std::string entry = blob_component(b, sphere);
    w.line(fmt::format("{} += [{}]", sphere ? blob_lists_.back().spheres : blob_lists_.back().cylinders, entry));
    return;
  }
  if (is_unsupported_shape(k)) {
    auto [alt, planned] = shape_alternative(k);
    unsupported(b.loc, k, alt, planned);
    w.line(fmt::format("{}group {{ }}  // POV-Ray's {} is not translated (rts import warned)", prefix, k));
    return;
  }
  if (clipped_object(w, b, prefix, place)) return;
  if (k == "object") {
    // object { sphere { ... } modifiers }: the inner object with the modifiers after its own.
    const Item* inner = nullptr;
    bool named = false;
    for (const Item& it : b.items) {
      if (it.kind == Item::Value) named = true;
      if (it.kind == Item::Nested && is_object_kind(it.block->kind) && !inner) inner = &it;
    }
    if (!named && inner) {
      Block merged = *inner->block;
      for (const Item& it : b.items)
        if (&it != inner) merged.items.push_back(it);
      return object(w, merged, prefix, place);
    }
  }
  std::vector<const Item*> values;
  std::vector<std::string> props, xforms, comments;
  std::vector<const Item*> children;  // CSG and mesh members, directives among them
  MaterialProps mat;
  bool textured = false;
  std::vector<const Item*> texture_blocks, interiors;  // two textures or more: layers
  std::size_t interior_at = std::string::npos;  // how many transforms came before the interior
  std::string base;  // object { X }
  const Expr* font = nullptr;  // text { ttf "font" ... }
  text_values_.clear();
  Block blob_rest;   // a blob without its components (they are in props)
  const Block* items_of = &b;
  if (k == "blob") {
    // Components placed by loops (or conditions): the loops go before the blob, appending to
    // two lists its spheres and cylinders then read.
    bool looped = false;
    for (const Item& it : b.items)
      looped = looped || it.kind == Item::While || it.kind == Item::For || it.kind == Item::If ||
               it.kind == Item::Switch;
    if (looped) {
      ++blob_list_count_;
      BlobLists lists{fmt::format("pov_blob_spheres{}", blob_list_count_),
                      fmt::format("pov_blob_cylinders{}", blob_list_count_)};
      w.line(fmt::format("let {} = []  // the blob's components, placed by the loop below", lists.spheres));
      w.line(fmt::format("let {} = []", lists.cylinders));
      blob_lists_.push_back(lists);
      for (const Item& it : b.items)
        if (it.kind == Item::While || it.kind == Item::For || it.kind == Item::If || it.kind == Item::Switch ||
            it.kind == Item::Declare)
          item(w, it, false);
      Block components = b;
      components.items.clear();
      for (const Item& it : b.items)
        if (!(it.kind == Item::While || it.kind == Item::For || it.kind == Item::If || it.kind == Item::Switch ||
              it.kind == Item::Declare))
          components.items.push_back(it);
      blob_rest = blob_components(components, props);
      blob_lists_.pop_back();
    } else {
      blob_rest = blob_components(b, props);
    }
    items_of = &blob_rest;
  }
  if (k == "height_field" || k == "isosurface") {
    blob_rest = solid_components(w, b, props);
    if (blob_rest.kind == "unsupported") {
      w.line(fmt::format("{}group {{ }}  // POV-Ray's {} is not translated (rts import warned)", prefix, k));
      return;
    }
    items_of = &blob_rest;
  }
  Block mesh_rest;  // a mesh translated as one rts mesh: its texture and transforms
  const bool one_mesh = (k == "mesh" || k == "mesh2") && mesh_components(b, props, mesh_rest);
  if (one_mesh) items_of = &mesh_rest;
  Block lathe_rest;  // `cubic_spline N, <a>, ...` reads as a keyword with the values as its arguments
  if (k == "lathe" || k == "prism") {
    lathe_rest = b;
    lathe_rest.items.clear();
    for (const Item& it : b.items) {
      if (it.kind == Item::Keyword && (is_spline_keyword(it.name) || it.name == "linear_sweep" || it.name == "conic_sweep") &&
          !it.args.empty()) {
        Item keyword = it;  // the keyword alone (it says which spline), then its values
        keyword.args.clear();
        lathe_rest.items.push_back(std::move(keyword));
        for (const ExprPtr& a : it.args) {
          Item value;
          value.kind = Item::Value;
          value.loc = a->loc;
          value.args.push_back(a);
          lathe_rest.items.push_back(std::move(value));
        }
        continue;
      }
      lathe_rest.items.push_back(it);
    }
    items_of = &lathe_rest;
  }
  for (const Item& it : items_of->items) {
    switch (it.kind) {
      case Item::Value:
        if (k == "object" && base.empty()) {
          const Expr::Kind ek = it.args[0]->kind;
          if (ek == Expr::Name && missing_name(it.loc, it.args[0]->text, "object")) return;
          // What POV-Ray reuses: a declared object, a macro's, an array element. Anything else
          // (fuzz_pov: `object { +x + UnitBox }`) is no object, in POV-Ray too, and written
          // as rts it would be a statement that does not parse.
          if (ek != Expr::Name && ek != Expr::Call && ek != Expr::Index)
            error(it.loc, "'object' reuses a declared object, a macro's or an array element: object { Name ... }");
          base = value(*it.args[0]);
          // A name of a value that is no object (`object { z A38 }`, fuzz_pov: z is <0, 0, 1>)
          // would be written as that value.
          if (ek == Expr::Name && !base.empty() && !(std::isalpha(static_cast<unsigned char>(base[0])) || base[0] == '_'))
            error(it.loc, fmt::format("'object' reuses a declared object, and '{}' is a value: object {{ Name ... }}",
                                      it.args[0]->text));
        } else if (k == "union" || k == "merge" || k == "intersection" || k == "difference" || k == "mesh") {
          children.push_back(&it);
        } else {
          values.push_back(&it);
        }
        break;
      case Item::Nested:
        if (is_texture_part(it.block->kind)) {
          if (it.block->kind == "texture") texture_blocks.push_back(&it);
          if (it.block->kind == "interior") {
            interiors.push_back(&it);
            if (interior_at == std::string::npos) interior_at = xforms.size();
          }
          texture_part(it, mat);
          textured = textured || it.block->kind != "interior";
        } else if (is_object_kind(it.block->kind)) {
          children.push_back(&it);
        } else if (it.block->kind == "transform") {
          for (std::string& t : transforms(it)) xforms.push_back(std::move(t));
        } else if (it.block->kind == "bounded_by") {
          // rts bounds every object itself (BVH): nothing to write.
        } else if (it.block->kind == "clipped_by") {
          // clipped_object() wrote the ones rts can clip: an open object, or an open clipper
          unsupported(it.loc, "clipped_by", "a solid object clipped by solids (rts's clip block)", false);
        } else if (it.block->kind == "photons" || it.block->kind == "radiosity") {
          // photon and radiosity hints: no effect on a Whitted render
        } else {
          unsupported(it.loc, it.block->kind, "see docs/from-povray.md", false);
        }
        break;
      case Item::Keyword: {
        std::vector<std::string> t = transforms(it);
        if (!t.empty()) {
          xforms.insert(xforms.end(), t.begin(), t.end());
        } else if (it.name == "open") {
          props.push_back(k == "sor" || k == "prism" ? "open = true" : "capped = false");
        } else if (it.name == "inverse") {
          props.push_back("inverse = true");
        } else if ((k == "lathe" || k == "prism") && it.name == "linear_spline") {
          // rts's lathe and prism default to straight segments too
        } else if ((k == "lathe" || k == "prism") && is_spline_keyword(it.name)) {
          props.push_back(fmt::format("spline = \"{}\"", it.name.substr(0, it.name.find('_'))));
        } else if (k == "prism" && it.name == "linear_sweep") {
          // rts's prism is swept straight unless told
        } else if (k == "prism" && it.name == "conic_sweep") {
          props.push_back("sweep = \"conic\"");
        } else if (it.name == "hollow" || it.name == "sturm" || it.name == "smooth" || it.name == "no_radiosity" ||
                   it.name == "cutaway_textures" || it.name == "split_union") {
          // no effect on the picture rts makes (or rts's behaviour already)
        } else if (it.name == "double_illuminate") {
          unsupported(it.loc, it.name, "a surface lit on the side facing the light only", false);
        } else if (it.name == "no_reflection") {
          unsupported(it.loc, it.name, "the object seen in reflections too", false);
        } else if (it.name == "no_shadow") {
          if (csg_depth_ > 0)  // rts: a CSG block casts its shadow as a whole
            unsupported(it.loc, "no_shadow", "no_shadow on the whole CSG block", true);
          else
            props.push_back("casts_shadow = false");
        } else if (k == "text" && it.name == "ttf" && !it.args.empty()) {
          font = it.args[0].get();
          // `ttf "f.ttf", "string", 0.1, 0`: with commas the keyword read the values too.
          for (std::size_t a = 1; a < it.args.size(); ++a) {
            text_values_.emplace_back();
            text_values_.back().kind = Item::Value;
            text_values_.back().loc = it.args[a]->loc;
            text_values_.back().args.push_back(it.args[a]);
          }
        } else if (it.name == "no_image") {
          unsupported(it.loc, "no_image", "leave the object out", false);
        } else {
          unsupported(it.loc, it.name, "see docs/shapes.md", false);
        }
        break;
      }
      default:
        children.push_back(&it);  // directives inside CSG: loops, ifs, declarations
        break;
    }
  }
  if (interior_at != std::string::npos && interior_at < xforms.size()) {
    // POV-Ray's media move with their object; rts evaluates a media density at the world point
    // (docs/rendering.md#media), so the object's transforms written after its interior move the
    // density texture as well (those before it moved only the shape, as in POV-Ray).
    std::string after;
    for (std::size_t i = interior_at; i < xforms.size(); ++i) after += " " + xforms[i];
    for (auto& p : mat.props)
      if (p.first == "media_density") p.second = "(" + p.second + ")" + after;
  }
  if (texture_blocks.size() >= 2) layered_texture(texture_blocks, interiors, mat);  // texture { A } texture { B }
  auto v = [&](std::size_t i) -> const Expr* { return i < values.size() ? values[i]->args[0].get() : nullptr; };
  auto need = [&](std::size_t n, const char* form) {
    if (values.size() < n) error(b.loc, fmt::format("'{}' needs {}", k, form));
  };
  std::string kind = k;
  if (k == "sphere") {
    need(2, "a centre and a radius: sphere { <x, y, z>, r }");
    props.insert(props.begin(), {"center = " + vector_value(*v(0)), "radius = " + value(*v(1))});
  } else if (k == "box") {
    need(2, "two corners: box { <x1, y1, z1>, <x2, y2, z2> }");
    std::vector<double> a, c;
    // A literal vector, or a literal float promoted to <f, f, f> (`box { -0.4, 0.4 }`).
    auto point = [](const Expr& e, std::vector<double>& out) {
      double k;
      if (literal_number(e, k)) {
        out.assign(3, k);
        return true;
      }
      return literal_vector(e, out) && out.size() == 3;
    };
    if (point(*v(0), a) && point(*v(1), c)) {
      glm::dvec3 lo(std::min(a[0], c[0]), std::min(a[1], c[1]), std::min(a[2], c[2]));
      glm::dvec3 hi(std::max(a[0], c[0]), std::max(a[1], c[1]), std::max(a[2], c[2]));
      if (lo != glm::dvec3(a[0], a[1], a[2])) comments.push_back("corners sorted: POV-Ray takes them in any order");
      props.insert(props.begin(), {"min = " + vec(lo), "max = " + vec(hi)});
    } else {
      // Computed corners may come in either order (POV-Ray takes both): sorted when evaluated.
      const std::string a0 = vector_value(*v(0)), a1 = vector_value(*v(1));
      props.insert(props.begin(), {fmt::format("min = min({}, {})", a0, a1), fmt::format("max = max({}, {})", a0, a1)});
    }
  } else if (k == "plane") {
    need(2, "a normal and a distance: plane { <x, y, z>, d }");
    props.insert(props.begin(), {"normal = " + vector_value(*v(0)), "offset = " + value(*v(1))});
  } else if (k == "cylinder") {
    need(3, "two end points and a radius: cylinder { <a>, <b>, r }");
    props.insert(props.begin(),
                 {"from = " + vector_value(*v(0)), "to = " + vector_value(*v(1)), "radius = " + value(*v(2))});
  } else if (k == "cone") {
    need(4, "two ends with their radii: cone { <a>, ra, <b>, rb }");
    props.insert(props.begin(), {"from = " + vector_value(*v(0)), "radius_from = " + value(*v(1)),
                                 "to = " + vector_value(*v(2)), "radius_to = " + value(*v(3))});
  } else if (k == "torus") {
    need(2, "two radii: torus { major, minor }");
    props.insert(props.begin(), {"major = " + value(*v(0)), "minor = " + value(*v(1))});
  } else if (k == "quartic" || k == "cubic" || k == "poly") {
    // rts's poly, with POV-Ray's order of the coefficients.
    const bool general = k == "poly";
    need(general ? 2 : 1, general ? "an order and its coefficients: poly { order, <c1, c2, ...> }"
                                  : "its coefficients: quartic { <c1, ..., c35> } (cubic: 20)");
    kind = "poly";
    const Expr& c = *v(general ? 1 : 0);
    if (c.kind != Expr::Vector)
      error(c.loc, fmt::format("'{}' needs its coefficients written as one vector <c1, c2, ...>", k));
    std::string list;
    for (const ExprPtr& a : c.args) list += (list.empty() ? "" : ", ") + value(*a);
    props.insert(props.begin(), {"order = " + (general ? value(*v(0)) : std::string(k == "quartic" ? "4" : "3")),
                                 "coefficients = [" + list + "]"});
  } else if (k == "quadric") {
    // A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0: rts's poly of
    // order 2, whose coefficients follow POV-Ray's poly order (x^2, xy, xz, x, y^2, yz, y, z^2, z, 1).
    need(4, "three vectors and a constant: quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }");
    kind = "poly";
    auto part = [&](const Expr& e, int i) {
      if (e.kind == Expr::Vector && e.args.size() == 3) return value(*e.args[i]);
      return fmt::format("({}).{}", vector_value(e), "xyz"[i]);
    };
    const Expr &sq = *v(0), &mixed = *v(1), &lin = *v(2);
    const std::string list = fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}, {}", part(sq, 0), part(mixed, 0),
                                         part(mixed, 1), part(lin, 0), part(sq, 1), part(mixed, 2), part(lin, 1),
                                         part(sq, 2), part(lin, 2), value(*v(3)));
    props.insert(props.begin(), {"order = 2", "coefficients = [" + list + "]"});
  } else if (k == "text") {
    // text { ttf "font.ttf" "string" thickness, offset }: rts's text block (a font beside the
    // scene as written; one only in POV-Ray's library folder by its full path).
    // The values read with the ttf keyword (`ttf "f.ttf", "string", ...`) come first.
    for (Item& t : text_values_) values.insert(values.begin() + static_cast<long>(&t - text_values_.data()), &t);
    need(2, "a font, a string and a thickness: text { ttf \"timrom.ttf\" \"Hello\" 0.2, 0 }");
    if (!font) error(b.loc, "'text' needs its font: text { ttf \"timrom.ttf\" \"Hello\" 0.2, 0 }");
    // The font as written: rts's text looks beside the scene, then in POV-Ray's library folder.
    std::vector<std::string> p = {"font = " + value(*font), "string = " + value(*v(0)), "thickness = " + value(*v(1))};
    if (v(2)) p.push_back("offset = " + vector_value(*v(2)));
    props.insert(props.begin(), p.begin(), p.end());
  } else if (k == "disc") {
    need(3, "a centre, a normal and a radius: disc { <c>, <n>, r }");
    std::vector<std::string> p = {"center = " + vector_value(*v(0)), "normal = " + vector_value(*v(1)),
                                  "radius = " + value(*v(2))};
    if (v(3)) p.push_back("inner_radius = " + value(*v(3)));
    props.insert(props.begin(), p.begin(), p.end());
  } else if (k == "triangle") {
    need(3, "three corners: triangle { <a>, <b>, <c> }");
    props.insert(props.begin(),
                 {"v0 = " + vector_value(*v(0)), "v1 = " + vector_value(*v(1)), "v2 = " + vector_value(*v(2))});
  } else if (k == "smooth_triangle") {
    need(6, "three corners each with its normal: smooth_triangle { <a>, <na>, <b>, <nb>, <c>, <nc> }");
    kind = "triangle";
    props.insert(props.begin(), {"v0 = " + vector_value(*v(0)), "n0 = " + vector_value(*v(1)),
                                 "v1 = " + vector_value(*v(2)), "n1 = " + vector_value(*v(3)),
                                 "v2 = " + vector_value(*v(4)), "n2 = " + vector_value(*v(5))});
  } else if (k == "superellipsoid") {
    need(1, "its two exponents: superellipsoid { <e, n> }");
    std::vector<double> en;
    if (literal_vector(*v(0), en) && en.size() == 2) {
      props.insert(props.begin(), {"e = " + num(en[0]), "n = " + num(en[1])});
    } else if (expr(*v(0)).type == Type::Float) {
      // A float promotes to <f, f>: both exponents.
      const std::string p = value(*v(0));
      props.insert(props.begin(), {"e = " + p, "n = " + p});
    } else {
      std::string p = value(*v(0));
      props.insert(props.begin(), {"e = " + p + ".x", "n = " + p + ".y"});
    }
  } else if (k == "sor" || k == "lathe") {
    if (k == "lathe") need(3, "a count and at least two points: lathe { linear_spline 2, <r0, h0>, <r1, h1> }");
    else need(5, "a count and at least four points: sor { 4, <r0, h0>, <r1, h1>, <r2, h2>, <r3, h3> }");
    double count;
    if (literal_number(*v(0), count) && count != static_cast<double>(values.size() - 1))
      error(values[0]->loc, fmt::format("{} says {} points but lists {}", k, num(count), values.size() - 1));
    std::string pts;
    for (std::size_t i = 1; i < values.size(); ++i) {
      std::vector<double> q;
      pts += i > 1 ? ", " : "";
      if (literal_vector(*v(i), q) && q.size() >= 2) {
        pts += fmt::format("[{}, {}]", num(q[0]), num(q[1]));
      } else {
        std::string p = value(*v(i));
        pts += fmt::format("[{}.x, {}.y]", p, p);
      }
    }
    props.insert(props.begin(), "points = [" + pts + "]");
  } else if (k == "prism") {
    need(6, "two heights, a count and at least three points: prism { 0, 1, 3, <x0, z0>, <x1, z1>, <x2, z2> }");
    double count;
    if (literal_number(*v(2), count) && count != static_cast<double>(values.size() - 3))
      error(values[2]->loc, fmt::format("prism says {} points but lists {}", num(count), values.size() - 3));
    std::string pts;
    for (std::size_t i = 3; i < values.size(); ++i) {
      std::vector<double> q;
      pts += i > 3 ? ", " : "";
      if (literal_vector(*v(i), q) && q.size() >= 2) {
        pts += fmt::format("[{}, {}]", num(q[0]), num(q[1]));
      } else {
        std::string p = value(*v(i));
        pts += fmt::format("[{}.x, {}.y]", p, p);
      }
    }
    props.insert(props.begin(), {"points = [" + pts + "]", "height1 = " + value(*v(0)), "height2 = " + value(*v(1))});
  } else if (one_mesh) {
    kind = "mesh";
  } else if (k == "mesh") {
    kind = "group";
    comments.push_back("POV-Ray's mesh: its triangles in a group (not all of them literal)");
  } else if (k == "union") {
    // POV-Ray's union of open shapes (triangles, discs) or meshes is a group in rts: rts's
    // CSG takes closed shapes only, and for opaque objects the picture is the same.
    bool closed = true;
    for (const Item* c : children) {
      if (c->kind == Item::Nested) {
        const std::string& ck = c->block->kind;
        if (ck == "object") {
          for (const Item& r : c->block->items)
            if (r.kind == Item::Value && r.args[0]->kind == Expr::Name) {
              Symbol* s = lookup(r.args[0]->text);
              if (!s || !is_solid_kind(s->object_kind)) closed = false;
              break;
            }
        } else if (!is_solid_kind(ck) || (ck == "cylinder" || ck == "cone" || ck == "sor" || ck == "lathe" || ck == "prism")) {
          // open cylinders/cones are open shapes too
          if (!is_solid_kind(ck)) closed = false;
          for (const Item& r : c->block->items)
            if (r.kind == Item::Keyword && r.name == "open") closed = false;
        }
      } else {
        closed = false;  // loops and macro calls: their members are not known here
      }
    }
    // Outside intersection/difference a union is a group: the same picture for opaque objects,
    // and rts's CSG blocks combine at most 256 shapes.
    // A declared union stays CSG when it can (a material given at `object { U texture {...} }`
    // then reaches its members).
    if (!closed || (csg_depth_ == 0 && place)) kind = "group";
  } else if (k == "object") {
    if (base.empty()) error(b.loc, "'object' needs the object it reuses: object { Name ... }");
  }
  last_kind_ = kind;
  const bool in_group = !group_material_.empty();
  // An untextured object a macro places takes POV-Ray's default texture only where the call
  // puts it: inside a textured union (union { M() pigment { Red } }) it takes the union's, so
  // the macro writes none and the group's material reaches it.
  bool needs_default = (place || in_group) && !textured && !has_texture(b) && (in_group || macro_depth_ == 0);
  // In a group (rts's groups take no material) a member without its own texture gets the
  // group's, as POV-Ray's union gives it.
  auto material_of = [&](bool own) { return !own && in_group ? group_material_.back() : material_text(mat, true); };
  if (k == "object") {
    // object { X modifiers }: X itself, given a material and moved.
    std::string s = base;
    if (textured || needs_default) {
      std::string m = material_of(textured);
      Symbol* sym = b.items.empty() || b.items[0].kind != Item::Value || b.items[0].args[0]->kind != Expr::Name
                        ? nullptr
                        : lookup(b.items[0].args[0]->text);
      std::string ok = sym ? sym->object_kind : "";
      // A CSG value takes the material as a one-child union (children without their own
      // material take the block's); a group, a mesh or what a macro or an unknown name gives
      // (often a union) as a one-member group with the material, which its members without
      // their own take (POV-Ray's texture on a union); a shape is derived with it (POV-Ray's
      // texture on a shape replaces the shape's).
      if (ok == "intersection" || ok == "difference" || ok == "merge" || ok == "union" || ok == "clip")
        s = fmt::format("union {{ {}  material = {} }}", base, m);
      else if (ok.empty() || ok == "object" || ok == "mesh" || ok == "group")
        s = fmt::format("group {{ {}  material = {} }}", base, m);
      else
        s = fmt::format("{} with {{ material = {} }}", base, m);
    }
    for (const std::string& p : props) {
      if (p == "inverse = true") {
        // A bare name needs no parentheses, and a line starting with one would continue the
        // line before as a call (`QCone_Y` then `(QCone_Y) with ...`).
        const bool name = std::all_of(s.begin(), s.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; });
        const std::size_t with = s.find(" with { ");
        const bool derived = with != std::string::npos && s.size() > 2 && s.compare(s.size() - 2, 2, " }") == 0 &&
                             std::all_of(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(with), [](char ch) {
                               return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
                             });
        if (name)
          s += " with { inverse = true }";
        else if (derived)  // `Name with { material = ... }`: one derivation more
          s.insert(s.size() - 2, "  inverse = true");
        else  // never a statement that starts with '(' (it would call the line before)
          s = "union { (" + s + ") with { inverse = true } }";
      } else if (p == "casts_shadow = false") {
        s = "group { " + s + "  casts_shadow = false }";  // whatever it places casts none
      } else {
        warn(b.loc, "'" + p + "' on a reused object is not translated");
      }
    }
    for (const std::string& t : xforms) s += " " + t;
    for (const std::string& c : comments) w.line("// " + c);
    w.line(prefix + s);
    return;
  }
  // What may place a member: an object, a directive (a loop, an #if), a macro call; a bare
  // value (`merge { y, 0 ... }`, from fuzz_pov) places nothing.
  const bool members = std::any_of(children.begin(), children.end(), [](const Item* c) {
    return c->kind != Item::Value || c->args.empty() || c->args[0]->kind == Expr::Call;
  });
  if ((kind == "intersection" || kind == "difference" || kind == "merge" || kind == "union") && !members) {
    // rts's CSG needs a shape; one without shows nothing in POV-Ray either: an empty group,
    // which renders nothing.
    warn(b.loc, fmt::format("a {} without objects shows nothing: written as an empty group", k));
    kind = "group";
  }
  bool pushed = false;
  if (kind == "group") {
    if (textured || needs_default) {
      group_material_.push_back(material_of(textured));
      pushed = true;
      // What a macro call or a name places inside is translated elsewhere: the group's own
      // material reaches its members that have none (rts's group material).
      if (std::any_of(children.begin(), children.end(), [](const Item* c) { return c->kind == Item::Value; }))
        props.push_back("material = " + group_material_.back());
    }
  } else if (textured || needs_default) {
    props.push_back("material = " + material_of(textured));
  }
  std::string suffix;
  for (const std::string& t : xforms) suffix += " " + t;
  for (const std::string& c : comments) w.line("// " + c);
  if (children.empty()) {
    if (pushed) group_material_.pop_back();
    std::string s;
    for (const std::string& p : props) s += (s.empty() ? " " : "  ") + p;
    std::string one = fmt::format("{}{} {{{} }}{}", prefix, kind, s, suffix);
    if (one.size() <= 110) {
      w.line(one);
      return;
    }
    w.open(prefix + kind);
    for (const std::string& p : props) w.line(p);
    w.close(suffix);
    return;
  }
  w.open(prefix + kind);
  scopes_.emplace_back();
  const bool csg = kind == "intersection" || kind == "difference" || kind == "merge" || kind == "union";
  if (csg) ++csg_depth_;
  {
    BodyFlag body(in_block_body_, true);
    for (const Item* c : children) {
      if (c->kind == Item::Nested) {
        w.comments(c->comments);
        object(w, *c->block, "", false);
      } else {
        item(w, *c, false);
      }
    }
  }
  if (csg) --csg_depth_;
  scopes_.pop_back();
  if (pushed) group_material_.pop_back();
  last_kind_ = kind;  // the members wrote theirs
  for (const std::string& p : props) w.line(p);
  w.close(suffix);
}

}  // namespace rts::import::pov
