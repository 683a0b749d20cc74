// The POV-Ray 3.7 counterpart of ../patterns.rts (render: povray +W640 +H420 +A0.1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -13> look_at <0, 0, 0> angle 50 right x*640/420 }
light_source { <-6, 8, -10> color rgb 1 }
background { color rgb <0.3, 0.35, 0.45> }
#declare CM = color_map { [0 rgb <0.95, 0.9, 0.8>] [0.5 rgb <0.6, 0.3, 0.2>] [1 rgb <0.1, 0.05, 0.05>] }
sphere { <-4.8, 2.4, 0>, 1 texture { pigment { bozo color_map { CM } scale 0.4 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <-2.4, 2.4, 0>, 1 texture { pigment { granite color_map { CM } } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <0.0, 2.4, 0>, 1 texture { pigment { marble turbulence 0.8 color_map { CM } scale 0.6 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <2.3999999999999995, 2.4, 0>, 1 texture { pigment { wood turbulence 0.05 color_map { CM } scale 0.2 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <4.8, 2.4, 0>, 1 texture { pigment { agate color_map { CM } scale 0.6 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <-4.8, 0.0, 0>, 1 texture { pigment { onion color_map { CM } scale 0.3 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <-2.4, 0.0, 0>, 1 texture { pigment { leopard color_map { CM } scale 0.15 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <0.0, 0.0, 0>, 1 texture { pigment { wrinkles color_map { CM } scale 0.5 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <2.3999999999999995, 0.0, 0>, 1 texture { pigment { crackle color_map { CM } scale 0.4 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <4.8, 0.0, 0>, 1 texture { pigment { cells color_map { CM } scale 0.4 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <-4.8, -2.4, 0>, 1 texture { pigment { spotted color_map { CM } scale 0.3 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <-2.4, -2.4, 0>, 1 texture { pigment { dents color_map { CM } scale 0.3 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <0.0, -2.4, 0>, 1 texture { pigment { ripples color_map { CM } frequency 2 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <2.3999999999999995, -2.4, 0>, 1 texture { pigment { waves color_map { CM } frequency 2 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
sphere { <4.8, -2.4, 0>, 1 texture { pigment { bumps color_map { CM } scale 0.2 } finish { ambient 0.1 diffuse 0.7 specular 0.3 } } }
