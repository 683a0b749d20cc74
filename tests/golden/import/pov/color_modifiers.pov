// A colour with its transmit or filter set after it (`color Black transmit 0.6`), in a colour
// map of a layer and on a plain pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
camera { location <0, 3, -6> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0
  texture { pigment { color rgb <0.8, 0.7, 0.5> } }
  texture { pigment { gradient x color_map { [0.0, 0.3 color Black transmit 0.6 color Black transmit 1.0]
                                             [0.3, 1.0 color Scarlet transmit 0.8 color DimGray transmit 0.9] } } }
}
sphere { <0, 1, 0>, 1 pigment { color Red transmit 0.5 } }
