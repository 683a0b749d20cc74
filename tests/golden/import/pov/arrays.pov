// Arrays: one of a computed size filled element by element in a #while, and a 2-D one filled
// in nested #for loops (rts's lists are values: each element changes with with_item).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
#declare N = 5;
#declare Heights = array[N];
#declare I = 0;
#while (I < N)
  #declare Heights[I] = 0.2 + 0.15 * I;
  #declare I = I + 1;
#end
#declare Grid = array[2][3];
#for (R, 0, 1)
  #for (C, 0, 2)
    #declare Grid[R][C] = <C - 1, 0, R * 1.5>;
  #end
#end
#for (K, 0, N - 1)
  sphere { <K - 2, Heights[K], -1>, 0.3 pigment { rgb <1, 0.5, 0.2> } }
#end
#for (R, 0, 1)
  #for (C, 0, 2)
    box { Grid[R][C] - <0.2, 0, 0.2>, Grid[R][C] + <0.2, 0.4 + 0.2 * C, 0.2> pigment { rgb <0.2, 0.5, 1> } }
  #end
#end
