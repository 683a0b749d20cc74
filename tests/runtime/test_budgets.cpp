// Evaluation budgets (issue 7): the step budget counts loop iterations, macro calls and the
// list elements and string bytes built; groups are counted as they expand; appending to a
// list held by one variable is amortised O(1) and never changes what other holders see.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include "eval_helpers.hpp"
#include "render/scene/resource_limits.hpp"

using namespace rts;
using rts::test::dump;
using rts::test::eval_diagnostic;
using rts::test::eval_text;

namespace {

EvalOptions with_steps(uint64_t steps) {
  EvalOptions o;
  o.limits.max_steps = steps;
  return o;
}

}  // namespace

TEST_CASE("a doubling macro recursion ends at the step budget, naming the macro", "[budgets]") {
  // 2^61 calls, never deeper than 61: only counting calls can stop it.
  Diagnostic d = eval_diagnostic("macro f(d) {\n  if d > 0 { f(d - 1)  f(d - 1) }\n}\nf(60)\n", with_steps(10000));
  CHECK(d.message.find("more than 10000 steps") != std::string::npos);
  CHECK(d.message.find("calls to macro 'f'") != std::string::npos);
  CHECK(d.message.find("--max-steps") != std::string::npos);
  CHECK(d.loc.line() == 2);
}

TEST_CASE("doubling a list or a string ends at the step budget", "[budgets]") {
  Diagnostic list = eval_diagnostic("let xs = [1]\nfor i in 0 .. 64 { xs = xs + xs }\n", with_steps(1'000'000));
  CHECK(list.message.find("list elements built") != std::string::npos);
  CHECK(list.loc.line() == 2);
  Diagnostic str = eval_diagnostic("let s = \"ab\"\nfor i in 0 .. 64 { s = s + s }\n", with_steps(1'000'000));
  CHECK(str.message.find("string bytes built") != std::string::npos);
  Diagnostic fmt = eval_diagnostic("let s = \"ab\"\nfor i in 0 .. 64 { s = format(\"{}{}\", s, s) }\n",
                                   with_steps(1'000'000));
  CHECK(fmt.message.find("string bytes built") != std::string::npos);
}

TEST_CASE("appending to a list in a loop costs one step per element, not a copy", "[budgets]") {
  // 100,000 iterations, 100,000 one-element literals, 100,000 elements appended: 300,000
  // steps. Copying the list on every append would build 5 billion elements.
  EvalOptions o = with_steps(300'000);
  CHECK_NOTHROW(eval_text("let xs = []\nfor i in 0 .. 100000 { xs = xs + [i] }\nassert(len(xs) == 100000)", o));
  CHECK_NOTHROW(eval_text("let xs = []\nfor i in 0 .. 100000 { xs += [i] }\nassert(xs[99999] == 99999)", o));
  CHECK_NOTHROW(eval_text("let s = \"\"\nfor i in 0 .. 100000 { s = s + \"x\" }\nassert(len(s) == 100000)", o));
}

TEST_CASE("appending in place never changes another holder of the list", "[budgets]") {
  // Each assert fails if the append wrote into a list someone else still sees.
  CHECK_NOTHROW(eval_text(
      "let xs = [1, 2]\nlet ys = xs\nxs = xs + [3]\nassert(len(ys) == 2)\nassert(len(xs) == 3)\n"
      "let zs = [xs]\nxs += [4]\nassert(len(zs[0]) == 3)\n"
      "let a = [1]\nfor x in a { a = a + [x] }\nassert(len(a) == 2)\n"
      "let b = [1, 2]\nb = b + b\nassert(b == [1, 2, 1, 2])\nb += b\nassert(len(b) == 8)\n"
      "let s = \"ab\"\nlet t = s\ns = s + s\nassert(t == \"ab\")\nassert(s == \"abab\")\n"));
  // The right operand may rebind the variable: the old value is still the left operand.
  CHECK_NOTHROW(eval_text(
      "let xs = [1]\nmacro reset() { xs = [7, 7, 7]  return 2 }\nxs = xs + [reset()]\nassert(xs == [1, 2])\n"));
  // Type errors read as before.
  CHECK(eval_diagnostic("let xs = [1]\nxs = xs + 2\n").message == "cannot add a list and a number");
}

TEST_CASE("groups are counted as they expand, before anything is built", "[budgets]") {
  EvalOptions o;
  o.limits.max_objects = 1000;
  Diagnostic d = eval_diagnostic(
      "let g = group { sphere { radius = 1 } }\n"
      "for i in 0 .. 40 {\n  g = group { g  g translate <1, 0, 0> }\n}\ng\n",
      o);
  CHECK(d.message.find("this group expands to 1024 objects, more than the limit of 1000") != std::string::npos);
  CHECK(d.message.find("--max-objects") != std::string::npos);
  CHECK(d.loc.line() == 3);
  // Placing a group that fits many times over still counts every copy.
  Diagnostic w = eval_diagnostic(
      "let g = group { sphere { radius = 1 } sphere { radius = 2 } }\nfor i in 0 .. 600 { g translate <i, 0, 0> }\n", o);
  CHECK(w.message.find("more than 1000 objects once its groups are expanded") != std::string::npos);
  // Lights count as objects, and shapes placed one by one, and a CSG block as one (traced whole).
  Diagnostic l = eval_diagnostic(
      "let g = group { sphere { radius = 1 } point_light { position = <0, 5, 0> } }\n"
      "for i in 0 .. 501 { g translate <i, 0, 0> }\n", o);
  CHECK(l.message.find("more than 1000 objects once its groups are expanded") != std::string::npos);
  CHECK(l.loc.line() == 2);
  Diagnostic c = eval_diagnostic(
      "for i in 0 .. 300 { sphere { radius = 1 } }\n"
      "let d = difference { sphere { radius = 1 } sphere { radius = 0.5 } }\n"
      "for i in 0 .. 701 { d translate <i, 0, 0> }\n", o);
  CHECK(c.message.find("more than 1000 objects") != std::string::npos);
  CHECK(c.loc.line() == 3);
  CHECK(eval_text("let g = group { sphere { radius = 1 } point_light { position = <0, 5, 0> } }\n"
                  "for i in 0 .. 500 { g translate <i, 0, 0> }\n", o).roots.size() == 500);
}

TEST_CASE("the memory budget stops a list before it is built", "[budgets]") {
  EvalOptions o;
  o.limits.max_memory = std::size_t(256) << 20;
  Diagnostic d = eval_diagnostic("let xs = [1]\nfor i in 0 .. 64 { xs = xs + xs }\n", o);
  CHECK(d.message.find("memory limit of 256 MiB") != std::string::npos);
  CHECK(d.message.find("--max-memory") != std::string::npos);
  CHECK(d.loc.line() == 2);
}

TEST_CASE("the memory budget reaches OBJ loading: a mesh too big for it is a located error", "[budgets]") {
  // The evaluator once built the scene builder without --max-memory, so a 2M-triangle mesh
  // loaded under --max-memory 64M. 300,000 triangles need about 19 MB by the loader's estimate.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rts_budget_obj_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream obj(dir / "big.obj");
    obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 300000; ++i) obj << "f 1 2 3\n";
  }
  const std::string scene = (dir / "scene.rts").string();
  const std::string text = "settings { width = 8 height = 8 }\nmesh { file = \"big.obj\" }\n";
  EvalOptions o;
  o.limits.max_memory = render::resident_bytes() + (std::size_t(8) << 20);
  std::string message;
  SourceLoc loc;
  try {
    rts::test::eval_text(text, o, scene);
  } catch (const LanguageError& e) {
    message = e.diag.message;
    loc = e.diag.loc;
  }
  // Without the limit the same mesh loads.
  CHECK(rts::test::eval_text(text, EvalOptions{}, scene).meshes.size() == 1);
  fs::remove_all(dir);
  CHECK(message.find("mesh file big.obj") != std::string::npos);
  CHECK(message.find("--max-memory") != std::string::npos);
  CHECK(loc.line() == 2);
}

TEST_CASE("area light samples above the cap are clamped with a located warning", "[budgets]") {
  std::string w = rts::test::eval_warnings(
      "area_light { position = <0, 5, 0>  u = <1, 0, 0>  v = <0, 0, 1>\n  samples = 100000 }\n", {});
  CHECK(w.find("test.rts:2:3: warning: area_light samples 100000 is more than 4096; 4096 are used") !=
        std::string::npos);
  Diagnostic d = eval_diagnostic("settings { samples = 1000000000 }");
  CHECK(d.message == "property 'samples' of settings must be from 1 to 65536, got 1000000000");
}
