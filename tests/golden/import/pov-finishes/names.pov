// POV-Ray's finish and interior names from finish.inc, metals.inc and glass.inc, imported as
// rts's library finishes (tests/import/pov_import.sh). written.pov is the same scene with rts's
// values for the names written out.
#version 3.7;
#include "colors.inc"
#include "finish.inc"
#include "metals.inc"
#include "glass.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -6> look_at <0, 0.6, 0> }
light_source { <-6, 8, -8> color White }
plane { y, 0 pigment { checker White, Gray40 } finish { Phong_Dull } }
sphere { <-2.4, 0.6, 0>, 0.6 pigment { Red } finish { Shiny } }
sphere { <-1.2, 0.6, 0.8>, 0.6 texture { pigment { color Green } finish { Phong_Glossy } } }
sphere { <0, 0.6, 0>, 0.6 pigment { Blue } finish { Dull } }
sphere { <1.2, 0.6, 0.8>, 0.6 pigment { color rgb <0.9, 0.7, 0.3> } finish { F_MetalC } }
sphere { <2.4, 0.6, 0>, 0.6 pigment { color rgbf <1, 1, 1, 0.95> } finish { F_Glass4 } interior { I_Glass } }
sphere { <0, 2.2, 1.5>, 0.4 pigment { Yellow } finish { Luminous } }
sphere { <1.6, 2, 2>, 0.5 pigment { White } finish { Mirror } }
