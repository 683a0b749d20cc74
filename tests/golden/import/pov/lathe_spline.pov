// Lathes and prisms with POV-Ray's smooth splines and conic_sweep: the spline keyword becomes
// rts's spline property (the same points), conic_sweep its sweep property.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -5> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
lathe {
  cubic_spline 7, <0.2, -0.3>, <0, 0>, <0.8, 0.1>, <0.5, 0.8>, <0.9, 1.4>, <0, 1.2>, <-0.3, 1.2>
  pigment { color rgb <0.9, 0.3, 0.2> }
  translate <-1.4, 0, 0>
}
lathe {
  bezier_spline 8, <0, 0>, <1.2, 0>, <0.2, 0.6>, <0.6, 0.8>, <0.6, 0.8>, <1.0, 1.0>, <0.5, 1.4>, <0, 1.4>
  pigment { color rgb <0.2, 0.4, 0.9> }
}
prism {
  conic_sweep quadratic_spline 0.4, 1, 7,
  <-0.6, 0.6>, <-0.6, -0.6>, <0.6, -0.6>, <0.7, 0.1>, <0.1, 0.7>, <-0.6, 0.6>, <-0.6, -0.6>
  pigment { color rgb <0.3, 0.8, 0.3> }
  rotate <180, 0, 0> translate <1.4, 1.1, 0>
}
plane { y, 0 pigment { color rgb 1 } }
