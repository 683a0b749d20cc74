// A gradient along a vector that is not an axis (textures.inc's Candy_Cane is gradient x+y):
// along the vector's direction, turned before the pigment's own transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <-4, 6, -5> color rgb 1 }
sphere { <-1.2, 0.8, 0>, 0.8 pigment { gradient x+y color_map { [0.25 rgb <1, 0, 0>] [0.25 rgb 1] [0.75 rgb 1] [0.75 rgb <1, 0, 0>] } scale 0.5 } }
sphere { <1.2, 0.8, 0>, 0.8 pigment { gradient <1, 2, 3> color_map { [0 rgb <0.1, 0.2, 0.9>] [1 rgb <0.9, 0.9, 0.2>] } scale 0.7 rotate y * 20 } }
plane { y, 0 pigment { rgb 0.5 } }
