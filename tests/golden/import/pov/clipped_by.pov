// clipped_by: a bowl (a sphere clipped by a box, its inside seen through the cut), half a
// torus (clipped by a plane, moved after the clip), a square of a plane (clipped by a box),
// a declared clipped ball reused with a transform, and a clip by an inverse plane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
sphere { <0, 0, 0>, 0.9
  pigment { rgb <0.9, 0.3, 0.2> }
  clipped_by { box { <-1, -1, -1>, <1, 0.3, 1> } }
  translate <-2, 0.9, 0>
}
torus { 0.7, 0.2
  translate 0.5 * x
  clipped_by { plane { x, 0.4 } }
  rotate 90 * x
  translate <0.2, 1, 0.5>
  pigment { rgb <0.3, 0.8, 0.3> }
}
plane { z, 0 hollow
  clipped_by { box { <-0.6, 0, -1>, <0.6, 1.2, 1> } }
  pigment { rgb <0.3, 0.4, 0.9> }
  translate <2, 0, 1.5>
}
#declare Cup = sphere { 0, 0.6 clipped_by { plane { y, 0.2 } } }
object { Cup pigment { rgb <0.9, 0.8, 0.2> } translate <1.8, 0.6, -1.2> }
sphere { <-0.6, 0.5, -1.6>, 0.5
  pigment { rgb <0.7, 0.3, 0.8> }
  clipped_by { plane { y, 0.3 inverse } }
}
// A quadric (an infinite cone, POV-Ray's QCone_Y) clipped between two planes: rts's poly of
// order 2 in a clip.
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0
  clipped_by { plane { y, 0 } plane { y, -0.6 inverse } }
  pigment { rgb <0.9, 0.6, 0.8> }
  scale <0.5, 1, 0.5>
  translate <-1.0, 0.6, 2.2>
}
