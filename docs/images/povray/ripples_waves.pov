// The POV-Ray 3.7 counterpart of ../ripples_waves.rts (render: povray +W600 +H400 +A0.1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x*18 up y*12 }
background { color rgb <0.3, 0.35, 0.45> }
#for (Row, 0, 1)
  #for (Col, 0, 2)
    box { <-3, -3, 0>, <3, 3, 0.1>
      texture {
        #if (Row = 0)
          pigment { ripples color_map { [0 rgb 0] [1 rgb 1] } frequency Col + 1 }
        #else
          pigment { waves color_map { [0 rgb 0] [1 rgb 1] } frequency Col + 1 }
        #end
        finish { ambient 1 diffuse 0 } }
      translate <(Col - 1) * 6, 3 - Row * 6, 0> }
  #end
#end
