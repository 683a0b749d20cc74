// assumed_gamma 1.8 (neither 1.0's sRGB nor the legacy scene's none): POV-Ray renders in a
// space of gamma 1.8 and writes each value v as sRGB of v^1.8.
#version 3.7;
global_settings { assumed_gamma 1.8 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <-4, 6, -5> color rgb 1 }
sphere { <-1.2, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <1.2, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.5, 0.8> } }
plane { y, 0 pigment { gradient x color_map { [0 rgb 0.1] [1 rgb 0.9] } scale 3 } }
