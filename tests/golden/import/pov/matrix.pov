// matrix <12 values>: a sheared box, and a declared transform holding a matrix; the values are
// computed, as scenes write them (matrix <xV.x, xV.y, ...>).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
#declare S = 0.6;
box { <-0.5, 0, -0.5>, <0.5, 1.5, 0.5>
  pigment { rgb <0.9, 0.3, 0.2> }
  matrix <1, 0, 0,  S, 1, 0,  0, 0, 1,  -1.5, 0, 0>
}
#declare V = vnormalize(<1, 0, 1>);
#declare T = transform { matrix <V.x, 0, V.z, 0, 1, 0, -V.z, 0, V.x, 1.5, 0, 0> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb <0.3, 0.5, 0.9> } transform T }
