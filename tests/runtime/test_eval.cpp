// Evaluating whole programs: scopes, loops, macros, recursion, builtins, materials, textures,
// transforms, placement and instancing, includes and defines.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "eval_helpers.hpp"
#include "render/builder/scene_summary.hpp"

using namespace rts;
using namespace rts::render;
using rts::test::eval_diagnostic;
using rts::test::eval_text;
using rts::test::eval_warnings;

namespace {

// Programs report values by placing spheres: `probe(x)` places a sphere whose radius is x.
// The world's placements in order (SceneDesc::roots keeps them as runs, read front to back).
std::vector<Child> roots_of(const SceneDesc& s) { return {s.roots.begin(), s.roots.end()}; }

const std::string kProbe = "macro probe(x) { sphere { radius = x } }\n";

std::vector<double> probes(const std::string& body, const EvalOptions& opts = {}) {
  SceneDesc s = eval_text(kProbe + body, opts);
  std::vector<double> out;
  for (const Child& c : s.roots) {
    const Node& n = s.nodes[c.node];
    if (n.kind == NodeKind::Shape)
      if (auto* sp = shape_if<Sphere>(s.shapes[n.index].geometry)) out.push_back(sp->radius);
  }
  return out;
}

double probe1(const std::string& body) {
  auto p = probes(body);
  REQUIRE(p.size() == 1);
  return p[0];
}

}  // namespace

TEST_CASE("let, assignment and compound assignment", "[eval]") {
  CHECK(probe1("let a = 2  a += 3  a *= 4  a -= 1  a /= 19  probe(a)") == 1.0);
  CHECK(probe1("let v = <1, 2, 3>  probe(v.y + v.z)") == 5.0);
  CHECK(probe1("let c = rgb(0.25, 0.5, 1)  probe(c.r + c.b)") == 1.25);
}

TEST_CASE("scopes: inner lets shadow and vanish; assignment reaches the nearest binding", "[eval]") {
  CHECK(probes("let x = 1  if true { let x = 2  probe(x) }  probe(x)") == std::vector<double>{2, 1});
  CHECK(probe1("let x = 1  if true { x = 5 }  probe(x)") == 5);
  CHECK(probe1("let t = 0  for i in 0 .. 3 { let sq = i * i  t += sq }  probe(t + 1)") == 6);
  // A loop variable is local to its loop.
  CHECK_THAT(test::eval_error("for i in 0 .. 2 { }  sphere { radius = i }"), Catch::Contains("undefined name 'i'"));
}

TEST_CASE("loops: ranges with steps, lists, break and continue, while", "[eval]") {
  CHECK(probes("for i in 1 ..= 3 { probe(i) }") == std::vector<double>{1, 2, 3});
  CHECK(probes("for i in 1 .. 2 step 0.25 { probe(i) }") == std::vector<double>{1, 1.25, 1.5, 1.75});
  CHECK(probes("for r in [3, 1, 2] { probe(r) }") == std::vector<double>{3, 1, 2});
  CHECK(probes("for i in 1 .. 100 { if i == 3 { break }  probe(i) }") == std::vector<double>{1, 2});
  CHECK(probes("for i in 1 ..= 4 { if i % 2 == 0 { continue }  probe(i) }") == std::vector<double>{1, 3});
  CHECK(probe1("let n = 0  while n < 10 { n += 3 }  probe(n)") == 12);
}

TEST_CASE("macros: defaults, named arguments, return values", "[eval]") {
  std::string defs =
      "macro area(w, h = 2) { return w * h }\n"
      "macro third(a, b = a + 1, c = b * 10) { return c }\n";
  CHECK(probe1(defs + "probe(area(3))") == 6);
  CHECK(probe1(defs + "probe(area(3, 4))") == 12);
  CHECK(probe1(defs + "probe(area(h = 5, w = 1))") == 5);
  CHECK(probe1(defs + "probe(third(1))") == 20);  // defaults see earlier parameters
  CHECK(probe1(defs + "probe(third(1, c = 7))") == 7);
  CHECK(probe1("macro nothing() { return }  probe(1)  nothing()") == 1);
}

TEST_CASE("macros see globals but not their caller's locals", "[eval]") {
  CHECK(probe1("let g = 4  macro f() { return g }  probe(f())") == 4);
  CHECK_THAT(test::eval_error("macro f() { return local }\nif true { let local = 1  f() }"),
             Catch::Contains("undefined name 'local'"));
}

TEST_CASE("recursion works to the limit and stops past it", "[eval]") {
  std::string fact = "macro fact(n) { if n <= 1 { return 1 } return n * fact(n - 1) }\n";
  CHECK(probe1(fact + "probe(fact(10))") == 3628800);
  std::string deep = "macro down(n) { if n == 0 { return 0 } return down(n - 1) }\n";
  EvalOptions opts;
  opts.limits.max_recursion = 1000;
  CHECK(probe1(deep + "probe(down(999) + 1)") == 1);
  CHECK_THAT(test::eval_error(deep + "down(1000)", opts), Catch::Contains("nested deeper than 1000"));
  opts.limits.max_recursion = 100000;  // the evaluator's stack grows with the limit
  CHECK(probes(deep + "probe(down(50000) + 1)", opts).size() == 1);
}

TEST_CASE("macros place objects into the caller's current group", "[eval]") {
  SceneDesc s = eval_text(
      "macro two() { sphere { radius = 1 }  box { min = <0,0,0> max = <1,1,1> } }\n"
      "group { two() }\n two()");
  REQUIRE(s.groups.size() == 1);
  CHECK(s.groups[0].children.size() == 2);
  CHECK(s.roots.size() == 3);  // the group and the second call's two objects
}

TEST_CASE("builtins", "[eval]") {
  CHECK(probe1("probe(sqrt(16) + abs(-1) + floor(2.7) + ceil(0.2) + round(1.5))") == 10);
  CHECK(probe1("probe(sin(radians(90)))") == Approx(1.0));
  CHECK(probe1("probe(degrees(atan2(1, 1)))") == Approx(45.0));
  CHECK(probe1("probe(min(3, 1, 2) + max([4, 9, 2]))") == 10);
  // Vectors component by component: a box from two corners in any order.
  CHECK(probe1("let a = min(<1, -2, 3>, <0, 5, 4>)  probe(a.x + 10 * a.y + 100 * a.z)") == 0 - 20 + 300);
  CHECK(probe1("let b = max([<1, -2, 3>, <0, 5, 4>, <2, 0, 0>])  probe(b.x + 10 * b.y + 100 * b.z)") == 2 + 50 + 400);
  CHECK_THAT(test::eval_error("let c = min(<1, 2, 3>, 4)"), Catch::Contains("'min' of vectors needs vectors only, got a number"));
  // with_item: a copy with one element replaced; the original list is unchanged.
  CHECK(probe1("let a = [1, 2, 3]  let b = with_item(a, 1, 20)  probe(a[1] + b[1] + b[0] + b[2] + len(b))") ==
        2 + 20 + 1 + 3 + 3);
  CHECK_THAT(test::eval_error("let a = with_item([1, 2], 2, 0)"), Catch::Contains("index 2 out of range for a list of 2 elements"));
  CHECK_THAT(test::eval_error("let a = with_item([1, 2], 0.5, 0)"), Catch::Contains("index 0.5 out of range"));
  CHECK_THAT(test::eval_error("let a = with_item(3, 0, 0)"), Catch::Contains("a list"));
  CHECK(probe1("probe(clamp(5, 0, 2) + mix(0, 10, 0.25))") == 4.5);
  CHECK(probe1("probe(dot(<1,2,3>, <4,5,6>))") == 32);
  CHECK(probe1("probe(length(cross(<1,0,0>, <0,1,0>) * 3))") == 3);
  CHECK(probe1("probe(length(normalize(<3, 4, 0>)))") == Approx(1.0));
  CHECK(probe1("probe(len([1, 2, 3]) + len(\"abcd\") + len(0 .. 10 step 2))") == 12);
  CHECK(probe1("probe(len(format(\"{} and {}\", 1, <1,2,3>)))") == std::string("1 and <1, 2, 3>").size());
  CHECK(probe1("probe(len(str(0.5)))") == 3);
  // POV-Ray's str(x, width, decimals): printf's %W.Df, a negative width padding with zeros.
  CHECK(probe1("probe(len(str(0, 0, 2)))") == 4);                              // "0.00"
  CHECK(probe1("probe(len(str(3.14159, 8, 3)))") == 8);                        // "   3.142"
  CHECK(probe1("assert(str(-2.5, -7, 1) == \"-0002.5\", \"zeros after the sign\")  probe(1)") == 1);
  CHECK(probe1("assert(str(1, 0, -1) == \"1.000000\", \"six decimals\")  probe(1)") == 1);
  CHECK(probe1("probe(pow(2, 3) + exp(0) + log(1))") == 9);
  CHECK(probe1("let v = vec(1, 2, 3)  probe(v.z)") == 3);
  CHECK(probe1("assert(1 < 2, \"fine\")  probe(1)") == 1);
}

TEST_CASE("random streams are deterministic from their seed", "[eval][random]") {
  std::string draws = "let r = random(7)  for i in 0 .. 5 { probe(rand(r, 1, 2)) }";
  auto a = probes(draws), b = probes(draws);
  CHECK(a == b);
  REQUIRE(a.size() == 5);
  for (double x : a) CHECK((x >= 1 && x < 2));
  CHECK(a != probes("let r = random(8)  for i in 0 .. 5 { probe(rand(r, 1, 2)) }"));
  CHECK(a[0] != a[1]);  // a stream advances
}

TEST_CASE("random(seed, \"povray\") draws POV-Ray 3.7's own sequence", "[eval][random]") {
  // Printed by POV-Ray 3.7 (#debug str(rand(seed(12)), 0, 9) ..., and seed(-5)).
  auto a = probes("let r = random(12, \"povray\")  for i in 0 .. 3 { probe(rand(r)) }");
  REQUIRE(a.size() == 3);
  CHECK(a[0] == Approx(0.063882885).margin(1e-9));
  CHECK(a[1] == Approx(0.713253849).margin(1e-9));
  CHECK(a[2] == Approx(0.250982069).margin(1e-9));
  CHECK(probe1("let r = random(-5, \"povray\")  probe(rand(r))") == Approx(0.890052870).margin(1e-9));
  CHECK(eval_diagnostic("let r = random(1, \"pov\")").message.find("\"povray\"") != std::string::npos);
  CHECK(eval_diagnostic("let r = random(1.5, \"povray\")").message.find("a whole number") != std::string::npos);
}

TEST_CASE("one definition placed many times is one shape and many instances", "[eval][instancing]") {
  SceneDesc s = eval_text("let s = sphere { radius = 0.1 }\nfor i in 0 .. 100 { s translate <i, 0, 0> }");
  CHECK(s.shapes.size() == 1);
  CHECK(s.nodes.size() == 1);
  REQUIRE(s.roots.size() == 100);
  for (std::size_t i = 0; i < 100; ++i) {
    CHECK(roots_of(s)[i].node == roots_of(s)[0].node);
    CHECK(roots_of(s)[i].transform[3].x == static_cast<double>(i));
  }
  // A block evaluated in a loop, by contrast, defines a shape per iteration.
  SceneDesc t = eval_text("for i in 0 .. 10 { sphere { radius = 1 } }");
  CHECK(t.shapes.size() == 10);
}

TEST_CASE("transforms compose in written order; rotate is in degrees x then y then z", "[eval][transform]") {
  SceneDesc s = eval_text(
      "sphere { radius = 1 } scale 2 translate <1, 0, 0>\n"
      "sphere { radius = 1 } rotate <0, 90, 0>\n"
      "sphere { radius = 1 } rotate <90, 90, 0>\n"
      "sphere { radius = 1 } matrix [1,0,0, 0,1,0, 0,0,1, 4,5,6]");
  REQUIRE(s.roots.size() == 4);
  auto apply = [&](std::size_t i, glm::dvec3 p) { return glm::dvec3(roots_of(s)[i].transform * glm::dvec4(p, 1)); };
  CHECK(apply(0, {1, 0, 0}) == glm::dvec3(3, 0, 0));  // scaled, then moved
  glm::dvec3 r = apply(1, {1, 0, 0});
  CHECK(r.x == Approx(0).margin(1e-12));
  CHECK(r.z == Approx(-1));            // POV-Ray / glm convention
  glm::dvec3 q = apply(2, {0, 1, 0});  // x first: y → z; then about y: z → x
  CHECK(q.x == Approx(1));
  CHECK(q.y == Approx(0).margin(1e-12));
  CHECK(apply(3, {0, 0, 0}) == glm::dvec3(4, 5, 6));
}

TEST_CASE("groups nest and carry their transforms; lights in groups are children", "[eval]") {
  SceneDesc s = eval_text(
      "group { group { sphere { radius = 1 } } translate <0, 1, 0>  point_light { position = <0, 5, 0> } }"
      " rotate <0, 45, 0>");
  REQUIRE(s.roots.size() == 1);
  REQUIRE(s.groups.size() == 2);
  const Node& outer = s.nodes[roots_of(s)[0].node];
  CHECK(outer.kind == NodeKind::Group);
  const GroupDesc& g = s.groups[outer.index];
  REQUIRE(g.children.size() == 2);
  CHECK(s.nodes[g.children[0].node].kind == NodeKind::Group);
  CHECK(g.children[0].transform[3].y == 1);
  CHECK(s.nodes[g.children[1].node].kind == NodeKind::Light);
}

TEST_CASE("every node's item keeps where it was written", "[eval]") {
  // Nodes carry no location of their own (8 bytes each); node_loc reads the item's.
  SceneDesc s = eval_text(
      "sphere { radius = 1 }\n"
      "  point_light { position = <0, 5, 0> }\n"
      "group { box { min = <0, 0, 0>  max = <1, 1, 1> } }\n"
      "   difference { sphere { radius = 1 } box { min = <0, 0, 0>  max = <1, 1, 1> } }\n");
  REQUIRE(s.roots.size() == 4);
  const uint32_t lines[] = {1, 2, 3, 4}, cols[] = {1, 3, 1, 4};
  for (std::size_t i = 0; i < 4; ++i) {
    const SourceRef at = node_loc(s, s.nodes[roots_of(s)[i].node]);
    CHECK(at.line == lines[i]);
    CHECK(at.col == cols[i]);
  }
  CHECK(node_loc(s, Node{NodeKind::Csg, 99}).line == 0);  // out of range: no location
}

TEST_CASE("materials: one value is one material; with derives new ones", "[eval][material]") {
  SceneDesc s = eval_text(
      "let ivory = material { color = rgb(0.9, 0.9, 0.8)  diffuse = 0.7  reflect = 0.2 }\n"
      "let glass = ivory with { diffuse = 0  transmit = 0.95  ior = 1.5 }\n"
      "for i in 0 .. 5 { sphere { radius = 1  material = ivory } }\n"
      "sphere { radius = 1  material = glass }\n"
      "sphere { radius = 1  material = ivory with { color = rgb(1, 0, 0) } }");
  REQUIRE(s.materials.size() == 3);
  const MaterialDesc& ivory = s.materials[s.shapes[0].material];
  const MaterialDesc& glass = s.materials[s.shapes[5].material];
  const MaterialDesc& red = s.materials[s.shapes[6].material];
  for (int i = 1; i < 5; ++i) CHECK(s.shapes[i].material == s.shapes[0].material);
  CHECK(ivory.diffuse == 0.7);
  CHECK(glass.diffuse == 0);
  CHECK(glass.transmit == Color(0.95));
  CHECK(glass.reflect == Color(0.2));  // inherited
  CHECK(glass.ior == 1.5);
  CHECK(red.color == Color(1, 0, 0));
  CHECK(red.diffuse == 0.7);
}

TEST_CASE("textures from builtins and blocks, with transforms", "[eval][texture]") {
  SceneDesc s = eval_text(
      "let c = checker(rgb(1), rgb(0), 0.5)\n"
      "plane { normal = <0,1,0>  material = material { texture = c } }\n"
      "plane { normal = <0,1,0>  material = material { color = stripes { color1 = rgb(1,0,0) axis = \"z\" } "
      "scale 2 } }");
  REQUIRE(s.textures.size() == 2);
  CHECK(s.textures[0].kind == TextureKind::Checker);
  CHECK(s.textures[0].scale == 0.5);
  CHECK(s.textures[1].kind == TextureKind::Stripes);
  CHECK(s.textures[1].axis == 2);
  CHECK(s.textures[1].transform[0][0] == 2);
  CHECK(s.materials[1].texture == 1);
}

TEST_CASE("settings and camera blocks configure the scene", "[eval]") {
  SceneDesc s =
      eval_text("settings { width = 100  height = 50  samples = 4 }  camera { position = <0, 1, -3>  fov = 45 }");
  CHECK(s.settings.width == 100);
  CHECK(s.settings.height == 50);
  CHECK(s.settings.samples == 4);
  CHECK(s.has_camera);
  CHECK(s.camera.fov == 45);
}

TEST_CASE("inline meshes from lists", "[eval]") {
  SceneDesc s = eval_text("mesh { vertices = [<0,0,0>, <1,0,0>, <0,1,0>, <1,1,0>]  faces = [<0,1,2>, <1,3,2>] }");
  REQUIRE(s.meshes.size() == 1);
  CHECK(s.meshes[0]->indices.size() == 6);
}

TEST_CASE("vertex_specular takes numbers or colors", "[eval][course]") {
  const std::string tri = "triangle { v0 = <0,0,0>  v1 = <1,0,0>  v2 = <0,1,0>  vertex_specular = ";
  SceneDesc colors = eval_text(tri + "[rgb(1, 0.5, 0), rgb(0), rgb(0.25)] }");
  REQUIRE(colors.meshes.size() == 1);
  REQUIRE(colors.meshes[0]->specular.size() == 3);
  CHECK(colors.meshes[0]->specular[0] == glm::vec3(1.0f, 0.5f, 0.0f));
  CHECK(colors.meshes[0]->specular[2] == glm::vec3(0.25f));
  // A number x is the gray color rgb(x).
  SceneDesc numbers = eval_text(tri + "[0.5, 0, 1] }");
  REQUIRE(numbers.meshes.size() == 1);
  CHECK(numbers.meshes[0]->specular[0] == glm::vec3(0.5f));
  CHECK(rts::test::eval_error(tri + "[rgb(1), rgb(-1, 0, 0), rgb(0)] }").find("must not be negative") != std::string::npos);
  CHECK(rts::test::eval_error(tri + "[1, 2] }").find("has 2 entries for 3 vertices") != std::string::npos);
  CHECK(rts::test::eval_error(tri + "\"shiny\" }").find("expects a list of numbers or colors") != std::string::npos);
}

TEST_CASE("defines replace the first top-level let of the main file", "[eval][defines]") {
  EvalOptions opts;
  opts.defines = {{"q", "2"}, {"v", "<1, 2, 3>"}};
  CHECK(probes("let q = 1  let v = <0, 0, 0>  probe(q + v.z)", opts) == std::vector<double>{5});
  // The defined let's own expression is not evaluated.
  CHECK(probes("let q = 1 / 0  let v = 0  probe(q)", opts) == std::vector<double>{2});
  EvalOptions twice;
  twice.defines = {{"q", "1"}, {"q", "3"}};
  CHECK(probes("let q = 0  probe(q)", twice) == std::vector<double>{3});  // the last one wins
  CHECK(test::eval_warnings("let q = 0", twice).empty());
  EvalOptions unused;
  unused.defines = {{"nothing", "3"}};
  CHECK_THAT(test::eval_warnings("let a = 1", unused),
             Catch::Contains("define 'nothing=3' matches no top-level 'let nothing'"));
}

TEST_CASE("includes resolve relative to the including file, then -I paths", "[eval][include]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("rts_include_test_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  fs::create_directories(dir / "lib");
  std::ofstream(dir / "sub" / "a.rts") << "include \"b.rts\"\nlet from_a = from_b + 1\n";
  std::ofstream(dir / "sub" / "b.rts") << "let from_b = 10\n";
  std::ofstream(dir / "lib" / "c.rts") << "let from_c = 100\n";
  std::ofstream(dir / "main.rts") << kProbe << "include \"sub/a.rts\"\ninclude \"c.rts\"\nprobe(from_a + from_c)\n";
  EvalOptions opts;
  opts.include_paths = {(dir / "lib").string()};
  SourceManager sm;
  std::ostringstream w;
  DiagnosticSink sink(w);
  SceneDesc s = evaluate_file(sm, (dir / "main.rts").string(), opts, sink).scene;
  REQUIRE(s.shapes.size() == 1);
  CHECK(shape_get<Sphere>(s.shapes[0].geometry).radius == 111);
  fs::remove_all(dir);
}

TEST_CASE("a file already fully included is not run again; one being included is a cycle", "[eval][include]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("rts_include_once_test_" + std::to_string(::getpid()));
  fs::create_directories(dir / "lib");
  // materials.rts declares a name and places a sphere: included from a.rts, b.rts and main
  // (by another spelling of its path), it runs once, so no "already defined" and one sphere.
  std::ofstream(dir / "lib" / "materials.rts") << "let ivory = material { diffuse = 0.7 }\nsphere { radius = 5 }\n";
  std::ofstream(dir / "a.rts") << "include \"lib/materials.rts\"\nsphere { radius = 1  material = ivory }\n";
  std::ofstream(dir / "b.rts") << "include \"lib/materials.rts\"\nsphere { radius = 2  material = ivory }\n";
  std::ofstream(dir / "main.rts") << "include \"a.rts\"\ninclude \"b.rts\"\ninclude \"lib/../lib/materials.rts\"\n";
  std::ofstream(dir / "cycle.rts") << "include \"cycle.rts\"\n";
  SourceManager sm;
  std::ostringstream w;
  DiagnosticSink sink(w);
  SceneDesc s = evaluate_file(sm, (dir / "main.rts").string(), {}, sink).scene;
  REQUIRE(s.shapes.size() == 3);
  CHECK(shape_get<Sphere>(s.shapes[0].geometry).radius == 5);  // materials.rts, once
  CHECK(shape_get<Sphere>(s.shapes[1].geometry).radius == 1);
  CHECK(shape_get<Sphere>(s.shapes[2].geometry).radius == 2);
  CHECK(s.roots.size() == 3);
  CHECK(s.materials.size() == 1);
  // A file that includes itself is still a cycle (it is on the include stack, not finished).
  try {
    evaluate_file(sm, (dir / "cycle.rts").string(), {}, sink);
    FAIL("expected an include cycle");
  } catch (const LanguageError& e) {
    CHECK(e.diag.message == "include cycle: 'cycle.rts' is already being included");
  }
  fs::remove_all(dir);
}

TEST_CASE("with derives a new shape or light definition from an object", "[eval][instancing]") {
  SceneDesc s = eval_text(
      "let m = material { diffuse = 0.5 }\n"
      "let s = sphere { radius = 1  material = m }\n"
      "let big = s with { radius = 2 }\n"
      "for i in 0 .. 3 { s translate <i, 0, 0> }\n"
      "for i in 0 .. 4 { big translate <i, 5, 0> }\n"
      "(s translate <0, 0, 9>) with { center = <1, 0, 0> }\n"
      "let lamp = point_light { position = <0, 5, 0>  intensity = 0.5 }\n"
      "lamp\n"
      "lamp with { position = <1, 2, 3> }\n");
  // Two placed sphere definitions plus the transformed-and-derived one; the base unchanged.
  REQUIRE(s.shapes.size() == 3);
  CHECK(shape_get<Sphere>(s.shapes[0].geometry).radius == 1);
  CHECK(shape_get<Sphere>(s.shapes[1].geometry).radius == 2);
  CHECK(shape_get<Sphere>(s.shapes[2].geometry).radius == 1);                    // inherited
  CHECK(shape_get<Sphere>(s.shapes[2].geometry).center == glm::dvec3(1, 0, 0));  // overridden
  CHECK(s.shapes[1].material == s.shapes[0].material);                         // one material
  CHECK(s.materials.size() == 1);
  REQUIRE(s.roots.size() == 3 + 4 + 1 + 2);
  for (std::size_t i = 0; i < 3; ++i) CHECK(roots_of(s)[i].node == roots_of(s)[0].node);
  for (std::size_t i = 3; i < 7; ++i) CHECK(roots_of(s)[i].node == roots_of(s)[3].node);
  CHECK(roots_of(s)[3].node != roots_of(s)[0].node);
  CHECK(roots_of(s)[7].transform[3].z == 9);  // the derived object keeps its base's transform
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].intensity == 0.5);
  CHECK(s.lights[1].intensity == 0.5);  // inherited
  CHECK(s.nodes[roots_of(s)[9].node].kind == NodeKind::Light);
  CHECK(roots_of(s)[9].node != roots_of(s)[8].node);
}

TEST_CASE("the summary of a group that holds itself (a scene built by hand) ends", "[eval][summary]") {
  // The evaluator cannot make the cycle (a group holds only what existed before it); a
  // SceneDesc built through the API can, and both ways of counting must still stop.
  SceneDesc s = eval_text(
      "let ball = sphere { radius = 1 }\n"
      "let pair = group { ball  ball translate <4, 0, 0> }\n"
      "pair translate <0, 10, 0>\n");
  NodeId group_node = 0;
  while (group_node < s.nodes.size() && s.nodes[group_node].kind != render::NodeKind::Group) ++group_node;
  REQUIRE(group_node < s.nodes.size());
  s.groups[s.nodes[group_node].index].children.push_back(render::Child{group_node, render::Mat4(1.0), {}});
  // By each group's totals: the member open on the stack adds nothing.
  const render::SceneSummary grouped = render::summarize(s, 0);
  CHECK(grouped.shapes.at("sphere") == 2);
  CHECK(grouped.instances == 3);
  // Walked: stops once past the count the totals gave (what it has counted is not meaningful).
  CHECK(render::summarize(s, 1000).instances <= 4);
}

TEST_CASE("check's summary counts placed instances through groups and bounds them in world space", "[eval][summary]") {
  SceneDesc s = eval_text(
      "let ball = sphere { radius = 1 }\n"
      "let pair = group { ball  ball translate <4, 0, 0> }\n"
      "pair translate <0, 10, 0>\n"
      "pair scale 2\n"
      "plane { normal = <0, 1, 0> }\n"
      "point_light { position = <0, 5, 0> }\n");
  render::SceneSummary sum = render::summarize(s);
  CHECK(sum.shapes["sphere"] == 4);  // one definition: 2 group instances x 2 children
  CHECK(sum.shapes["plane"] == 1);
  CHECK(sum.lights["point_light"] == 1);
  CHECK(sum.shape_definitions == 2);
  CHECK(sum.instances == 2 + 4 + 1 + 1);  // groups, their children, plane, light
  CHECK(sum.unbounded);
  REQUIRE(sum.has_bounds);
  CHECK(sum.bounds_min == glm::dvec3(-2, -2, -2));  // the scaled pair: spheres of radius 2
  CHECK(sum.bounds_max == glm::dvec3(10, 11, 2));   // <8,0,0> + 2, and <4,10,0> + 1
}

TEST_CASE("check's summary of a scene past the exact walk counts the same and bounds it by its groups' boxes", "[eval][summary]") {
  // Nested groups, a CSG block, lights and a mesh inside groups, rotated and scaled placements:
  // summarized from each group's totals (limit 0) the counts are the walk's; the bounds enclose
  // the walk's (each placed group's box, looser under a rotation) and equal them here where no
  // group is rotated.
  const std::string text =
      "let ball = sphere { radius = 1 }\n"
      "let tri = mesh { vertices = [<0, 0, 0>, <1, 0, 0>, <0, 1, 0>]  faces = [<0, 1, 2>] }\n"
      "let lens = intersection { sphere { center = <0, 0, -0.5>  radius = 1 }  sphere { center = <0, 0, 0.5>  radius = 1 } }\n"
      "let pair = group { ball  ball translate <4, 0, 0>  tri  point_light { position = <0, 3, 0> } }\n"
      "let quad = group { pair  pair translate <0, 0, 6>  lens }\n"
      "for i in 0 .. 5 { quad translate <i * 20, 0, 0> }\n"
      "pair scale 2\n"
      "plane { normal = <0, 1, 0> }\n";
  render::SceneSummary exact = render::summarize(eval_text(text + "quad translate <0, 10, 0>\n"));
  render::SceneSummary grouped = render::summarize(eval_text(text + "quad translate <0, 10, 0>\n"), 0);
  CHECK_FALSE(exact.bounds_of_group_boxes);
  CHECK(grouped.bounds_of_group_boxes);
  CHECK(grouped.shapes == exact.shapes);
  CHECK(grouped.lights == exact.lights);
  CHECK(grouped.shapes["sphere"] == 6 * (2 * 2 + 2) + 2);  // 6 quads (2 pairs of 2 balls, a lens of 2), a pair
  CHECK(grouped.instances == exact.instances);
  CHECK(grouped.triangles == exact.triangles);
  CHECK(grouped.triangles == 6 * 2 + 1);
  CHECK(grouped.unbounded == exact.unbounded);
  REQUIRE(grouped.has_bounds);
  for (int a = 0; a < 3; ++a) {
    CHECK(grouped.bounds_min[a] == Approx(exact.bounds_min[a]));
    CHECK(grouped.bounds_max[a] == Approx(exact.bounds_max[a]));
  }
  // A rotated placement: the group's box turned is larger than its shapes turned, never smaller.
  render::SceneDesc turned = eval_text(text + "quad rotate <0, 30, 0> translate <-50, 10, 0>\n");
  render::SceneSummary t_exact = render::summarize(turned), t_grouped = render::summarize(turned, 0);
  CHECK(t_grouped.shapes == t_exact.shapes);
  CHECK(t_grouped.instances == t_exact.instances);
  for (int a = 0; a < 3; ++a) {
    CHECK(t_grouped.bounds_min[a] <= t_exact.bounds_min[a]);
    CHECK(t_grouped.bounds_max[a] >= t_exact.bounds_max[a]);
  }
  const Vec3 looser = (t_exact.bounds_min - t_grouped.bounds_min) + (t_grouped.bounds_max - t_exact.bounds_max);
  CHECK(looser.x + looser.y + looser.z > 0.1);
}

TEST_CASE("a mesh is built when first placed: an unused one never opens its file", "[eval][lazy]") {
  // The OBJ does not exist: unused, that is no error and no mesh is built.
  render::SceneDesc unused = eval_text("let m = mesh { file = \"no-such-mesh.obj\" }\nsphere { radius = 1 }");
  CHECK(unused.meshes.empty());
  CHECK(unused.shapes.size() == 1);
  // Placed, the same declaration is the usual error, located at the file property.
  CHECK(eval_diagnostic("let m = mesh { file = \"no-such-mesh.obj\" }\nm").message.find("no-such-mesh.obj") !=
        std::string::npos);
  // Placed twice (and once transformed), an inline mesh is built once.
  render::SceneDesc placed = eval_text(
      "let m = mesh { vertices = [<0, 0, 0>, <1, 0, 0>, <0, 1, 0>]  faces = [<0, 1, 2>] }\n"
      "m\nm translate <1, 0, 0>\nlet n = m with { smooth = false }\n");
  CHECK(placed.meshes.size() == 1);
  CHECK(placed.roots.size() == 2);
  CHECK(roots_of(placed)[0].node == roots_of(placed)[1].node);
}

TEST_CASE("check warns about each unused top-level declaration, with its location", "[eval][lazy]") {
  EvalOptions opts;
  opts.warn_unused = true;
  std::string w = eval_warnings(
      "let used = material { }\nlet spare = material { }\nlet t = checker(rgb(1), rgb(0), 1)\n"
      "macro unused_macro() { }\nlet big = mesh { file = \"missing.obj\" }\nlet n = 3\n"
      "sphere { radius = 1  material = used }\n",
      opts);
  CHECK(w.find("test.rts:2:5: warning: material 'spare' is declared but never used") != std::string::npos);
  CHECK(w.find("test.rts:3:5: warning: texture 't'") != std::string::npos);
  CHECK(w.find("macro 'unused_macro' is declared but never used (so it never runs)") != std::string::npos);
  CHECK(w.find("mesh 'big' is declared but never used (so it is not built); its file 'missing.obj' does not exist") !=
        std::string::npos);
  CHECK(w.find("'used'") == std::string::npos);  // used
  CHECK(w.find("'n'") == std::string::npos);     // numbers are not declarations of features
  // Without the option (rts render, rts eval) nothing is said.
  CHECK(eval_warnings("let spare = material { }\n", EvalOptions{}).empty());
}
