// image_map: POV-Ray's planar map (the image spans x and y from 0 to 1, repeating, projected
// along z), its nearest texel without interpolate; a file named without its extension.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.53, 0.47, -2.3> look_at <0.53, 0.47, 0> }
light_source { <0, 0, -10> color rgb 1 }
plane { z, 0 pigment { image_map { png "image_map_tex.png" } } finish { ambient 1 diffuse 0 } }
box { <0.9, -0.4, -1>, <1.6, 0.3, -0.5> pigment { image_map { "image_map_tex" } scale 0.35 } finish { ambient 0.6 diffuse 0.4 } }
