// Race scene "glass" (bench/race.sh): the same picture as glass.rts. max_trace_level counts
// the camera ray as level 1, so rts's max_depth 10 is POV-Ray's 11.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 11 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.3, 0.4, 0.6> }
camera { perspective location <0, 3, -9> look_at <0, 1, 0> right x*image_width/image_height angle 60 }
light_source { <-4, 10, -8> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.1 } finish { ambient 0.1 diffuse 0.8 } }
#declare Glass = material { texture { pigment { rgbt <1, 1, 1, 0.85> }
                                      finish { ambient 0 diffuse 0 phong 0.6 phong_size 200 reflection 0.1 } }
                            interior { ior 1.5 } }
#for (K, 0, 4)
  sphere { <K * 2.4 - 4.8, 1.1, 0>, 1.1 material { Glass } }
  sphere { <K * 2.4 - 4.8, 1.1, 0>, 0.75 material { Glass } }
  sphere { <K * 2.4 - 4.8, 1.1, 0>, 0.4 material { Glass } }
#end
