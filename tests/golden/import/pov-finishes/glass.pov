// glass.inc's names with POV-Ray's values (rts's glass.rts): textures, finishes, interiors with
// their fade, F_Glass5 (a variable Fresnel reflection) and a Col_Glass_* colour with its filter.
// pov_import.sh: within 1.5 codes of POV-Ray's render (glass.pov.png, 80x60; measured 0.51;
// 0.84 with F_Glass4 before reflect_min, 4.8 with rts's own approximations of the names).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#include "colors.inc"
#include "glass.inc"
camera { location <0, 2, -6> look_at <0, 0.8, 0> }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }
sphere { <-2.1, 1, 0>, 0.9 texture { T_Glass4 } interior { I_Glass } }
sphere { <0, 1, 0>, 0.9 texture { T_Ruby_Glass } interior { I_Glass_Fade_Exp2 } }
sphere { <2.1, 1, 0>, 0.9 pigment { Col_Glass_Bluish } finish { F_Glass5 } interior { I_Glass1 } }
box { <-1.5, 0, 1.5>, <1.5, 2, 1.7> texture { T_Winebottle_Glass } interior { I_Glass } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
plane { z, 6 pigment { gradient y color_map { [0 rgb <0.9, 0.6, 0.3>] [1 rgb <0.2, 0.4, 0.8>] } scale 4 } }
