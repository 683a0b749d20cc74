// A spot light given by negative angles (POV-Ray takes their cosines: `falloff -30` is 30)
// under a sky_sphere of one plain colour, seen directly and in a mirror-like ball.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 60 }
sky_sphere { pigment { rgb <0.4, 0.55, 0.8> } }
light_source { <2, 5, -3> color rgb 1 spotlight point_at <0, 0, 0> radius -15 falloff -30 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } finish { reflection 0.3 } }
