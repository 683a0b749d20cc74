// looks_like: the light's object is placed at the light's location, then moved by the light's
// transforms, and casts no shadow (POV-Ray gives it no_shadow). Before: a warning, no object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 1, 0> }
light_source { <0, 2.5, 1> color rgb 1
  looks_like { sphere { 0, 0.3 pigment { rgb <1, 1, 0.6> } finish { ambient 1 diffuse 0 } } }
  translate <0.5, 0, 0> }
light_source { <-6, 6, -6> color rgb 0.3 }
sphere { <-1, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
plane { y, 0 pigment { rgb 0.8 } }
