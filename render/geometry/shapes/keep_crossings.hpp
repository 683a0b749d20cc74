// The first crossings of a line with a shape whose surfaces are walked in no particular order
// (lathe segments, prism edges): kept sorted in the caller's short array.
#pragma once

namespace rts::render::detail {

// Inserts c into out[0..count) (ascending t) when it is among the smallest `max_out`, dropping
// the largest when full. max_out is small (1 for a hit, a few for CSG), so an insertion beats a
// sort at the end. Crossing needs a `t`.
template <class Crossing>
inline void keep_first_crossings(Crossing* out, int& count, int max_out, const Crossing& c) {
  if (max_out <= 0 || (count == max_out && !(c.t < out[count - 1].t))) return;
  int i = count < max_out ? count++ : count - 1;
  while (i > 0 && out[i - 1].t > c.t) {
    out[i] = out[i - 1];
    --i;
  }
  out[i] = c;
}

}  // namespace rts::render::detail
