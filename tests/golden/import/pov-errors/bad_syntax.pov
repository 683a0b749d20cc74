#declare R = 1;
sphere { <0, 0, 0>, R
  pigment { color rgb <1, 0, 0> }
