// The POV-Ray twin of prism_spline.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
prism {
  linear_sweep cubic_spline -0.2, 0.25, 15,
  <0.3, 1.3>, <1.5, 0.2>, <0.8, -1.1>, <-1.2, -1>, <-1.4, 0.9>, <0.3, 1.3>, <1.5, 0.2>, <0.8, -1.1>,
  <0, -0.4>, <0.4, 0>, <0, 0.4>, <-0.4, 0>, <0, -0.4>, <0.4, 0>, <0, 0.4>
  pigment { color rgb <1, 0, 0> } finish { Flat } scale 0.7 rotate <-65, 10, 0> translate <-1.7, 0.4, 0>
}
prism {
  linear_sweep quadratic_spline 0.5, -0.3, 7,
  <-0.6, 0.6>, <-0.6, -0.6>, <0.6, -0.6>, <0.7, 0.1>, <0.1, 0.7>, <-0.6, 0.6>, <-0.6, -0.6>
  pigment { color rgb <0, 1, 0> } finish { Flat } rotate <-55, 20, 0> translate <0, -0.4, 0.5>
}
difference {
  prism {
    linear_sweep bezier_spline -0.3, 0.4, 16,
    <0, -0.8>, <0.9, -0.8>, <0.6, 0.4>, <0, 0.9>, <0, 0.9>, <-0.6, 0.4>, <-0.9, -0.8>, <0, -0.8>,
    <0, -0.5>, <-0.3, -0.5>, <-0.3, 0>, <0, 0.2>, <0, 0.2>, <0.3, 0>, <0.3, -0.5>, <0, -0.5>
    pigment { color rgb <0, 0, 1> } finish { Flat }
  }
  box { <-1, 0.1, -1>, <0, 1, 0> pigment { color rgb <1, 1, 0> } finish { Flat } }
  rotate <-25, 30, 0> translate <1.7, 0.3, 0>
}
prism {
  linear_sweep bezier_spline 0, 0.6, 12,
  <-0.4, -0.3>, <0, -0.6>, <0.4, -0.3>, <0.4, -0.3>, <0.4, -0.3>, <0.5, 0.2>, <0, 0.4>, <0, 0.4>,
  <0, 0.4>, <-0.5, 0.2>, <-0.4, -0.3>, <-0.4, -0.3>
  open
  pigment { color rgb <0, 1, 1> } finish { Flat } rotate <-30, 20, 0> translate <0, 1.3, -0.5>
}
