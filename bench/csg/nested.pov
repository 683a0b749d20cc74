// The POV-Ray twin of nested.rts.
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 50 right x*320/240 }
#declare Flat = finish { ambient 1 diffuse 0 }
merge {
  intersection {
    sphere { <0, 0, 0>, 1.2 pigment { color rgb <1, 0, 0> } finish { Flat } }
    box { <-1, -1, -1>, <1, 1, 1> pigment { color rgb <0, 1, 0> } finish { Flat } rotate <0, 45, 0> }
    plane { y, 0.5 inverse pigment { color rgb <0, 0, 1> } finish { Flat } }
    translate <-1.2, 0, 0>
  }
  torus { 0.8, 0.3 pigment { color rgb <1, 1, 0> } finish { Flat } rotate <-60, 0, 0> translate <1.2, 0.2, 0> }
}
