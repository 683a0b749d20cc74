// #default's finish under each texture's own: a texture's finish starts from the default and
// changes only what it names (the left ball takes the default, the middle one its own
// ambient 1 diffuse 0, the right one its own diffuse with the default's ambient).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#default { finish { ambient 0.3 diffuse 0.4 } }
camera { location <0, 1, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, 0 pigment { rgb <0.6, 0.7, 0.6> } }
sphere { <-1.7, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.4, 0.3> } }
sphere { <0, 0.7, 0>, 0.7 texture { pigment { checker rgb 0.2 rgb 0.9 scale 0.3 } finish { ambient 1 diffuse 0 } } }
sphere { <1.7, 0.7, 0>, 0.7 pigment { rgb <0.3, 0.4, 0.9> } finish { diffuse 0.9 } }
