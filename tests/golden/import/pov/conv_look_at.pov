// POV-Ray's look_at turns its right, up and direction vectors towards the point, keeping their
// lengths: here a right/up ratio of 1.6 on a 4:3 image (POV-Ray stretches the picture).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 2, -4> right x*1.6 up y look_at <0, 0.3, 0> }
light_source { <3, 5, -4> color rgb 1 }
sphere { <-0.6, 0.5, 0>, 0.5 pigment { color rgb <0.9, 0.3, 0.2> } }
cylinder { <0.6, 0, 0>, <0.6, 1, 0>, 0.4 pigment { color rgb <0.2, 0.5, 0.9> } }
plane { y, 0 pigment { color rgb 1 } }
