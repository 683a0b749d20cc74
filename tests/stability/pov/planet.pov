// A planet of radius 1e6 seen from 1 unit above its surface, lit by a distant sun.
#include "common.inc"
background { rgb <0, 0, 1> }
camera { location <0, 1e6 + 1, 0> look_at <0, 1e6 + 1 - 0.0015, 1> angle 60 right x * 2 }
light_source { <-0.3, 1, -0.5> * 1e9 color rgb 1 parallel point_at <0, 0, 0> }
sphere { 0, 1e6 pigment { rgb <0.5, 0.6, 0.4> } finish { ambient 0 } }
