// The POV-Ray twin of difference.rts.
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <2, 3, -5> look_at <0, 0, 0> angle 50 right x*320/240 }
#declare Flat = finish { ambient 1 diffuse 0 }
difference {
  box { <-1, -1, -1>, <1, 1, 1> pigment { color rgb <1, 0, 0> } finish { Flat } }
  sphere { <0.3, 0.4, -0.5>, 0.9 pigment { color rgb <0, 1, 0> } finish { Flat } }
  cylinder { <-2, -0.3, 0>, <2, -0.3, 0>, 0.4 pigment { color rgb <0, 0, 1> } finish { Flat } }
  rotate <0, 25, 0>
}
