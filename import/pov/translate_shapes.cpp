// POV-Ray shapes whose components are blocks of their own: a blob's spheres and cylinders
// become the list properties of rts's blob (docs/shapes.md#blob); an isosurface's or a height
// field's function becomes a macro of the point, its container and controls properties
// (docs/shapes.md#isosurface, #height_field); a mesh of literal triangles and a mesh2 become
// one rts mesh (docs/shapes.md#mesh).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
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
      bool sphere = true;
      const std::string entry = blob_component(*it.block, sphere);
      std::string& list = sphere ? spheres : cylinders;
      list += (list.empty() ? "" : ", ") + entry;
      continue;
    }
    rest.items.push_back(it);
  }
  // Components a loop places: its lists, filled by the loops object() writes before the blob.
  const BlobLists* lists = blob_lists_.empty() ? nullptr : &blob_lists_.back();
  auto joined = [](const std::string& literal, const std::string& list) {
    if (literal.empty()) return list;
    return list.empty() ? "[" + literal + "]" : "[" + literal + "] + " + list;
  };
  const std::string s = joined(spheres, lists ? lists->spheres : ""), c = joined(cylinders, lists ? lists->cylinders : "");
  if (!s.empty()) props.push_back("spheres = " + s);
  if (!c.empty()) props.push_back("cylinders = " + c);
  return rest;
}

std::string Translator::blob_component(const Block& c, bool& sphere) {
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
  auto at = [&](std::size_t i) { return translate.empty() ? vector_value(*v[i]) : vector_value(*v[i]) + " + " + translate; };
  sphere = c.kind == "sphere";
  if (sphere) {
    if (v.size() < 3) error(c.loc, "a blob's 'sphere' needs a centre, a radius and a strength");
    return fmt::format("[{}, {}, {}]", at(0), value(*v[1]), value(*v[2]));
  }
  if (v.size() < 4) error(c.loc, "a blob's 'cylinder' needs two ends, a radius and a strength");
  return fmt::format("[{}, {}, {}, {}]", at(0), at(1), value(*v[2]), value(*v[3]));
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

namespace rts::import::pov {

namespace {

// One rts mesh's vertex list built from corners: a corner is a position and, in a smooth
// mesh, a normal; equal corners (compared as written) share one vertex.
struct MeshBuilder {
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  std::vector<std::string> positions, normals, faces;
  std::size_t corner(const std::string& p, const std::string& n) {
    auto [it, fresh] = index.emplace(std::make_pair(p, n), positions.size());
    if (fresh) {
      positions.push_back(p);
      if (!n.empty()) normals.push_back(n);
    }
    return it->second;
  }
  void face(std::size_t a, std::size_t b, std::size_t c) { faces.push_back(fmt::format("<{}, {}, {}>", a, b, c)); }
  void write(std::vector<std::string>& props) const {
    auto list = [](const std::vector<std::string>& v) {
      std::string s = "[";
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
      return s + "]";
    };
    props.insert(props.begin(), {"vertices = " + list(positions), "faces = " + list(faces)});
    if (!normals.empty()) props.insert(props.begin() + 2, "normals = " + list(normals));
    else props.insert(props.begin() + 2, "smooth = false");  // POV-Ray's mesh without normals is flat
  }
};

std::string literal_vec3(const std::vector<double>& q) { return vec(glm::dvec3(q[0], q[1], q[2])); }

}  // namespace

bool Translator::mesh_components(const Block& b, std::vector<std::string>& props, Block& rest) {
  rest = Block{};
  rest.kind = b.kind;
  rest.loc = b.loc;
  MeshBuilder m;
  if (b.kind == "mesh") {
    // Literal triangles only (no loop, macro or textured triangle among them), all flat or all
    // smooth; anything else stays a group of triangles.
    bool flat = false, smooth = false;
    for (const Item& it : b.items) {
      if (it.kind == Item::Keyword && (it.name == "inside_vector" || it.name == "hierarchy")) continue;
      if (it.kind != Item::Nested || (it.block->kind != "triangle" && it.block->kind != "smooth_triangle")) {
        if (it.kind == Item::Value) return false;
        rest.items.push_back(it);
        continue;
      }
      const bool s = it.block->kind == "smooth_triangle";
      std::vector<std::string> v;
      for (const Item& ti : it.block->items) {
        std::vector<double> q;
        if (ti.kind != Item::Value || !literal_vector(*ti.args[0], q) || q.size() != 3) return false;
        v.push_back(literal_vec3(q));
      }
      if (v.size() != (s ? 6u : 3u)) return false;
      (s ? smooth : flat) = true;
      std::size_t c[3];
      for (int k = 0; k < 3; ++k) c[k] = m.corner(v[s ? 2 * k : k], s ? v[2 * k + 1] : "");
      m.face(c[0], c[1], c[2]);
    }
    if (m.faces.empty() || (flat && smooth)) return false;
    m.write(props);
    return true;
  }
  // mesh2: vertex_vectors, normal_vectors, face_indices, normal_indices; the rest warned.
  std::vector<std::vector<double>> vertices, normals, face_list, normal_faces;
  bool have_normal_indices = false;
  auto values = [&](const Block& part, std::size_t width, std::vector<std::vector<double>>& out, bool faces) {
    std::vector<const Item*> v;
    for (const Item& it : part.items)
      if (it.kind == Item::Value) v.push_back(&it);
      else warn(it.loc, fmt::format("this entry of '{}' is not translated", part.kind));
    double count = 0;
    if (v.empty() || !literal_number(*v[0]->args[0], count))
      error(part.loc, fmt::format("'{}' needs its count first: {} {{ N, ... }}", part.kind, part.kind));
    std::size_t listed = 0;
    for (std::size_t i = 1; i < v.size(); ++i) {
      std::vector<double> q;
      double n;
      if (faces && literal_number(*v[i]->args[0], n)) continue;  // a face's texture index (texture_list)
      if (!literal_vector(*v[i]->args[0], q) || q.size() < width)
        error(v[i]->loc, fmt::format("'{}' lists literal vectors only here (rts import does not evaluate "
                                     "expressions inside a mesh2)", part.kind));
      out.push_back(q);
      ++listed;
    }
    if (count != static_cast<double>(listed))
      error(part.loc, fmt::format("'{}' says {} entries but lists {}", part.kind, num(count), listed));
  };
  for (const Item& it : b.items) {
    if (it.kind == Item::Keyword && (it.name == "inside_vector" || it.name == "hierarchy")) continue;
    if (it.kind != Item::Nested) {
      rest.items.push_back(it);
      continue;
    }
    const std::string& k = it.block->kind;
    if (k == "vertex_vectors") values(*it.block, 3, vertices, false);
    else if (k == "normal_vectors") values(*it.block, 3, normals, false);
    else if (k == "face_indices") values(*it.block, 3, face_list, true);
    else if (k == "normal_indices") {
      values(*it.block, 3, normal_faces, false);
      have_normal_indices = true;
    } else if (k == "uv_vectors" || k == "uv_indices")
      unsupported(it.loc, k, "the mesh's own uvs (its barycentric coordinates)", false);
    else if (k == "texture_list")
      unsupported(it.loc, "texture_list", "one texture for the whole mesh2 (its own)", false);
    else
      rest.items.push_back(it);
  }
  if (vertices.empty() || face_list.empty())
    error(b.loc, "'mesh2' needs vertex_vectors and face_indices");
  const bool smooth = !normals.empty();
  if (have_normal_indices && normal_faces.size() != face_list.size())
    error(b.loc, fmt::format("mesh2's normal_indices lists {} faces, face_indices {}", normal_faces.size(),
                             face_list.size()));
  if (smooth && !have_normal_indices && normals.size() != vertices.size())
    error(b.loc, fmt::format("mesh2 has {} normal_vectors for {} vertex_vectors and no normal_indices",
                             normals.size(), vertices.size()));
  auto at = [&](const std::vector<std::vector<double>>& list, double i, const char* what) -> const std::vector<double>& {
    if (!(i >= 0 && i < static_cast<double>(list.size())) || i != std::floor(i))
      error(b.loc, fmt::format("mesh2 names {} {} of {}", what, num(i), list.size()));
    return list[static_cast<std::size_t>(i)];
  };
  for (std::size_t f = 0; f < face_list.size(); ++f) {
    std::size_t c[3];
    for (int k = 0; k < 3; ++k) {
      const double vi = face_list[f][k];
      const double ni = have_normal_indices ? normal_faces[f][k] : vi;
      c[k] = m.corner(literal_vec3(at(vertices, vi, "vertex")), smooth ? literal_vec3(at(normals, ni, "normal")) : "");
    }
    m.face(c[0], c[1], c[2]);
  }
  m.write(props);
  return true;
}

}  // namespace rts::import::pov
