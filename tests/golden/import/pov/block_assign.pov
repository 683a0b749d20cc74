// A #local redeclared directly in a union's body (thingy.inc's RoundedBox): rts reads
// `name = value` there as the block's property, so the assignment is written inside
// `if true { ... }`; and `vector + number` promotes the number (POV-Ray's rule, rts's too).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb <0.7, 0.75, 0.8> } }
#macro Corners(P, Q, R)
  union {
    #local A = P * <1, 1, 1>;
    #local B = Q;
    box { A + R, B - R }
    #local A = A + R;
    #local B = B - R;
    sphere { A, R }
    sphere { B, R }
    sphere { <A.x, B.y, A.z>, R }
    pigment { rgb <0.9, 0.5, 0.3> }
  }
#end
object { Corners(<-2, 0, -0.5>, <0, 1.2, 0.5>, 0.25) }
object { Corners(<0.5, 0, -0.5>, <2.2, 1.6, 0.5>, 0.3) translate <0, 0, 0.5> }
