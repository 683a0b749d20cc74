// shapes.inc's solids by name: the unit cube and disc, an infinite cylinder and double cone
// cut by other shapes, a paraboloid cut by a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
camera { location <0, 2, -5> look_at <0, 0.4, 0> }
light_source { <3, 5, -4> color rgb 1 }
intersection { object { Cube } object { Cylinder_X scale 1.2 } pigment { color rgb <0.9, 0.5, 0.2> }
  scale 0.6 rotate y*30 translate <-1.5, 0.6, 0> }
object { Disk_Y scale <0.5, 0.2, 0.5> translate <-0.2, 0.2, -0.5> pigment { color rgb <0.2, 0.6, 0.9> } }
intersection { object { Cone_Y } object { UnitBox } pigment { color rgb <0.3, 0.8, 0.3> }
  scale 0.5 translate <0.6, 0.5, 0.6> }
intersection { object { Paraboloid_Y } object { UnitBox translate y } pigment { color rgb <0.8, 0.8, 0.2> }
  scale 0.5 translate <1.8, 0, 0> }
plane { y, 0 pigment { color rgb 1 } }
