// POV-Ray shapes whose components are blocks of their own: a blob's spheres and cylinders
// become the list properties of rts's blob (docs/shapes.md#blob); an isosurface's or a height
// field's function becomes a macro of the point, its container and controls properties
// (docs/shapes.md#isosurface, #height_field).
#include <algorithm>
#include <functional>
#include <set>

#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

Block Translator::blob_components(const Block& b, std::vector<std::string>& props) {
  Block rest;
  rest.kind = b.kind;
  rest.loc = b.loc;
  std::string spheres, cylinders;
  for (const Item& it : b.items) {
    if (it.kind == Item::Keyword && it.name == "threshold" && !it.args.empty()) {
      props.push_back("threshold = " + value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Keyword && (it.name == "sturm" || it.name == "hierarchy")) continue;  // solver hints
    if (it.kind == Item::Keyword && it.name == "component") {
      // The old form: component strength, radius, <centre>.
      if (it.args.size() < 3) error(it.loc, "'component' needs a strength, a radius and a centre");
      spheres += fmt::format("{}[{}, {}, {}]", spheres.empty() ? "" : ", ", vector_value(*it.args[2]),
                             value(*it.args[1]), value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Nested && (it.block->kind == "sphere" || it.block->kind == "cylinder")) {
      const Block& c = *it.block;
      std::vector<const Expr*> v;
      std::string translate;  // a literal translate moves the component; other modifiers are not carried
      for (const Item& ci : c.items) {
        if (ci.kind == Item::Value) v.push_back(ci.args[0].get());
        else if (ci.kind == Item::Keyword && ci.name == "strength" && !ci.args.empty()) v.push_back(ci.args[0].get());
        else if (ci.kind == Item::Keyword && ci.name == "translate" && !ci.args.empty() && translate.empty())
          translate = vector_value(*ci.args[0]);
        else
          unsupported(ci.loc, ci.kind == Item::Nested ? ci.block->kind + " (on a blob component)"
                                                      : ci.name + " (on a blob component)",
                      "the blob's own texture and transforms", false);
      }
      auto at = [&](std::size_t i) { return translate.empty() ? vector_value(*v[i])
                                                              : vector_value(*v[i]) + " + " + translate; };
      if (c.kind == "sphere") {
        if (v.size() < 3) error(c.loc, "a blob's 'sphere' needs a centre, a radius and a strength");
        spheres += fmt::format("{}[{}, {}, {}]", spheres.empty() ? "" : ", ", at(0), value(*v[1]), value(*v[2]));
      } else {
        if (v.size() < 4) error(c.loc, "a blob's 'cylinder' needs two ends, a radius and a strength");
        cylinders += fmt::format("{}[{}, {}, {}, {}]", cylinders.empty() ? "" : ", ", at(0), at(1), value(*v[2]),
                                 value(*v[3]));
      }
      continue;
    }
    rest.items.push_back(it);
  }
  if (!spheres.empty()) props.push_back("spheres = [" + spheres + "]");
  if (!cylinders.empty()) props.push_back("cylinders = [" + cylinders + "]");
  return rest;
}

namespace {

// The file types POV-Ray's height_field reads; rts reads PNG.
bool is_image_keyword(const std::string& k) {
  return k == "png" || k == "tga" || k == "gif" || k == "pot" || k == "ppm" || k == "pgm" || k == "sys" ||
         k == "jpeg" || k == "tiff" || k == "exr" || k == "hdr" || k == "iff" || k == "bmp";
}

// A literal vector, or a literal float promoted to <f, f, f> (POV-Ray's `box { -1, 1 }`).
bool literal_point(const Expr& e, std::vector<double>& out) {
  double k;
  if (Translator::literal_number(e, k)) {
    out.assign(3, k);
    return true;
  }
  return Translator::literal_vector(e, out) && out.size() == 3;
}

const Block* function_block(const Item& it) {
  return it.kind == Item::Nested && it.block && it.block->kind == "function" ? it.block.get() : nullptr;
}

}  // namespace

std::string Translator::function_text(const Block& f, const std::map<std::string, std::string>& vars,
                                      std::string& why) {
  const Item* body = nullptr;
  for (const Item& it : f.items)
    if (it.kind == Item::Value) body = &it;
  if (!body) {
    why = "a body that is not one expression of its parameters (a pattern, POV-Ray-only syntax)";
    return "";
  }
  // Calls rts's function compiler takes: the math builtins, and functions declared as macros.
  static const std::set<std::string> kCompiled = {"sin",  "cos",  "tan",  "asin", "acos",  "atan",   "atan2",
                                                  "sqrt", "pow",  "exp",  "abs",  "floor", "ceil",   "min",
                                                  "max",  "radians", "degrees"};
  std::function<bool(const Expr&)> compiles = [&](const Expr& e) {
    if (e.kind == Expr::Call && !kCompiled.count(e.text)) {
      Symbol* s = lookup(e.text);
      if (!s || s->type != Type::Macro) {
        why = fmt::format("a call of '{}', which rts's compiled functions do not have", e.text);
        return false;
      }
    }
    for (const ExprPtr& a : e.args)
      if (a && !compiles(*a)) return false;
    return true;
  };
  if (!compiles(*body->args[0])) return "";
  auto saved = function_vars_;
  function_vars_ = vars;
  std::string text = value(*body->args[0]);
  function_vars_ = std::move(saved);
  return text;
}

bool Translator::declare_function(Writer& w, const std::string& name, const Block& f, std::string& why) {
  std::vector<std::string> params;
  for (const Item& it : f.items)
    if (it.kind == Item::Keyword && it.name == "params")
      for (const ExprPtr& a : it.args) params.push_back(a->text);
  if (params.empty()) params = {"x", "y", "z"};  // POV-Ray's function { ... } takes x, y, z
  std::map<std::string, std::string> vars;
  std::string list;
  for (const std::string& p : params) {
    vars[p] = rename(p);
    list += (list.empty() ? "" : ", ") + rename(p);
  }
  std::string body = function_text(f, vars, why);
  if (body.empty()) return false;
  w.line(fmt::format("macro {}({}) {{ return {} }}", rename(name), list, body));
  return true;
}

Block Translator::solid_components(Writer& w, const Block& b, std::vector<std::string>& props) {
  Block rest;
  rest.kind = b.kind;
  rest.loc = b.loc;
  const bool iso = b.kind == "isosurface";
  for (const Item& it : b.items) {
    if (const Block* f = function_block(it)) {
      // POV-Ray samples a height field's function at <x, 1 - z, 0> of the unit square (rts's
      // height field puts the image's top row at z = 1); an isosurface's at the point.
      const std::map<std::string, std::string> vars =
          iso ? std::map<std::string, std::string>{{"x", "p.x"}, {"y", "p.y"}, {"z", "p.z"}}
              : std::map<std::string, std::string>{{"x", "p.x"}, {"y", "(1 - p.z)"}, {"z", "0"}};
      std::string why;
      std::string body = function_text(*f, vars, why);
      if (body.empty()) {
        unsupported(it.loc, "function with " + why,
                    "a function written as one expression of x, y and z, with the math builtins and declared functions",
                    false);
        return Block{"unsupported", b.loc, {}};
      }
      const std::string name = fmt::format("pov_{}_{}", iso ? "iso" : "height", ++functions_written_);
      w.line(fmt::format("macro {}(p) {{ return {} }}", name, body));
      props.push_back("function = " + name);
      for (const Item& r : f->items)
        if (r.kind == Item::Keyword && r.name == "resolution" && !r.args.empty())
          props.push_back(fmt::format("resolution = [{}, {}]", value(*r.args[0]),
                                      value(*r.args[r.args.size() > 1 ? 1 : 0])));
      continue;
    }
    if (it.kind == Item::Keyword && !iso && is_image_keyword(it.name) && !it.args.empty()) {
      if (it.name != "png")
        unsupported(it.loc, "height_field " + it.name, "a PNG image (convert it: rts reads PNG height fields)", false);
      props.push_back("file = " + value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Keyword && !iso && it.name == "smooth") {
      props.push_back("smooth = true");
      continue;
    }
    if (it.kind == Item::Keyword && !iso && it.name == "water_level" && !it.args.empty()) {
      props.push_back("water_level = " + value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Keyword && !iso && it.name == "hierarchy") continue;  // a build hint
    if (it.kind == Item::Keyword && iso &&
        (it.name == "threshold" || it.name == "max_gradient" || it.name == "accuracy" || it.name == "max_trace") &&
        !it.args.empty()) {
      props.push_back(it.name + " = " + value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Keyword && iso && it.name == "max_trace") continue;  // `max_trace all_intersections`
    if (it.kind == Item::Keyword && iso && (it.name == "all_intersections" || it.name == "evaluate")) {
      if (it.name == "evaluate") unsupported(it.loc, "evaluate", "a max_gradient that bounds the function", false);
      continue;
    }
    if (it.kind == Item::Keyword && iso && it.name == "open") {
      unsupported(it.loc, "open (isosurface)", "the isosurface closed by its container", false);
      continue;
    }
    if (it.kind == Item::Nested && iso && it.block->kind == "contained_by") {
      const Block* shape = nullptr;
      for (const Item& c : it.block->items)
        if (c.kind == Item::Nested) shape = c.block.get();
      std::vector<const Expr*> v;
      if (shape)
        for (const Item& c : shape->items)
          if (c.kind == Item::Value) v.push_back(c.args[0].get());
      if (shape && shape->kind == "box" && v.size() >= 2) {
        std::vector<double> a, c;
        if (literal_point(*v[0], a) && literal_point(*v[1], c)) {
          glm::dvec3 lo(std::min(a[0], c[0]), std::min(a[1], c[1]), std::min(a[2], c[2]));
          glm::dvec3 hi(std::max(a[0], c[0]), std::max(a[1], c[1]), std::max(a[2], c[2]));
          props.push_back(fmt::format("contained_by = box {{ min = {}  max = {} }}", vec(lo), vec(hi)));
        } else {
          props.push_back(fmt::format("contained_by = box {{ min = {}  max = {} }}", vector_value(*v[0]),
                                      vector_value(*v[1])));
        }
      } else if (shape && shape->kind == "sphere" && v.size() >= 2) {
        props.push_back(fmt::format("contained_by = sphere {{ center = {}  radius = {} }}", vector_value(*v[0]),
                                    value(*v[1])));
      } else {
        unsupported(it.loc, "contained_by", "a box { A, B } or sphere { C, r } container", false);
      }
      continue;
    }
    rest.items.push_back(it);
  }
  return rest;
}

}  // namespace rts::import::pov
