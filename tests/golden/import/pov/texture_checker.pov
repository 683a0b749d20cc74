// A checker of two textures (one declared, one written in place, with a reflection) moved by
// the texture's transforms; a texture_map on a gradient whose entries switch sharply at 0.5.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0, 0> }
light_source { <3, 6, -4> color rgb 1 }
#declare T1 = texture { pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.8 } }
plane { y, 0 texture { checker texture { T1 } texture { pigment { rgb <0.2, 0.3, 0.9> } finish { reflection 0.3 } } scale 0.7 translate <0.1, 0, 0.1> } }
sphere { <0, 1, 0>, 1 texture { gradient y texture_map { [0.0 T1] [0.5 T1] [0.5 pigment { rgb 1 }] [1.0 pigment { rgb 1 }] } scale 2 translate -y } }
