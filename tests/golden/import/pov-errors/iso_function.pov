#version 3.7;
camera { location <0, 1, -4> look_at 0 }
isosurface { function { pattern { granite } } contained_by { box { -1, 1 } } }
isosurface { function { x*x + y*y + z*z - 0.25 } contained_by { box { -1, 1 } } open }
#include "functions.inc"
isosurface { function { f_sphere(x, y, z, 0.5) } contained_by { box { -1, 1 } } }
#declare H = function { f_torus(x, y, z, 0.5, 0.1) }
isosurface { function { H(x, y, z) } contained_by { box { -1, 1 } } }
