// Prisms: POV-Ray's defaults (linear_sweep, linear_spline) written out and left out, a star
// with a pentagonal hole (two sub-polygons, even-odd), heights in either order, an outline left
// unclosed and open, sturm ignored, a prism minus a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> }
light_source { <3, 5, -4> color rgb 1 }
prism {
  linear_sweep linear_spline 0, 0.35, 17, <0, 0.9>, <-0.223, 0.307>, <-0.856, 0.278>, <-0.361, -0.117>, <-0.529, -0.728>, <-0, -0.38>, <0.529, -0.728>, <0.361, -0.117>, <0.856, 0.278>, <0.223, 0.307>, <0, 0.9>, <-0.118, 0.162>, <-0.19, -0.062>, <-0, -0.2>, <0.19, -0.062>, <0.118, 0.162>, <-0.118, 0.162>
  pigment { color rgb <0.9, 0.3, 0.2> }
  rotate <-40, 0, 0> translate <-1.4, 0.7, 0>
}
difference {
  prism { 0.9, 0, 5, <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5> sturm pigment { color rgb <0.2, 0.4, 0.9> } }
  box { <0, 0.5, -1>, <1, 2, 0> pigment { color rgb <0.9, 0.8, 0.2> } }
  rotate <0, 30, 0> translate <1.3, 0, 0>
}
prism {
  linear_spline -0.1, 0.5, 3, <-0.4, 0>, <0.4, 0>, <0, 0.6> open
  pigment { color rgb <0.3, 0.8, 0.4> }
  translate <0, 0.2, 1>
}
plane { y, 0 pigment { color rgb 1 } }
