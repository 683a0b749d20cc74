// POV-Ray's interior fade: light crossing the inside keeps fade_color + (1 - fade_color) /
// (1 + (d / fade_distance)^fade_power), or exp(-(1 - fade_color) d / fade_distance) with a
// power of 1000 and more; POV-Ray's shadow rays skip a fade of power 0 (the right sphere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> }
light_source { <2, 12, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.2> rgb <0.2, 0.6, 0.2> } }
#declare Clear = texture { pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 phong 0.5 phong_size 100 } }
sphere { <-3, 1, 0>, 1 texture { Clear } interior { ior 1.2 fade_distance 1 fade_power 1 } }
sphere { <-1, 1, 0>, 1 texture { Clear } interior { ior 1.2 fade_distance 0.8 fade_power 2 fade_color rgb <0.8, 0.3, 0.1> } }
box { <0.2, 0.05, -0.8>, <1.8, 1.6, 0.8> texture { Clear } interior { ior 1 fade_distance 1 fade_power 1001 fade_colour rgb <0.2, 0.5, 0.9> } }
sphere { <3, 1, 0>, 1 texture { Clear } interior { fade_distance 2 } }
