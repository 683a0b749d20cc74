// A light of intensity 1e300.
#include "common.inc"
camera { location <0, 2, -4> look_at <0, 0, 0> angle 60 right x * 4 / 3 }
light_source { <2, 4, -3> color rgb 1e300 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgbf <0.8, 0.8, 0.8, 0.5> } finish { reflection { 0 0.3 fresnel on } specular 0.5 } interior { ior 1.5 } }
