// A camera moved by its own transforms after look_at: rotate, then translate (literal values
// are applied to the camera's position and vectors).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 60 rotate <0, 30, 0> translate <1, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.8, 0.8, 0.7> rgb <0.4, 0.4, 0.5> } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } }
box { <1.5, 0, -0.5>, <2.5, 1, 0.5> pigment { rgb <0.3, 0.5, 0.9> } }
