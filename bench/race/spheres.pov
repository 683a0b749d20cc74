// Race scene "spheres" (bench/race.sh): the same picture as spheres.rts. POV-Ray's camera is
// left-handed like rts's; `angle` is the horizontal field of view. adc_bailout matches rts's
// path-weight cut-off (1e-4) instead of POV-Ray's default 1/255, so both trace the same rays.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.1, 0.12, 0.18> }
camera { perspective location <0, 5, -13> look_at <0, 0.3, 0> right x*image_width/image_height angle 60 }

light_source { <-5, 10, -6> rgb 1 }
light_source { <6, 8, -3> rgb 0.4 }

plane { y, 0
  pigment { checker rgb 0.8, rgb 0.2 }
  finish { ambient 0.1 diffuse 0.8 } }

#declare Mirror = finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 100 reflection 0.8 }
#declare Red = finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0.3 }

#for (I, 0, 19)
  #for (J, 0, 19)
    #if (mod(I + J, 2) = 1)
      sphere { <(I - 9.5) * 0.5, 0.2, (J - 9.5) * 0.5>, 0.2 pigment { rgb 0.1 } finish { Mirror } }
    #else
      sphere { <(I - 9.5) * 0.5, 0.2, (J - 9.5) * 0.5>, 0.2 pigment { rgb <0.8, 0.2, 0.1> } finish { Red } }
    #end
  #end
#end

sphere { <0, 1.6, -2>, 1.2
  pigment { rgbt <1, 1, 1, 0.9> }
  finish { ambient 0 diffuse 0 phong 0.8 phong_size 200 }
  interior { ior 1.5 } }
