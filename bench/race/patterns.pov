// Race scene "patterns" (bench/race.sh): the same picture as patterns.rts. Pattern parameters
// carry over one to one (docs/from-povray.md#patterns); rts's bump_scale 0.08 at scale 0.15 is
// POV-Ray's bumps 0.5 (docs/textures.md#normal-patterns).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.55, 0.6, 0.7> }
camera { perspective location <0, 3, -7> look_at <0, 0.5, 0> right x*image_width/image_height angle 60 }

light_source { <-5, 10, -6> rgb 1 }
light_source { <6, 8, -3> rgb 0.4 }

#declare Oak = color_map { [0 rgb <0.62, 0.4, 0.2>] [0.6 rgb <0.5, 0.3, 0.14>] [1 rgb <0.3, 0.16, 0.07>] }
#for (I, 0, 23)
  #local X = I * 0.5 - 6;
  box { <X + 0.01, -0.1, -6>, <X + 0.49, 0, 12>
        pigment { wood turbulence 0.04 color_map { Oak } scale <0.08, 0.08, 1>
                  translate <X + 0.25 + mod(I, 5) * 0.7 - 1.4, mod(I, 3) - 2, 0> }
        finish { ambient 0.1 diffuse 0.7 phong 0.2 phong_size 40 reflection 0.1 } }
#end
#declare Veins = pigment { marble turbulence 1.2 scale 0.4
  color_map { [0 rgb <0.95, 0.93, 0.9>] [0.7 rgb <0.85, 0.82, 0.8>] [0.9 rgb <0.45, 0.42, 0.45>] [1 rgb <0.15, 0.12, 0.15>] } }
#declare Stone = pigment { granite color_map { [0 rgb <0.85, 0.8, 0.78>] [0.4 rgb <0.55, 0.45, 0.45>] [1 rgb 0.1] } }
#declare Agate = pigment { agate scale 0.3 color_map { [0 rgb <0.9, 0.6, 0.3>] [0.5 rgb <0.6, 0.25, 0.1>] [1 rgb <0.95, 0.85, 0.7>] } }
#for (I, 0, 2)
  #for (J, 0, 2)
    sphere { <(I - 1) * 1.6, 0.5, J * 1.6>, 0.5
      #switch (mod(I + J, 3))
        #case (0) pigment { Veins } #break
        #case (1) pigment { Stone } #break
        #else pigment { Agate }
      #end
      finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 100 } }
  #end
#end
sphere { <2.6, 0.5, -1.5>, 0.5 pigment { rgb <0.8, 0.55, 0.35> } normal { bumps 0.5 scale 0.15 }
         finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 } }
