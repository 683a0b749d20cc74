// Hostile input never crashes, hangs or overflows the stack: nesting is limited.
#include <catch2/catch.hpp>

#include <initializer_list>
#include <string>
#include <string_view>

#include "parser_test_support.hpp"

using rts::testing::error_of;
using rts::testing::first_line_of_error;

namespace {
constexpr int kHuge = 100000;

// Appends rather than `"literal" + std::string`, which trips a false -Wrestrict in GCC 12.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out += p;
  return out;
}

std::string repeat(const std::string& s, int n) {
  std::string out;
  out.reserve(s.size() * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out += s;
  return out;
}
}  // namespace

TEST_CASE("100,000 open parentheses or brackets are a nesting error, not a crash", "[limits]") {
  // The 257th bracket's content is where the limit is crossed: column 8 + 257.
  CHECK(first_line_of_error(cat({"let x = ", repeat("(", kHuge)})) ==
        "1:266: error: nesting too deep (more than 256 levels)");
  CHECK(first_line_of_error(cat({"let x = ", repeat("[", kHuge)})) ==
        "1:266: error: nesting too deep (more than 256 levels)");
  CHECK(first_line_of_error(cat({"let x = ", repeat("<", kHuge)})) ==
        "1:266: error: nesting too deep (more than 256 levels)");
  CHECK(first_line_of_error(cat({"f", repeat("(f", kHuge)})).find("nesting too deep") != std::string::npos);
  CHECK(first_line_of_error(cat({"x", repeat("[x", kHuge)})).find("nesting too deep") != std::string::npos);
}

TEST_CASE("deeply nested blocks and bodies", "[limits]") {
  CHECK(first_line_of_error(repeat("group { ", kHuge)).find("nesting too deep (more than 256 levels)") !=
        std::string::npos);
  CHECK(first_line_of_error(repeat("if a { ", kHuge)).find("nesting too deep") != std::string::npos);
  CHECK(first_line_of_error(repeat("while a { ", kHuge)).find("nesting too deep") != std::string::npos);
  CHECK(first_line_of_error(cat({"let m = a ", repeat("with { p = b ", kHuge)})).find("nesting too deep") !=
        std::string::npos);
}

TEST_CASE("long chains of prefix operators are limited too", "[limits]") {
  CHECK(first_line_of_error(cat({"let x = ", repeat("-", kHuge), "1"})).find("nesting too deep") != std::string::npos);
  CHECK(first_line_of_error(cat({"let x = ", repeat("not ", kHuge), "a"})).find("nesting too deep") != std::string::npos);
  CHECK(first_line_of_error(cat({"let x = 2", repeat("^2", kHuge)})).find("nesting too deep") != std::string::npos);
}

TEST_CASE("exactly the limit is accepted, one more is not", "[limits]") {
  rts::ParseLimits limits;
  int n = static_cast<int>(limits.max_nesting);
  CHECK(error_of(cat({"let x = ", repeat("(", n), "1", repeat(")", n)})) == "");
  CHECK(error_of(cat({"let x = ", repeat("(", n + 1), "1", repeat(")", n + 1)})) != "");
  CHECK(error_of(repeat("group { ", n) + repeat("}", n)) == "");
  CHECK(error_of(repeat("group { ", n + 1) + repeat("}", n + 1)) != "");
}

TEST_CASE("the limit is configurable", "[limits]") {
  rts::ParseLimits limits;
  limits.max_nesting = 3;
  CHECK(error_of("let x = (((1)))", limits) == "");
  CHECK(first_line_of_error("let x = ((((1))))", limits) == "1:13: error: nesting too deep (more than 3 levels)");
}

TEST_CASE("very long flat operator chains are capped by tree height", "[limits]") {
  // A left-deep chain would make every later tree walk recurse 100,000 levels.
  std::string sum = cat({"let x = 1", repeat(" + 1", kHuge)});
  CHECK(first_line_of_error(sum).find("expression nested too deeply") != std::string::npos);
  CHECK(first_line_of_error(cat({"let y = v", repeat(".x", kHuge)})).find("expression nested too deeply") !=
        std::string::npos);
  CHECK(first_line_of_error(cat({"s", repeat(" scale 2", kHuge)})).find("expression nested too deeply") !=
        std::string::npos);
  // A few hundred terms are fine.
  CHECK(error_of(cat({"let x = 1", repeat(" + 1", 500)})) == "");
}

TEST_CASE("many statements in a row are flat, not nested", "[limits]") {
  CHECK(error_of(repeat("sphere { radius = 1 }\n", kHuge)) == "");
  CHECK(error_of(cat({"let xs = [", repeat("1, ", kHuge), "]"})) == "");
}

TEST_CASE("a larger nesting limit raises the tree-height cap with it", "[limits]") {
  // 400 nested groups make a tree about 1200 levels deep, past the default cap of 1024.
  constexpr int kDeep = 400;
  rts::ParseLimits limits;
  limits.max_nesting = kDeep;
  CHECK(error_of(cat({repeat("group { ", kDeep), repeat("}", kDeep)}), limits) == "");
  CHECK(first_line_of_error(cat({repeat("group { ", kDeep + 1), repeat("}", kDeep + 1)}), limits)
            .find("nesting too deep (more than 400 levels)") != std::string::npos);
}
