// POV-Ray's default finish (ambient 0.1, diffuse 0.6) and default black pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -3> look_at 0 angle 60 }
light_source { <2, 3, -4> color rgb 1 }
sphere { <-0.6, 0, 0>, 0.5 pigment { color rgb <0.9, 0.8, 0.7> } }
sphere { <0.6, 0, 0>, 0.5 }
plane { y, -0.5 pigment { color rgb 1 } }
