// Lathes with straight segments: POV-Ray's default spline and linear_spline written out, a
// closed loop in a difference, sturm ignored.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -5> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
lathe {
  7, <0, 0>, <0.7, 0>, <0.5, 0.15>, <1.1, 1.3>, <1, 1.4>, <0.9, 1.25>, <0, 0.35>
  pigment { color rgb <0.9, 0.3, 0.2> }
  scale 0.8 translate <-1.3, 0, 0>
}
difference {
  lathe { linear_spline 5, <0.4, 0>, <0.9, 0>, <0.6, 1.2>, <0.3, 1.2>, <0.4, 0> sturm pigment { color rgb <0.2, 0.4, 0.9> } }
  box { <0, 0.6, -1>, <1, 2, 0> pigment { color rgb <0.9, 0.8, 0.2> } }
  translate <1.2, 0, 0>
}
plane { y, 0 pigment { color rgb 1 } }
