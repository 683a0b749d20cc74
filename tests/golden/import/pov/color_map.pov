// A gradient with a colour map of several stops keeps them all (rts's gradient pattern), and
// the old entry form [a b color A color B] runs A at a to B at b. Gradients are exact arithmetic,
// so rts's render of the translation must match POV-Ray's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 angle 50 }
light_source { <0, 0, -20> color rgb 1 }
box { <-2, 0.1, -0.1>, <2, 1.5, 0.1>
  pigment { gradient x color_map { [0.0 color rgb <1, 0, 0>] [0.3 color rgb <1, 1, 0>] [0.6 color rgb <0, 0.6, 0>] [1.0 color rgb <0, 0, 1>] } scale 4 translate -2*x }
  finish { ambient 0.2 diffuse 0.8 }
}
box { <-2, -1.5, -0.1>, <2, -0.1, 0.1>
  pigment { gradient x color_map { [0.0 0.5 color rgb <1, 0, 0> color rgb <0, 0, 1>] [0.5 1.0 color rgb <0, 0, 1> color rgb <0, 1, 0>] } scale 4 translate -2*x }
  finish { ambient 0.2 diffuse 0.8 }
}
