// A sphere of radius 1e-3 seen from 1e4 with a narrow field of view.
#include "common.inc"
background { rgb <0, 0, 1> }
camera { location <0, 0, -1e4> look_at <0, 0, 0> angle degrees(2 * atan(1.4e-7)) right x }
sphere { <0.11e-3, -0.07e-3, 0>, 1e-3 pigment { rgb 0.8 } }
