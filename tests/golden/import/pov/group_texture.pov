// A texture on the union a macro makes: POV-Ray gives it to the members that have none of
// their own (the blue sphere keeps its pigment).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> }
light_source { <3, 5, -4> color rgb 1 }
#macro Pair(D)
  union {
    sphere { <-D, 0.5, 0>, 0.5 }
    sphere { <D, 0.5, 0>, 0.5 pigment { color rgb <0.2, 0.4, 0.9> } }
    cylinder { <-D, 0.5, 0>, <D, 0.5, 0>, 0.15 }
  }
#end
object { Pair(1) texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } } }
object { Pair(0.6) translate <0, 1.1, 1> pigment { color rgb <0.3, 0.8, 0.3> } }
plane { y, 0 pigment { color rgb 0.8 } }
