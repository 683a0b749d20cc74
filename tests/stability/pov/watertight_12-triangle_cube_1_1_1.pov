// Inside a 12-triangle cube, no light inside, magenta background.
#include "common.inc"
background { rgb <1, 0, 1> }
camera { location <0, 0, 0> look_at <1, 1, 1> angle 100 right x }
mesh2 {
  vertex_vectors { 8, <-1,-1,-1>, <1,-1,-1>, <1,1,-1>, <-1,1,-1>, <-1,-1,1>, <1,-1,1>, <1,1,1>, <-1,1,1> }
  face_indices { 12, <0,1,2>, <0,2,3>, <4,6,5>, <4,7,6>, <0,4,5>, <0,5,1>, <3,2,6>, <3,6,7>, <0,3,7>, <0,7,4>, <1,5,6>, <1,6,2> }
  pigment { rgb 0.6 }
}
