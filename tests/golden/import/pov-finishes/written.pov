// names.pov with rts's values for its finish and interior names written out (finish.inc's and glass.inc's are POV-Ray's).
#version 3.7;
#include "colors.inc"
#include "finish.inc"
#include "metals.inc"
#include "glass.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -6> look_at <0, 0.6, 0> }
light_source { <-6, 8, -8> color White }
plane { y, 0 pigment { checker White, Gray40 } finish { phong 0.5 phong_size 1 } }
sphere { <-2.4, 0.6, 0>, 0.6 pigment { Red } finish { specular 1 roughness 0.001 } }
sphere { <-1.2, 0.6, 0.8>, 0.6 texture { pigment { color Green } finish { phong 1 phong_size 300 reflection 0.13 } } }
sphere { <0, 0.6, 0>, 0.6 pigment { Blue } finish { specular 0.5 roughness 0.15 } }
sphere { <1.2, 0.6, 0.8>, 0.6 pigment { color rgb <0.9, 0.7, 0.3> } finish { ambient 0.25 brilliance 4 diffuse 0.5 metallic specular 0.8 roughness 0.0125 reflection 0.5 } }
sphere { <2.4, 0.6, 0>, 0.6 pigment { color rgbf <1, 1, 1, 0.95> } finish { ambient 0.1 diffuse 0.1 specular 1 roughness 0.001 reflection 0.25 } interior { ior 1.5 } }
sphere { <0, 2.2, 1.5>, 0.4 pigment { Yellow } finish { ambient 1 diffuse 0 } }
sphere { <1.6, 2, 2>, 0.5 pigment { White } finish { ambient 0 diffuse 0 reflection 1 } }
