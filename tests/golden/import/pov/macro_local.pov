// #local in loops belongs to the macro or file (POV-Ray's #while opens no scope: the loops end),
// and a macro's untextured objects take the texture of the union the call is in.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 55 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
#macro Ring(Stuff, N)
  #local Count = 0;
  #while (Count < N)
    object { Stuff rotate y * Count * 360 / N }
    #local Count = Count + 1;
  #end
#end
#declare Arm = cylinder { 0, x, 0.08 }
union { Ring(Arm, 6) pigment { rgb <1, 0.3, 0.2> } translate <-1.3, 0.3, 0> }
union { Ring(Arm, 4) pigment { rgb <0.2, 0.4, 1> } translate <1.3, 0.3, 0> }
#local Row = 0;
#while (Row < 2)
  #local Col = 0;
  #while (Col < 3)
    sphere { <Col - 1, 0.2, 1.5 + Row>, 0.2 pigment { rgb <0.3, 0.9, 0.4> } }
    #local Col = Col + 1;
  #end
  #local Row = Row + 1;
#end
