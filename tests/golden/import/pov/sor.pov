// Surfaces of revolution: a closed vase (with POV-Ray's sturm, ignored), an open one, and a
// sor cut by a box in a difference.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.6, 0> }
light_source { <3, 5, -4> color rgb 1 }
sor {
  6, <0.3, -0.2>, <0.35, 0>, <0.7, 0.5>, <0.25, 1.1>, <0.3, 1.4>, <0.45, 1.6>
  sturm
  pigment { color rgb <0.9, 0.3, 0.2> }
  translate <-1.2, 0, 0>
}
sor {
  5, <0, -0.3>, <0.6, 0>, <0.3, 0.5>, <0.5, 0.9>, <0.7, 1.2>
  open
  pigment { color rgb <0.2, 0.4, 0.9> }
  translate <0.2, 0, 0.5>
}
difference {
  sor { 4, <0, -1>, <0.5, 0>, <0.5, 1>, <0, 2> pigment { color rgb <0.3, 0.8, 0.3> } }
  box { <0, 0.5, -1>, <1, 2, 0> pigment { color rgb <0.9, 0.8, 0.2> } }
  translate <1.4, 0, -0.3>
}
plane { y, 0 pigment { color rgb 1 } }
