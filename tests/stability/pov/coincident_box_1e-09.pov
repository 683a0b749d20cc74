// A box 1e-9 above a plane.
#include "common.inc"
background { rgb <0.3, 0.4, 0.6> }
camera { location <1.5, 2.5, -4> look_at <0, 0, 0> angle 60 right x * 4 / 3 }
light_source { <2, 5, -3> color rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
box { <-1, 1e-9, -1>, <1, 1 + 1e-9, 1> pigment { rgb <0.8, 0.3, 0.2> } }
