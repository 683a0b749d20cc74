// A colour ambient (golds.inc's finishes have one) weighs each channel of the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <-4, 6, -5> color rgb 0.6 }
#declare A = <0.5, 0.2, 0.05>;
sphere { <-1.2, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.8, 0.5> } finish { ambient rgb <0.6, 0.3, 0.1> diffuse 0.4 } }
sphere { <1.2, 0.8, 0>, 0.8 pigment { rgb <0.8, 0.8, 0.8> } finish { ambient A diffuse 0.3 } }
plane { y, 0 pigment { rgb 0.5 } }
