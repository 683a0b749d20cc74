// The POV-Ray twin of height_field.rts (Declare=Lit=1: the diffuse-lit pass). POV-Ray
// samples a height-field function at <x, 1 - z, 0>: the rts macro's p.z is 1 - y here.
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
height_field { png "assets/terrain.png" smooth water_level 0.3 pigment { color rgb <1, 0, 0> } finish { Flat }
  scale <1.8, 0.9, 1.8> rotate <0, 20, 0> translate <-2.9, -0.6, -0.2> }
height_field { function 48, 48 { 0.5 + 0.3 * sin(6 * x) * cos(5 * (1 - y)) } pigment { color rgb <0, 1, 0> } finish { Flat }
  scale <1.6, 0.8, 1.6> translate <-0.8, -1.2, -1.6> }
intersection {
  height_field { function 32, 32 { 0.5 + 0.3 * sin(6 * x) * cos(5 * (1 - y)) } pigment { color rgb <0, 0, 1> } finish { Flat } scale <2, 1.2, 2> }
  box { <0.2, -0.5, 0.2>, <1.8, 0.75, 1.8> pigment { color rgb <1, 1, 0> } finish { Flat } }
  rotate <0, -30, 0> translate <1.1, -0.8, -0.6>
}
