// Layered textures: a declared one (a base, stripes whose colour map lets the base show
// between them, a clear varnish with a highlight and a reflection) and one written on the
// object, whose coat is a plain colour half transmitted.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
#declare Layered =
  texture { pigment { color rgb <0.6, 0.4, 0.2> } }
  texture { pigment { gradient x color_map { [0 color rgbt <0.1, 0.1, 0.8, 1>] [0.5 color rgbt <0.1, 0.1, 0.8, 0.7>] [0.5 color rgb <0.1, 0.1, 0.8>] [1 color rgb <0.1, 0.1, 0.8>] } scale 0.3 } }
  texture { pigment { rgbt 1 } finish { specular 0.8 roughness 0.005 reflection 0.15 } }
sphere { <-1.1, 0.8, 0>, 0.8 texture { Layered } }
sphere { <1.1, 0.8, 0>, 0.8
  texture { pigment { color rgb <0.2, 0.6, 0.2> } finish { phong 0.5 } }
  texture { pigment { color rgbt <0.9, 0.1, 0.1, 0.5> } }
}
plane { y, 0 pigment { rgb 0.6 } }
