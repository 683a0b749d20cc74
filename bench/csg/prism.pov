// The POV-Ray twin of prism.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
prism {
  linear_sweep linear_spline -0.2, 0.25, 17, <0, 1>, <-0.2469, 0.3398>, <-0.9511, 0.309>, <-0.3994, -0.1298>, <-0.5878, -0.809>, <-0, -0.42>, <0.5878, -0.809>, <0.3994, -0.1298>, <0.9511, 0.309>, <0.2469, 0.3398>, <0, 1>, <-0.1176, 0.1618>, <-0.1902, -0.0618>, <-0, -0.2>, <0.1902, -0.0618>, <0.1176, 0.1618>, <-0.1176, 0.1618>
  pigment { color rgb <1, 0, 0> } finish { Flat } rotate <-65, 10, 0> translate <-1.7, 0.4, 0>
}
prism {
  0.5, -0.3, 6, <-0.6, -0.6>, <0.6, -0.6>, <0.6, -0.2>, <-0.2, -0.2>, <-0.2, 0.7>, <-0.6, 0.7>
  pigment { color rgb <0, 1, 0> } finish { Flat } rotate <-55, 20, 0> translate <0, -0.4, 0.5>
}
difference {
  prism { linear_spline -0.3, 0.4, 10, <-0.7, -0.5>, <0.3, -0.5>, <0.3, 0.5>, <-0.7, 0.5>, <-0.7, -0.5>, <-0.3, -0.2>, <0.7, -0.2>, <0.7, 0.8>, <-0.3, 0.8>, <-0.3, -0.2> pigment { color rgb <0, 0, 1> } finish { Flat } }
  box { <-1, 0.1, -1>, <0, 1, 0> pigment { color rgb <1, 1, 0> } finish { Flat } }
  rotate <-25, 30, 0> translate <1.7, 0.3, 0>
}
prism {
  0, 0.6, 4, <-0.4, -0.3>, <0.4, -0.3>, <0, 0.4>, <-0.4, -0.3> open
  pigment { color rgb <0, 1, 1> } finish { Flat } rotate <-30, 20, 0> translate <0, 1.3, -0.5>
}
