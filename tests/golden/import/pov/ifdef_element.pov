// #ifdef(A[i]): whether an array element has been given a value (portfolio/html_gen.inc).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> }
light_source { <-4, 6, -5> color rgb 1 }
#declare A = array[3];
#declare A[1] = 0.7;
#declare I = 0;
#while (I < 3)
  #ifdef (A[I])
    sphere { <(I - 1) * 1.6, 0.6, 0>, 0.6 pigment { rgb <A[I], 0.2, 0.2> } }
  #else
    sphere { <(I - 1) * 1.6, 0.6, 0>, 0.6 pigment { rgb <0.2, 0.2, 0.8> } }
  #end
  #declare I = I + 1;
#end
plane { y, 0 pigment { rgb 0.6 } }
