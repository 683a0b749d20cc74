// Race scene "glossy" (bench/race.sh): the same picture as glossy.rts. POV-Ray 3.7 has no
// blurred reflection of its own; the usual way is micro-normals (`normal { bumps A scale
// 0.0002 }`, far below a pixel) with every pixel supersampled (+AM1 +A0.0 +R2 -J, set by
// bench/race.sh as for "soft"): each of a pixel's 2x2 rays meets a differently tilted normal,
// so the pixel averages 4 reflected directions, as rts's 4 samples do. (The micro-normals
// also tilt the diffuse and highlight terms, which rts's roughness does not.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.1, 0.12, 0.18> }
camera { perspective location <0, 3, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 6, -3> rgb 0.4 }
plane { y, 0
  pigment { checker rgb 0.8, rgb 0.2 }
  normal { bumps 0.15 scale 0.0002 }
  finish { ambient 0.1 diffuse 0.6 reflection 0.3 } }
#declare Gold = texture { pigment { rgb <0.8, 0.6, 0.3> } normal { bumps 0.1 scale 0.0002 }
  finish { ambient 0.1 diffuse 0.3 phong 0.6 phong_size 60 reflection 0.6 } }
#declare Steel = texture { pigment { rgb <0.3, 0.35, 0.4> } normal { bumps 0.2 scale 0.0002 }
  finish { ambient 0.1 diffuse 0.4 phong 0.4 phong_size 40 reflection 0.5 } }
#for (I, 0, 4)
  sphere { <I * 1.8 - 3.6, 0.8, 0>, 0.8 texture { Gold } }
  box { <I * 1.8 - 4.0, 0, 2.5>, <I * 1.8 - 3.2, 1.2, 3.3> texture { Steel } }
#end
