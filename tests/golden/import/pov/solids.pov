// POV-Ray's function shapes as rts imports them: an image height field (smooth, water level),
// a height field from a function, isosurfaces in a box and in a sphere, and declared functions
// (one of x, y, z, one of named parameters calling it) used inside an isosurface.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.6, 1.6, -1.6> look_at <0.6, 0.2, 0.5> }
light_source { <2, 4, -3> color rgb 1 }
height_field { png "solids_hill.png" smooth water_level 0.1 pigment { color rgb <0.4, 0.7, 0.3> } scale <1, 0.3, 1> }
height_field { function 32, 32 { 0.1 + 0.08 * sin(x * 6) * cos(y * 6) } pigment { color rgb <0.3, 0.4, 0.9> } translate <-1, 0, 0> }
isosurface {
  function { sqrt(x*x + y*y + z*z) - 0.3 + 0.05 * sin(10 * x) }
  contained_by { box { 0.5, -0.5 } }
  max_gradient 2
  pigment { rgb 1 }
  translate <0.5, 0.5, 0.5>
}
#declare F = function { x*x + z*z - 0.1 }
#declare G = function(a, b, c) { sqrt(F(a, b, c) + 0.1) + b }
isosurface {
  function { G(x, y, z) - 0.3 }
  contained_by { sphere { <0, 0, 0>, 0.5 } }
  threshold 0
  accuracy 0.001
  max_gradient 1.5
  pigment { rgb <1, 0.5, 0.2> }
  translate <1.3, 0.5, 0.6>
}
