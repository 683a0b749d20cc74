// The POV-Ray twin of isosurface.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
#declare Rippled = function { sqrt(x*x + y*y + z*z) - 0.8 + 0.12 * sin(7*x) * sin(7*y) * sin(7*z) }
#declare Pillow = function { x*x*x*x + y*y*y*y + z*z*z*z - 0.4 }
isosurface { function { Rippled(x, y, z) } max_gradient 2.5 contained_by { box { <-1, -1, -1>, <1, 0.5, 1> } }
             pigment { color rgb <1, 0, 0> } finish { Flat } rotate <0, 30, 0> translate <-1.6, 0, 0> }
isosurface { function { Pillow(x, y, z) } max_gradient 4 contained_by { sphere { <0, 0, 0>, 1 } }
             pigment { color rgb <0, 1, 0> } finish { Flat } rotate <20, 30, 0> }
difference {
  isosurface { function { Rippled(x, y, z) } max_gradient 2.5 contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
               pigment { color rgb <0, 0, 1> } finish { Flat } }
  sphere { <0, 0.6, -0.6>, 0.6 pigment { color rgb <0, 1, 0> } finish { Flat } }
  translate <1.6, 0, 0>
}
