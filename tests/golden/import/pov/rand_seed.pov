// seed(n) and rand: POV-Ray's own sequence (rts's random(n, "povray")), so spheres placed by
// it land where POV-Ray puts them; two streams interleaved, one from a negative seed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
#declare R = seed(1234);
#declare C = seed(-77);
#declare I = 0;
#while (I < 40)
  sphere { <rand(R) * 8 - 4, rand(R) * 0.5, rand(R) * 8 - 4>, 0.2 + 0.3 * rand(R)
    pigment { rgb <rand(C), rand(C), rand(C)> } }
  #declare I = I + 1;
#end
plane { y, 0 pigment { rgb 0.7 } }
