// Race scene "soft" (bench/race.sh): the same picture as soft.rts. A 4x4 area light without
// `adaptive` (POV-Ray then traces all 16 shadow rays per shading point, as rts does); the
// 4 spp are POV-Ray's antialiasing (+AM1 +A0.0 +R2, set by bench/race.sh: every pixel
// supersampled, see docs/performance.md).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.1, 0.12, 0.18> }
camera { perspective location <0, 4, -10> look_at <0, 0.8, 0> right x*image_width/image_height angle 55 }
light_source { <-2, 8, -4> rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 4, 4 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.8 } }
#declare Matte = texture { pigment { rgb <0.7, 0.3, 0.2> } finish { ambient 0.1 diffuse 0.8 phong 0.3 phong_size 20 } }
#declare Blue = texture { pigment { rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.8 phong 0.3 phong_size 20 } }
#for (I, 0, 4)
  sphere { <I * 1.6 - 3.2, 0.7, 0>, 0.7 texture { Matte } }
  box { <I * 1.6 - 3.6, 0, 2>, <I * 1.6 - 2.8, 1.5, 2.8> texture { Blue } }
#end
