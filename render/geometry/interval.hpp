// A closed range of ray parameters [min, max] (Ray Tracing in One Weekend's Interval): every
// intersection routine takes one instead of loose tmin/tmax arguments.
#pragma once

#include <algorithm>
#include <limits>

namespace rts::render {

struct Interval {
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  double min = kInfinity;   // default: the empty interval
  double max = -kInfinity;

  constexpr Interval() = default;
  constexpr Interval(double lo, double hi) : min(lo), max(hi) {}

  constexpr double size() const { return max - min; }
  constexpr bool empty() const { return !(min <= max); }
  constexpr bool contains(double x) const { return min <= x && x <= max; }
  constexpr bool surrounds(double x) const { return min < x && x < max; }
  constexpr double clamp(double x) const { return x < min ? min : (x > max ? max : x); }
  // The largest interval inside both (empty when they do not overlap).
  constexpr Interval intersect(const Interval& o) const {
    return Interval(std::max(min, o.min), std::min(max, o.max));
  }

  static constexpr Interval universe() { return Interval(-kInfinity, kInfinity); }
  static constexpr Interval positive() { return Interval(0.0, kInfinity); }
};

}  // namespace rts::render
