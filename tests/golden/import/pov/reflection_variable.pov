// reflection { min, max }: POV-Ray's variable reflection, rts's reflect_min rising to reflect at
// grazing angles by (1 - cos)^falloff, or by Fresnel's factor with fresnel (with what reflects
// taken from what passes, POV-Ray's conserve_energy). 15.1 codes when the import took the maximum.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> }
light_source { <-5, 8, -6> color rgb 1 }
sphere { <-2.1, 1, 0>, 0.9 pigment { rgb <0.8, 0.2, 0.1> } finish { reflection { 0.05, 0.9 } } }
sphere { <0, 1, 0>, 0.9 pigment { rgb <0.1, 0.3, 0.8> } finish { reflection { 0.1, 1 falloff 3 } } }
sphere { <2.1, 1, 0>, 0.9 pigment { rgbf <1, 1, 1, 1> } finish { reflection { 0.2, 1.0 fresnel on } conserve_energy } interior { ior 1.5 } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } finish { reflection { 0, 0.8 } } }
plane { z, 6 pigment { gradient y color_map { [0 rgb <0.9, 0.6, 0.3>] [1 rgb <0.2, 0.4, 0.8>] } scale 4 } }
