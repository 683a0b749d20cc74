// The POV-Ray twin of blob.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
blob {
  threshold 0.6
  sphere { <-0.5, 0, 0>, 0.8, 1 } sphere { <0.5, 0, 0>, 0.8, 1 } sphere { <0, 0.6, 0>, 0.6, 1 }
  cylinder { <-0.9, -0.3, 0>, <0.9, -0.3, 0>, 0.35, 1 }
  pigment { color rgb <1, 0, 0> } finish { Flat } rotate <0, 20, 0> translate <-1.6, 0, 0>
}
blob { threshold 0.3 sphere { <0, 0, 0>, 1.1, 1 } sphere { <0, 0.3, -0.5>, 0.7, -1.5 } pigment { color rgb <0, 1, 0> } finish { Flat } }
difference {
  blob { threshold 0.5 cylinder { <0, -0.6, 0>, <0, 0.6, 0>, 0.8, 1.5 } sphere { <0.4, 0.4, 0>, 0.6, 1 } pigment { color rgb <0, 0, 1> } finish { Flat } }
  box { <-1, 0.1, -1>, <0, 1, 0> pigment { color rgb <0, 1, 0> } finish { Flat } }
  rotate <-20, 30, 0> translate <1.6, 0, 0>
}
