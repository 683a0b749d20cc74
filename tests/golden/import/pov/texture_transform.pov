// A declared texture moved where it is used (texture { T scale ... }), alone, derived with a
// finish, and as a layer of a layered texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
#declare Stripes = texture { pigment { gradient x color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <0.9, 0.2, 0.1>] [0.5 rgb 0.9] [1 rgb 0.9] } } }
#declare Dots = texture { pigment { gradient z color_map { [0 rgbt <0.1, 0.2, 0.8, 0>] [0.3 rgbt <0.1, 0.2, 0.8, 0>] [0.3 rgbt 1] [1 rgbt 1] } } }
sphere { <-1.5, 1, 0>, 1 texture { Stripes scale 0.4 rotate z * 30 } }
sphere { <1.5, 1, 0>, 1 texture { Stripes scale 0.25 finish { phong 0.8 } } }
plane { y, 0 texture { Stripes scale 2 } texture { Dots scale 0.5 rotate y * 45 } }
