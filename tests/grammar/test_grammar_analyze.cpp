// PEGTL's static grammar analysis: no rule can loop without consuming input (left
// recursion, star<> over something that may succeed empty).
#include <catch2/catch.hpp>
#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/grammar.hpp"

TEST_CASE("the grammar has no analysis issues", "[analyze]") {
  REQUIRE(tao::pegtl::analyze<rts::grammar::program>(0) == 0);
}

TEST_CASE("the expression levels analyse cleanly on their own", "[analyze]") {
  REQUIRE(tao::pegtl::analyze<rts::grammar::expression<true>>(0) == 0);
  REQUIRE(tao::pegtl::analyze<rts::grammar::expression<false>>(0) == 0);
}
