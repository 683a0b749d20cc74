// Spot lights given by negative angles and by a computed radius of 0 (POV-Ray takes their
// cosines: `falloff -30` is 30; radius 0 leaves the falloff cone alone), under a sky_sphere
// of one plain colour seen directly and in a mirror-like ball, and a box whose computed
// corners come in the wrong order.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 60 }
sky_sphere { pigment { rgb <0.4, 0.55, 0.8> } }
#declare Hot = 0;
#declare Corner = <0.4, 0.4, 0.4>;
light_source { <2, 5, -3> color rgb 1 spotlight point_at <0, 0, 0> radius -15 falloff -30 }
light_source { <-3, 4, -2> color rgb 0.6 spotlight point_at <-1.5, 0, 0> radius Hot falloff 25 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } finish { reflection 0.3 } }
box { Corner + <1.5, 0.4, 0>, -Corner + <1.5, 0.4, 0> pigment { rgb <0.3, 0.8, 0.4> } }
