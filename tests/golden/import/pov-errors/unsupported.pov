#version 3.7;
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <1, 0, 0>, 0.5 }
sphere { 0, 1 pigment { color rgb 1 } }
