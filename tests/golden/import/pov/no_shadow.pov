// no_shadow: on a shape (left), on a union (middle, its two parts), on a reused object (right
// back); the front right ball keeps its shadow. rts writes casts_shadow = false.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
sphere { <-2.2, 0.8, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } no_shadow }
union {
  sphere { <-0.4, 0.6, 0>, 0.5 }
  box { <-0.2, 0, -0.2>, <0.2, 1.6, 0.2> }
  pigment { rgb <0.3, 0.8, 0.3> }
  no_shadow
}
#declare Ball = sphere { <0, 0, 0>, 0.6 pigment { rgb <0.3, 0.4, 0.9> } }
object { Ball translate <1.6, 0.6, 1.5> no_shadow }
sphere { <1.4, 0.6, -1.2>, 0.6 pigment { rgb <0.9, 0.8, 0.2> } }
