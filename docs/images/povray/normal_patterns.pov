// The POV-Ray 3.7 counterpart of ../normal_patterns.rts (render: povray +W600 +H150 +A0.1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -13> look_at <0, 0, 0> angle 50 right x*600/150 }
light_source { <-6, 8, -10> color rgb 1 }
background { color rgb <0.3, 0.35, 0.45> }
#declare F = finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 1/40 }
#declare P = pigment { rgb <0.8, 0.55, 0.35> }
sphere { <-4.8, 0, 0>, 1 texture { pigment { P } normal { bumps 0.5 scale 0.2 } finish { F } } }
sphere { <-2.4, 0, 0>, 1 texture { pigment { P } normal { dents 1 scale 0.3 } finish { F } } }
sphere { <0, 0, 0>, 1 texture { pigment { P } normal { ripples 0.5 frequency 4 } finish { F } } }
sphere { <2.4, 0, 0>, 1 texture { pigment { P } normal { waves 0.5 frequency 4 } finish { F } } }
sphere { <4.8, 0, 0>, 1 texture { pigment { P } normal { wrinkles 0.8 scale 0.3 } finish { F } } }
