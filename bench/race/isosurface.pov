// Race scene "isosurface": the POV-Ray twin of isosurface.rts.
global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light 1 }
background { color rgb <0.55, 0.6, 0.7> }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 55 right x*800/600 }
light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 8, -3> color rgb 0.4 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } finish { ambient 0.1 diffuse 0.7 } }
isosurface {
  function { sqrt(x*x + y*y + z*z) - 0.85 + 0.12 * sin(7*x) * sin(7*y) * sin(7*z) }
  max_gradient 2.5 contained_by { box { <-1, -1, -1>, <1, 0.6, 1> } }
  pigment { color rgb <0.85, 0.2, 0.15> } finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 40 }
  rotate <0, 30, 0> translate <-2.2, 1, 0>
}
isosurface {
  function { sin(6*x) * cos(6*y) + sin(6*y) * cos(6*z) + sin(6*z) * cos(6*x) }
  max_gradient 11 contained_by { sphere { <0, 0, 0>, 1 } }
  pigment { color rgb <0.2, 0.6, 0.3> } finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 40 }
  translate <0, 1, 0.5>
}
isosurface {
  function { sqrt(pow(sqrt(x*x + z*z) - 0.8, 2) + y*y) - 0.3 }
  max_gradient 1.1 contained_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
  pigment { color rgb <0.2, 0.35, 0.85> } finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 40 }
  rotate <-50, 0, 0> translate <2.2, 1, 0>
}
