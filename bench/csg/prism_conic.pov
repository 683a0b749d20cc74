// The POV-Ray twin of prism_conic.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
prism {
  conic_sweep linear_spline 0.4, 1, 11,
  <0, 1>, <-0.2469, 0.3398>, <-0.9511, 0.309>, <-0.3994, -0.1298>, <-0.5878, -0.809>, <-0, -0.42>,
  <0.5878, -0.809>, <0.3994, -0.1298>, <0.9511, 0.309>, <0.2469, 0.3398>, <0, 1>
  pigment { color rgb <1, 0, 0> } finish { Flat } translate <0, -0.7, 0> rotate <-40, 10, 0> translate <-1.7, 0.4, 0>
}
prism {
  conic_sweep cubic_spline 0, 1, 8,
  <0.3, 1.0>, <0.9, 0.2>, <0.6, -0.8>, <-0.9, -0.7>, <-0.8, 0.7>, <0.3, 1.0>, <0.9, 0.2>, <0.6, -0.8>
  pigment { color rgb <0, 1, 0> } finish { Flat } translate <0, -0.5, 0> rotate <-160, 20, 0> translate <0, 0.3, 0.5>
}
difference {
  prism {
    conic_sweep quadratic_spline 0.3, 1.2, 7,
    <-0.6, 0.6>, <-0.6, -0.6>, <0.6, -0.6>, <0.7, 0.1>, <0.1, 0.7>, <-0.6, 0.6>, <-0.6, -0.6>
    pigment { color rgb <0, 0, 1> } finish { Flat }
  }
  box { <-1, 0.8, -1>, <0, 2, 0> pigment { color rgb <1, 1, 0> } finish { Flat } }
  translate <0, -0.7, 0> rotate <-25, 30, 0> translate <1.7, 0.3, 0>
}
