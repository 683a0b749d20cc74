// POV-Ray's geometric patterns: radial, spiral1 and spiral2 (with arms), boxed, cylindrical,
// planar and spherical.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.6, 0> }
light_source { <-4, 10, -6> color rgb 1 }
#declare M = color_map { [0 rgb <0.9, 0.8, 0.6>] [0.5 rgb <0.7, 0.3, 0.1>] [1 rgb <0.1, 0.1, 0.2>] }
sphere { <-3, 1, 2>, 1 pigment { radial frequency 6 color_map { M } } }
sphere { <0, 1, 2>, 1 pigment { spiral1 3 color_map { M } scale 0.5 } }
sphere { <3, 1, 2>, 1 pigment { spiral2 5 color_map { M } scale 0.6 rotate x * 90 } }
box { <-4, 0, -2>, <-2, 1.5, 0> pigment { boxed color_map { M } translate <-3, 0.75, -1> } }
sphere { <-0.8, 1, -1>, 1 pigment { cylindrical color_map { M } scale 1.2 translate <-0.8, 0, -1> } }
sphere { <1.4, 1, -1>, 1 pigment { planar color_map { M } translate y } }
sphere { <3.6, 1, -1>, 1 pigment { spherical color_map { M } scale 1.1 translate <3.6, 1, -1> } }
plane { y, 0 pigment { rgb 0.5 } }
