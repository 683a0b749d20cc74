// The POV-Ray twin of mesh.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
#include "assets/meshes.inc"
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0.2, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
difference {
  object { Ico pigment { color rgb <1, 0, 0> } finish { Flat } }
  box { <-0.2, 0.1, -1.5>, <1.5, 1.5, 0.2> pigment { color rgb <0, 1, 0> } finish { Flat } }
  cylinder { <-2, -0.3, 0>, <2, -0.3, 0>, 0.35 pigment { color rgb <0, 0, 1> } finish { Flat } }
  scale 1.1 rotate <0, 65, 0> translate <-1.3, 0, 0>
}
intersection {
  difference {
    object { TorusMesh pigment { color rgb <1, 1, 0> } finish { Flat } }
    box { <-1.5, -1, -1.5>, <0, 1, 0> pigment { color rgb <0, 1, 0> } finish { Flat } }
  }
  sphere { <0.3, 0, 0>, 1.05 pigment { color rgb <0, 0, 1> } finish { Flat } }
  rotate <-50, 0, 0> translate <1.3, 0.3, 0>
}
