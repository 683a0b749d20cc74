// Race scene "grid90k" (bench/race.sh): the same picture as grid90k.rts.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.1, 0.12, 0.18> }
camera { perspective location <0, 60, -170> look_at <0, 0, 0> right x*image_width/image_height angle 60 }
light_source { <-100, 200, -150> rgb 1 }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0.1 diffuse 0.8 } }
#declare Ivory = texture { pigment { rgb <0.9, 0.85, 0.7> } finish { ambient 0.1 diffuse 0.8 phong 0.4 phong_size 30 } }
#for (I, 0, 299)
  #for (J, 0, 299)
    sphere { <I - 149.5, 0.4, J - 149.5>, 0.4 texture { Ivory } }
  #end
#end
