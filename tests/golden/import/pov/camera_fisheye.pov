// POV-Ray's fisheye camera (fisheye angle 150): rts's projection of that name, POV-Ray's angle as fov.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { fisheye angle 150 location <0, 1.5, -4> look_at <0, 0.8, 0> }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-1.5, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <0.5, 0, -0.5>, <1.7, 1.2, 0.7> pigment { rgb <0.2, 0.5, 0.8> } }
cylinder { <0, 0, 2>, <0, 2.5, 2>, 0.3 pigment { rgb <0.3, 0.8, 0.3> } }
