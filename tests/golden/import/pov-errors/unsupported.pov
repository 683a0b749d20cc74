#version 3.7;
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
lathe { linear_spline 3, <0, 0>, <1, 1>, <0, 2> }
sphere { 0, 1 pigment { color rgb 1 } }
