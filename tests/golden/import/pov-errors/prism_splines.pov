#version 3.7;
camera { location <0, 1, -4> look_at 0 }
prism { conic_sweep 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
prism { linear_sweep cubic_spline 0, 1, 6, <0, 1>, <0, 0>, <1, 0>, <0, 1>, <0, 0>, <1, 0> }
prism { linear_sweep 0, 1, 3, <0, 0>, <1, 0>, <0, 1> pigment { color rgb 1 } }
