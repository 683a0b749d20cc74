// Nested dielectrics with absolute indices (POV-Ray tracks the containing interior too):
// water in glass, diamond in water, under a white sky.
#include "common.inc"
background { rgb 1 }
camera { location <0, 1, -4> look_at <0, 0.3, 0> angle 60 right x * 4 / 3 }
plane { y, -1 pigment { rgb 0.6 } }
#declare Clear = material { texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0 1 fresnel on } conserve_energy } } }
sphere { <-0.8, 0.3, 0>, 0.7 material { Clear interior { ior 1.5 } } }
sphere { <-0.8, 0.3, 0>, 0.4 material { Clear interior { ior 1.33 } } }
sphere { <0.8, 0.3, 0>, 0.7 material { Clear interior { ior 1.33 } } }
sphere { <0.8, 0.3, 0>, 0.3 material { Clear interior { ior 2.42 } } }
