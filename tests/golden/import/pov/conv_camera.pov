// POV-Ray's default camera: without a camera block it stands at the origin looking along +z,
// right <1.33, 0, 0> and up y (rts's own default camera is elsewhere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
light_source { <-3, 4, -2> color rgb 1 }
sphere { <-0.8, 0, 3>, 0.6 pigment { color rgb <0.9, 0.3, 0.2> } }
box { <0.2, -0.6, 2.5>, <1.3, 0.5, 3.6> rotate y*20 pigment { color rgb <0.2, 0.5, 0.9> } }
plane { y, -0.6 pigment { color rgb 1 } }
