// Macros that give a pigment, used inside texture { }: a pattern (its transform then turns
// it) and a plain colour; and a 2-D vector, which POV-Ray promotes with z = 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
#macro Stripes(S)
  pigment { gradient x color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb <0.2, 0.3, 0.8>] [1 rgb <0.2, 0.3, 0.8>] } scale S }
#end
#macro Plain(C)
  pigment { color C }
#end
#declare Spot = <1.2, -0.5>;
plane { y, 0 texture { Stripes(0.5) rotate <0, 45, 0> } }
sphere { <0, 1, 0>, 1 texture { Plain(rgb <0.9, 0.4, 0.2>) finish { phong 0.5 } } }
sphere { <Spot.x, 0.4, Spot.y>, 0.4 pigment { rgb <0.3, 0.8, 0.3> } }
sphere { Spot + <-2.4, 0.4, 0>, 0.4 pigment { rgb <0.8, 0.8, 0.3> } }
