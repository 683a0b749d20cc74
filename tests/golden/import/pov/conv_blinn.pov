// specular + roughness is a half-vector (Blinn) highlight, not phong.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -3> look_at 0 angle 50 }
light_source { <-3, 3, -4> color rgb 1 }
sphere { <-0.55, 0, 0>, 0.5 pigment { color rgb <0.2, 0.3, 0.8> } finish { specular 0.8 roughness 0.05 } }
sphere { <0.55, 0, 0>, 0.5 pigment { color rgb <0.8, 0.3, 0.2> } finish { specular 1 roughness 0.005 } }
