// Race scene "csg": the POV-Ray twin of csg.rts.
global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light 1 }
background { color rgb <0.55, 0.6, 0.7> }
camera { location <0, 6, -9> look_at <0, 0, 1> angle 60 right x*800/600 }
light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 8, -3> color rgb 0.4 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } finish { ambient 0.1 diffuse 0.7 } }
#declare Ivory = texture { pigment { color rgb <0.9, 0.88, 0.8> } finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 60 } }
#declare Ink = texture { pigment { color rgb <0.1, 0.1, 0.15> } finish { ambient 0.1 diffuse 0.7 } }
#for (I, 0, 5)
  #for (J, 0, 5)
    difference {
      intersection {
        box { <-0.4, -0.4, -0.4>, <0.4, 0.4, 0.4> }
        sphere { 0, 0.55 }
      }
      sphere { <0, 0.45, 0>, 0.12 texture { Ink } }
      sphere { <0, -0.45, 0>, 0.12 texture { Ink } }
      sphere { <0.45, 0.15, 0.15>, 0.1 texture { Ink } }
      sphere { <-0.45, -0.15, 0.15>, 0.1 texture { Ink } }
      sphere { <0.15, 0.15, -0.45>, 0.1 texture { Ink } }
      sphere { <-0.15, -0.15, -0.45>, 0.1 texture { Ink } }
      texture { Ivory }
      rotate <I * 17, J * 23, 0> translate <(I - 2.5) * 1.3, 0.45, (J - 2.5) * 1.3 + 1>
    }
  #end
#end
difference {
  union {
    torus { 1, 0.25 }
    cylinder { <0, -0.25, 0>, <0, 0.25, 0>, 0.5 }
  }
  box { <0, -1, -2>, <2, 1, 0> texture { Ink } }
  texture { pigment { color rgb <0.8, 0.3, 0.2> } finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 40 } }
  rotate <-30, 0, 0> translate <5.2, 1, 3>
}
#for (K, 0, 3)
  intersection {
    sphere { <0, 0, -0.6>, 1 }
    sphere { <0, 0, 0.6>, 1 }
    texture { pigment { color rgb <0.3, 0.5, 0.8> } finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 80 } }
    rotate <0, K * 40, 0> translate <(K - 1.5) * 1.8, 1.2, 6>
  }
#end
