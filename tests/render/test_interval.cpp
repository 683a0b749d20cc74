#include <catch2/catch.hpp>

#include "render/geometry/interval.hpp"

using rts::render::Interval;

TEST_CASE("Interval membership: contains is closed, surrounds is open", "[interval]") {
  Interval i(1.0, 3.0);
  CHECK(i.contains(1.0));
  CHECK(i.contains(3.0));
  CHECK_FALSE(i.surrounds(1.0));
  CHECK_FALSE(i.surrounds(3.0));
  CHECK(i.surrounds(2.0));
  CHECK_FALSE(i.contains(3.5));
  CHECK(i.size() == 2.0);
}

TEST_CASE("Interval defaults to empty; universe contains everything finite", "[interval]") {
  Interval e;
  CHECK(e.empty());
  CHECK_FALSE(e.contains(0.0));
  Interval u = Interval::universe();
  CHECK_FALSE(u.empty());
  CHECK(u.contains(-1e300));
  CHECK(u.contains(1e300));
  CHECK(Interval::positive().contains(0.0));
  CHECK_FALSE(Interval::positive().contains(-1e-300));
}

TEST_CASE("Interval clamp and intersect", "[interval]") {
  Interval i(-1.0, 1.0);
  CHECK(i.clamp(5.0) == 1.0);
  CHECK(i.clamp(-5.0) == -1.0);
  CHECK(i.clamp(0.25) == 0.25);
  Interval j = i.intersect(Interval(0.5, 4.0));
  CHECK(j.min == 0.5);
  CHECK(j.max == 1.0);
  CHECK(i.intersect(Interval(2.0, 3.0)).empty());
}
