// reflection { metallic }: the reflection tinted by the pigment, less at grazing angles.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb 0.9] [1 rgb <0.3, 0.5, 0.9>] } } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.6, 0.2> } finish { ambient 0.05 diffuse 0.2 reflection { 0.8 metallic } } }
sphere { <1.2, 1, 0>, 1 pigment { rgb <0.3, 0.8, 0.4> } finish { ambient 0.05 diffuse 0.2 reflection { 0.7 metallic 0.6 } } }
