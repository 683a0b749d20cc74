// USC CSCI 420's .scene format: an object count, the global ambient light, then objects:
//   2
//   amb: 0.3 0.3 0.3
//   triangle  (three vertices of pos: nor: dif: spe: shi:)
//   sphere    pos: rad: dif: spe: shi:
//   light     pos: col:
// The camera is fixed at the origin looking down -z with a 60° vertical field of view on a
// 640x480 image. Shading: amb + Σ light * (dif (N·L) + spe (R·V)^shi), the ambient term added
// once, not scaled by the material: it becomes each material's `emission`.
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "import/tokens.hpp"
#include "import/writer.hpp"

namespace rts::import {
namespace {

struct Vertex {
  glm::dvec3 pos{0}, nor{0}, dif{0}, spe{0};
  double shi = 1;
};

struct Csci {
  Csci(Tokens& t, SceneText& s) : tk(t), out(s) {}
  Tokens& tk;
  SceneText& out;
  glm::dvec3 amb{0};
  std::map<std::string, std::string> materials;   // material text → name, so equal ones share

  glm::dvec3 field(const std::string& name) {
    tk.expect(name);
    return tk.vec3();
  }

  std::string material(const glm::dvec3& dif, const glm::dvec3& spe, double shi) {
    std::string body = fmt::format("material {{ color = {}  ambient = 0  diffuse = 1  specular = {}  shininess = {}  "
                                   "emission = {} }}",
                                   rgb(dif), specular_value(spe), num(shi), rgb(amb));
    auto it = materials.find(body);
    if (it != materials.end()) return it->second;
    std::string name = fmt::format("material{}", materials.size());
    out.top.line(fmt::format("let {} = {}", name, body));
    materials.emplace(body, name);
    return name;
  }

  Vertex vertex() {
    Vertex v;
    v.pos = field("pos:");
    v.nor = field("nor:");
    v.dif = field("dif:");
    v.spe = field("spe:");
    tk.expect("shi:");
    v.shi = tk.number();
    return v;
  }

  void triangle(const Token& kind) {
    Vertex v[3] = {vertex(), vertex(), vertex()};
    out.world.comments(kind.comments);
    std::string geometry = fmt::format("v0 = {}  v1 = {}  v2 = {}  n0 = {}  n1 = {}  n2 = {}", vec(v[0].pos),
                                       vec(v[1].pos), vec(v[2].pos), vec(v[0].nor), vec(v[1].nor), vec(v[2].nor));
    bool same = v[0].dif == v[1].dif && v[1].dif == v[2].dif && v[0].spe == v[1].spe && v[1].spe == v[2].spe &&
                v[0].shi == v[1].shi && v[1].shi == v[2].shi;
    if (same) {
      out.world.line(fmt::format("triangle {{ {}  material = {} }}", geometry, material(v[0].dif, v[0].spe, v[0].shi)));
      return;
    }
    // Each vertex its own material: interpolated across the triangle.
    std::string base = material(glm::dvec3(1), glm::dvec3(0), 1);
    out.world.open("triangle");
    out.world.line(geometry);
    out.world.line(fmt::format("vertex_colors = [{}, {}, {}]", rgb(v[0].dif), rgb(v[1].dif), rgb(v[2].dif)));
    out.world.line("vertex_specular = " + specular_list({v[0].spe, v[1].spe, v[2].spe}));
    out.world.line(fmt::format("vertex_shininess = [{}, {}, {}]", num(v[0].shi), num(v[1].shi), num(v[2].shi)));
    out.world.line("material = " + base);
    out.world.close();
  }

  void run() {
    int count = tk.integer();
    tk.expect("amb:");
    amb = tk.vec3();
    out.top.line("settings { width = 640  height = 480 }");
    write_camera(out.top, glm::dvec3(0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), 60, FovAxis::Vertical,
                 "CSCI 420's fixed camera: 60° vertical field of view on 640x480");
    for (int i = 0; i < count; ++i) {
      Token kind = tk.next();
      if (kind.text == "triangle") {
        triangle(kind);
      } else if (kind.text == "sphere") {
        glm::dvec3 pos = field("pos:");
        tk.expect("rad:");
        double rad = tk.number();
        glm::dvec3 dif = field("dif:"), spe = field("spe:");
        tk.expect("shi:");
        double shi = tk.number();
        out.world.comments(kind.comments);
        out.world.line(fmt::format("sphere {{ center = {}  radius = {}  material = {} }}", vec(pos), num(rad),
                                   material(dif, spe, shi)));
      } else if (kind.text == "light") {
        glm::dvec3 pos = field("pos:"), col = field("col:");
        out.world.comments(kind.comments);
        out.world.line(fmt::format("point_light {{ position = {}  color = {} }}", vec(pos), rgb(col)));
      } else {
        tk.fail(kind, fmt::format("unknown object '{}' (expected triangle, sphere or light)", kind.text));
      }
    }
    if (!tk.done()) tk.fail(tk.peek(), fmt::format("more than the {} objects the first line announces", count));
  }
};

}  // namespace

void import_csci420(const std::string& text, const ImportOptions&, SceneText& out) {
  Tokens tk(text);
  Csci csci(tk, out);
  csci.run();
}

}  // namespace rts::import
