// rts import test scene: directives, objects, textures and a user include.
#version 3.7;
#include "colors.inc"
#include "parts.inc"

global_settings { assumed_gamma 1.0 max_trace_level 5 }
background { color rgb <0.1, 0.12, 0.2> }

camera {
  location <0, 2.5, -6>
  look_at <0, 0.6, 0>
  angle 55
}

light_source { <5, 8, -5> color White }
light_source { <-6, 4, -2> color rgb 0.4 shadowless }

/* The floor: a checker of two greys */
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.3 } finish { reflection 0.1 } }

#declare Count = 4;
#declare I = 0;
#while (I < Count)
  // one ball per step, redder to the right
  object { Ball(0.4) translate <I * 1.2 - 1.8, 0.4, 0> pigment { color rgb <1, I / Count, 0.2> } finish { Shiny } }
  #declare I = I + 1;
#end

#for (J, 0, 2)
  #switch (J)
    #case (0)
      cylinder { <0, 0, 0>, <0, 1, 0>, 0.25 translate <J - 1, 0, 2> pigment { Blue } }
    #break
    #case (1)
      cone { <0, 0, 0>, 0.35, <0, 1, 0>, 0 translate <J - 1, 0, 2> pigment { Yellow } }
    #break
    #else
      torus { 0.3, 0.1 translate <J - 1, 0.1, 2> pigment { Magenta } }
  #end
#end

// Corners in the "wrong" order: POV-Ray takes them as they come.
box { <2.8, 1, 1.5>, <2, 0, 0.7> pigment { Orange } finish { specular 0.6 roughness 0.02 } }

difference {
  sphere { <0, 0, 0>, 0.6 }
  box { -0.4, 0.4 }
  translate <-2.6, 0.6, 1.5>
  pigment { Cyan }
}

#ifdef (Shiny)
  smooth_triangle { <-1, 0.01, -1.5>, y, <1, 0.01, -1.5>, y, <0, 0.01, -2.5>, <0, 1, -0.2> pigment { Green } }
#end
