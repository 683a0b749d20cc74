// The POV-Ray twin of lathe_spline.rts (Declare=Lit=1: the diffuse-lit pass).
#ifndef (Lit) #declare Lit = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb 0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 50 right x*320/240 }
light_source { <-3, 6, -4> color rgb Lit }
#declare Flat = finish { ambient 1 - Lit diffuse 0.8 * Lit }
lathe {
  cubic_spline 10, <0.2, -0.8>, <0, -0.7>, <0.7, -0.65>, <0.9, 0>, <0.5, 0.5>, <0.7, 1.0>, <0.6, 1.05>, <0.4, 0.6>,
  <0, 0.3>, <-0.2, 0.3>
  pigment { color rgb <1, 0, 0> } finish { Flat } rotate <-50, 0, 0> translate <-1.7, -0.2, 0>
}
lathe {
  quadratic_spline 6, <0.6, 0.6>, <0.3, 0>, <0.6, -0.5>, <0.9, 0>, <0.6, 0.6>, <0.3, 0>
  pigment { color rgb <0, 1, 0> } finish { Flat } rotate <-60, 0, 20> translate <0, 0, 0.5>
}
difference {
  lathe {
    bezier_spline 8, <0, -0.8>, <0.9, -0.8>, <1.0, 0.2>, <0.6, 0.4>, <0.6, 0.4>, <0.2, 0.6>, <0.6, 1.1>, <0, 1.2>
    pigment { color rgb <0, 0, 1> } finish { Flat }
  }
  box { <-1, 0.2, -1>, <0, 1.5, 0> pigment { color rgb <1, 1, 0> } finish { Flat } }
  rotate <0, 30, 0> translate <1.7, -0.2, 0>
}
