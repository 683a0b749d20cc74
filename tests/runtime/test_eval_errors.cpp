// Runtime errors: located at the most precise node, with notes for each macro call.
#include <catch2/catch.hpp>

#include "eval_helpers.hpp"

using namespace rts;
using rts::test::eval_diagnostic;
using rts::test::eval_error;

TEST_CASE("undefined names suggest a close binding", "[errors]") {
  Diagnostic d = eval_diagnostic("let radius = 1\nsphere { radius = raduis }");
  CHECK(d.message == "undefined name 'raduis'; did you mean 'radius'?");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 19);
}

TEST_CASE("errors inside macros carry one note per active call, innermost first", "[errors]") {
  Diagnostic d = eval_diagnostic(
      "macro inner(x) { return x / 0 }\n"
      "macro outer() { return inner(1) }\n"
      "let y = outer()\n");
  CHECK(d.message == "division by zero");
  CHECK(d.loc.line() == 1);
  REQUIRE(d.notes.size() == 2);
  CHECK(d.notes[0].message == "in call to macro 'inner' from here");
  CHECK(d.notes[0].loc.line() == 2);
  CHECK(d.notes[1].message == "in call to macro 'outer' from here");
  CHECK(d.notes[1].loc.line() == 3);
}

TEST_CASE("builder errors become located language errors", "[errors]") {
  Diagnostic d = eval_diagnostic("macro ball(r) { sphere { radius = r  centre = <0,0,0> } }\nball(1)");
  CHECK(d.message == "unknown property 'centre' for sphere; did you mean 'center'? (sphere takes material, center, radius, casts_shadow)");
  CHECK(d.loc.line() == 1);
  CHECK(d.loc.col() == 38);
  REQUIRE(d.notes.size() == 1);
  CHECK(d.notes[0].loc.line() == 2);
  CHECK(eval_diagnostic("sphere { }").message == "sphere needs property 'radius'");
  CHECK(eval_diagnostic("sphere { radius = \"big\" }").message ==
        "property 'radius' of sphere expects a number, got a string");
}

TEST_CASE("a catalogue of runtime errors", "[errors]") {
  CHECK(eval_diagnostic("let a = <1,2,3> + \"s\"").message == "cannot add a vector and a string");
  CHECK(eval_diagnostic("let a = sqrt(\"x\")").message == "argument 1 of 'sqrt' must be a number, got a string");
  CHECK(eval_diagnostic("let a = sin(1, 2)").message == "'sin' takes 1 argument, got 2");
  CHECK(eval_diagnostic("let a = sqrt(-1)").message == "sqrt(-1) produced NaN (not a number)");
  CHECK(eval_diagnostic("let a = pow(10, 400)").message == "pow(10, 400) produced an infinite value");
  CHECK(eval_diagnostic("let a = [1, 2][2]").message == "index 2 out of range for a list of 2 elements");
  CHECK(eval_diagnostic("assert(1 > 2, \"one is small\")").message == "assertion failed: one is small");
  CHECK(eval_diagnostic("error(\"stop here\")").message == "stop here");
  CHECK(eval_diagnostic("let a = 1\nlet a = 2").message.find("'a' is already defined") == 0);
  CHECK(eval_diagnostic("b = 2").message.find("cannot assign to undefined name 'b'") == 0);
  CHECK(eval_diagnostic("macro m(a) { }\nm(1, 2)").message == "macro 'm' takes at most 1 argument, got 2");
  CHECK(eval_diagnostic("macro m(a) { }\nm()").message == "missing argument 'a' in call to macro 'm'");
  CHECK(eval_diagnostic("macro m(size) { }\nm(szie = 1)").message ==
        "macro 'm' has no parameter 'szie'; did you mean 'size'?");
  CHECK(eval_diagnostic("shpere { radius = 1 }").message == "unknown block kind 'shpere'; did you mean 'sphere'?");
  CHECK(eval_diagnostic("if 1 { }").message == "'if' condition must be a bool, got a number");
  CHECK(eval_diagnostic("break").message == "'break' outside a loop");
  CHECK(eval_diagnostic("return 1").message == "'return' outside a macro");
  CHECK(eval_diagnostic("let v = <1, 2>").message == "vectors have 3 components, this one has 2");
  CHECK(eval_diagnostic("for i in 0 .. 1 step 0 { }").message == "a range step must not be zero");
  CHECK(eval_diagnostic("let g = group { }\nlet h = g with { }").message == "cannot derive a group with 'with'");
  CHECK(eval_diagnostic("let g = group { } translate <1, 0, 0>\nlet h = g with { }").message ==
        "cannot derive a group with 'with'");
  CHECK(eval_diagnostic("let n = 1 with { }").message == "'with' derives from a material, a texture, a shape or a light, got a number");
  CHECK(eval_diagnostic("let s = sphere { radius = 1 }\nlet t = s with { radius = -1 }").message ==
        "property 'radius' of sphere must be > 0, got -1");
  CHECK(eval_diagnostic("sphere { radius = 1  sphere { radius = 2 } }").message.find("objects can only be placed") ==
        0);
}

TEST_CASE("values cannot nest without bound", "[errors][limits]") {
  CHECK_THAT(eval_error("let l = []\nfor i in 0 .. 20000 { l = [l] }"), Catch::Contains("nested more than 10000 deep"));
  CHECK_THAT(eval_error("let m = material { }\nfor i in 0 .. 20000 { m = m with { color = [m] } }"),
             Catch::Contains("nested more than 10000 deep"));
  CHECK(eval_diagnostic("let r = random(1e300)").message ==
        "argument 1 of 'random' must be a whole number from 0 to 2^53, got a number");
}

TEST_CASE("limits stop runaway scenes", "[errors][limits]") {
  EvalOptions opts;
  opts.limits.max_iterations = 1000;
  CHECK_THAT(eval_error("while true { }", opts), Catch::Contains("more than 1000 iterations"));
  CHECK_THAT(eval_error("for i in 0 .. 600 { }  for i in 0 .. 600 { }", opts),
             Catch::Contains("more than 1000 iterations"));  // the limit is for all loops together
  EvalOptions objs;
  objs.limits.max_objects = 10;
  CHECK_THAT(eval_error("let s = sphere { radius = 1 }\nfor i in 0 .. 11 { s }", objs),
             Catch::Contains("more than 10 objects placed"));
}

TEST_CASE("a name declared twice in a scope of many names is still found", "[errors]") {
  // Past 32 names a scope's duplicate check uses an index (10 MB of `let`s were quadratic);
  // it must find the first definition, forget a popped scope and see names bound by loops.
  std::string lets;
  for (int i = 0; i < 100; ++i) lets += "let v" + std::to_string(i) + " = " + std::to_string(i) + "\n";
  Diagnostic d = eval_diagnostic(lets + "let v7 = 1\n");
  CHECK(d.message.find("'v7' is already defined") == 0);
  CHECK(d.loc.line() == 101);
  REQUIRE(d.notes.size() == 1);
  CHECK(d.notes[0].loc.line() == 8);
  // Each iteration's body is a new scope with the same start: the same 40 names again are fine.
  std::string body;
  for (int i = 0; i < 40; ++i) body += " let w" + std::to_string(i) + " = i\n";
  CHECK_NOTHROW(rts::test::eval_text(lets + "for i in 0 .. 3 {\n" + body + "}\n"));
  // ... and a duplicate inside such a body is found in every iteration's scope.
  Diagnostic in_loop = eval_diagnostic(lets + "for i in 0 .. 3 {\n" + body + " let w3 = 0\n}\n");
  CHECK(in_loop.message.find("'w3' is already defined") == 0);
  CHECK(in_loop.notes.at(0).loc.line() == 105);
  // A global defined after a big loop scope was popped is checked against the globals.
  Diagnostic after = eval_diagnostic(lets + "for i in 0 .. 2 {\n" + body + "}\nlet v99 = 0\n");
  CHECK(after.message.find("'v99' is already defined") == 0);
  CHECK(after.notes.at(0).loc.line() == 100);
}
