// The POV-Ray twin of torus.rts.
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0, 0> angle 50 right x*320/240 }
#declare Flat = finish { ambient 1 diffuse 0 }
torus { 1, 0.4 pigment { color rgb <1, 0, 0> } finish { Flat } rotate <-30, 20, 0> translate <-1.4, 0, 0> }
torus { 1, 0.05 pigment { color rgb <0, 1, 0> } finish { Flat } rotate <70, 0, 0> translate <0, 0, 1> }
difference {
  torus { 0.8, 0.3 pigment { color rgb <0, 0, 1> } finish { Flat } }
  box { <0, -1, -2>, <2, 1, 0> pigment { color rgb <0, 1, 0> } finish { Flat } }
  rotate <-40, 0, 0> translate <1.4, 0, 0>
}
