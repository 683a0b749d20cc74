// USC CSCI 420's .scene format: an object count, the global ambient light, then objects:
//   2
//   amb: 0.3 0.3 0.3
//   triangle  (three vertices of pos: nor: dif: spe: shi:)
//   sphere    pos: rad: dif: spe: shi:
//   light     pos: col:
// The camera is fixed at the origin looking down -z with a 60° vertical field of view on a
// 640x480 image. Shading: amb + Σ light * (dif (N·L) + spe (R·V)^shi), the ambient term added
// once, not scaled by the material: it becomes each material's `emission`. The background is
// white; colors are clamped per channel.
// The extra-credit switches (ImportOptions): recursive reflection (1 - ks)·local + ks·reflected
// becomes materials scaled by (1 - ks) with reflect = ks; N x N supersampling is N² stratified
// samples; soft shadows split each point light into N sub-lights of color / N, jittered
// within a ball around it.
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "import/convert_util.hpp"
#include "import/tokens.hpp"
#include "import/writer.hpp"

namespace rts::import {
namespace {

struct Vertex {
  glm::dvec3 pos{0}, nor{0}, dif{0}, spe{0};
  double shi = 1;
};

// A small deterministic generator (splitmix64): the sub-lights of --soft-shadows are the same
// on every run and machine.
struct Jitter {
  uint64_t state = 0x9E3779B97F4A7C15ull;
  double next() {  // in [0, 1)
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
  glm::dvec3 in_ball(double radius) {  // uniform in the ball, by rejection
    while (true) {
      glm::dvec3 p(2 * next() - 1, 2 * next() - 1, 2 * next() - 1);
      if (glm::dot(p, p) <= 1) return radius * p;
    }
  }
};

struct Csci {
  Csci(Tokens& t, const ImportOptions& o, SceneText& s) : tk(t), opt(o), out(s) {}
  Tokens& tk;
  const ImportOptions& opt;
  SceneText& out;
  glm::dvec3 amb{0};
  std::map<std::string, std::string> materials;   // material text → name, so equal ones share
  Jitter jitter;

  glm::dvec3 field(const std::string& name) {
    tk.expect(name);
    return tk.vec3();
  }

  // What the local (Phong) color keeps with --reflection: (1 - ks) per channel; 1 without.
  glm::dvec3 local_weight(const glm::dvec3& ks) const {
    return opt.reflection > 0 ? glm::clamp(glm::dvec3(1) - ks, 0.0, 1.0) : glm::dvec3(1);
  }

  // `ks` is the mirror weight (--reflection); the local terms are already scaled by 1 - ks.
  std::string material(const glm::dvec3& dif, const glm::dvec3& spe, double shi, const glm::dvec3& ks,
                       const glm::dvec3& local) {
    std::string body = fmt::format("material {{ color = {}  ambient = 0  diffuse = 1  specular = {}  shininess = {}  "
                                   "emission = {}{} }}",
                                   rgb(dif), specular_value(spe), num(shi), rgb(amb * local),
                                   opt.reflection > 0 && ks != glm::dvec3(0) ? "  reflect = " + rgb(ks) : "");
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
      const glm::dvec3 k = local_weight(v[0].spe);
      out.world.line(fmt::format("triangle {{ {}  material = {} }}", geometry,
                                 material(v[0].dif * k, v[0].spe * k, v[0].shi, v[0].spe, k)));
      return;
    }
    // Each vertex its own material: interpolated across the triangle. The mirror weight and
    // the ambient term are one per material: the mean of the vertices' ks.
    const glm::dvec3 ks = (v[0].spe + v[1].spe + v[2].spe) / 3.0;
    std::string base = material(glm::dvec3(1), glm::dvec3(0), 1, ks, local_weight(ks));
    glm::dvec3 k[3] = {local_weight(v[0].spe), local_weight(v[1].spe), local_weight(v[2].spe)};
    out.world.open("triangle");
    out.world.line(geometry);
    out.world.line(fmt::format("vertex_colors = [{}, {}, {}]", rgb(v[0].dif * k[0]), rgb(v[1].dif * k[1]),
                               rgb(v[2].dif * k[2])));
    out.world.line("vertex_specular = " + specular_list({v[0].spe * k[0], v[1].spe * k[1], v[2].spe * k[2]}));
    out.world.line(fmt::format("vertex_shininess = [{}, {}, {}]", num(v[0].shi), num(v[1].shi), num(v[2].shi)));
    out.world.line("material = " + base);
    out.world.close();
  }

  void run() {
    int count = tk.integer();
    tk.expect("amb:");
    amb = tk.vec3();
    std::string settings = "settings { width = 640  height = 480  background = rgb(1)";
    if (opt.antialias > 1)
      settings += fmt::format("  samples = {}  sampler = \"stratified\"", opt.antialias * opt.antialias);
    if (opt.reflection > 0) settings += fmt::format("  max_depth = {}", opt.reflection);
    out.top.line(settings + aov_settings(opt, 0.0) + "  output_gamma = \"linear\" }");
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
        const glm::dvec3 k = local_weight(spe);
        out.world.line(fmt::format("sphere {{ center = {}  radius = {}  material = {} }}", vec(pos), num(rad),
                                   material(dif * k, spe * k, shi, spe, k)));
      } else if (kind.text == "light") {
        glm::dvec3 pos = field("pos:"), col = field("col:");
        out.world.comments(kind.comments);
        if (opt.soft_shadows > 1) {
          out.world.line(fmt::format("// soft shadows: the light at {} as {} sub-lights within {} of it", vec(pos),
                                     opt.soft_shadows, num(opt.soft_shadow_radius)));
          for (int j = 0; j < opt.soft_shadows; ++j)
            out.world.line(fmt::format("point_light {{ position = {}  color = {} }}",
                                       vec(pos + jitter.in_ball(opt.soft_shadow_radius)),
                                       rgb(col / static_cast<double>(opt.soft_shadows))));
        } else {
          out.world.line(fmt::format("point_light {{ position = {}  color = {} }}", vec(pos), rgb(col)));
        }
      } else {
        tk.fail(kind, fmt::format("unknown object '{}' (expected triangle, sphere or light)", kind.text));
      }
    }
    if (!tk.done()) tk.fail(tk.peek(), fmt::format("more than the {} objects the first line announces", count));
  }
};

}  // namespace

void import_csci420(const std::string& text, const ImportOptions& opt, SceneText& out) {
  Tokens tk(text);
  Csci csci(tk, opt, out);
  csci.run();
}

}  // namespace rts::import
