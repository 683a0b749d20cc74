// A blob whose components loops place (#while and #for), beside one written out.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.6 } }
blob {
  threshold 0.6
  sphere { <0, 1.6, 0>, 0.8, 1 }
  #declare I = 0;
  #while (I < 6)
    sphere { <1.2 * cos(radians(I * 60)), 0.8, 1.2 * sin(radians(I * 60))>, 0.7, 1 }
    #declare I = I + 1;
  #end
  #for (J, 0, 1)
    cylinder { <-2 + 4 * J, 0.3, -1>, <-2 + 4 * J, 0.3, 1>, 0.4, 1 }
  #end
  pigment { rgb <0.9, 0.5, 0.2> }
  finish { phong 0.5 }
}
