// POV-Ray's quartic and poly: an inline quartic torus, shapesq.inc's Piriform, and a monkey
// saddle cut by a Clear box (the box's faces let light through, as in POV-Ray's
// objects/quartic/monkey.pov). rts writes each as a poly with POV-Ray's coefficients.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "shapes.inc"
#include "shapesq.inc"
camera { location <0, 3, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, -1.2 pigment { rgb <0.7, 0.75, 0.8> } }
// (x^2 + y^2 + z^2 + 1 - 0.16)^2 - 4 (x^2 + z^2): a torus of radii 1 and 0.4.
quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2.32,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.68,  0, 0, 0, 0,  1, 0, -2.32, 0, 0.7056 >
  sturm
  pigment { rgb <0.9, 0.7, 0.2> }
  rotate -30*x
  translate <-2.3, 0, 0>
}
object { Piriform pigment { rgb <0.8, 0.2, 0.3> } scale 1.2 rotate 90*z translate <0, -1, 0> }
intersection {
  object { Monkey_Saddle pigment { Red } }
  box { -1, 1 pigment { Clear } }
  scale 0.8
  rotate <-30, 20, 0>
  translate <2.3, 0.2, 0>
}
