// The POV-Ray 3.7 counterpart of ../marble_wood.rts (render: povray +W480 +H300 +A0.1).
// rts's camera is left-handed like POV-Ray's, so coordinates carry over unchanged.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6> look_at <0, 0.6, 0> angle 50 right x*480/300 }
light_source { <-4, 7, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.35 }
background { color rgb <0.55, 0.6, 0.7> }
#declare Oak = color_map { [0 rgb <0.62, 0.4, 0.2>] [0.6 rgb <0.5, 0.3, 0.14>] [1 rgb <0.3, 0.16, 0.07>] }
#declare R = seed(3);
#for (I, 0, 8)
  #local X = I * 0.8 - 3.6;
  box { <X + 0.01, -0.1, -2>, <X + 0.79, 0, 8>
        texture { pigment { wood turbulence 0.04 color_map { Oak } scale <0.12, 0.12, 1>
                            translate <X + 0.4 + 4 * rand(R) - 2, 2 * rand(R) - 3, 0> }
                  finish { ambient 0.1 diffuse 0.7 specular 0.2 roughness 1/40 } } }
#end
sphere { 0, 0.8
  texture { pigment { marble turbulence 1.2 scale 0.7
                      color_map { [0 rgb <0.95, 0.93, 0.9>] [0.7 rgb <0.85, 0.82, 0.8>] [0.9 rgb <0.45, 0.42, 0.45>] [1 rgb <0.15, 0.12, 0.15>] } }
            finish { ambient 0.1 diffuse 0.7 specular 0.6 roughness 1/120 reflection 0.05 } }
  translate <-1.2, 0.8, 0.3> }
sphere { 0, 0.6
  texture { pigment { agate scale 0.5 color_map { [0 rgb <0.9, 0.6, 0.3>] [0.5 rgb <0.6, 0.25, 0.1>] [1 rgb <0.95, 0.85, 0.7>] } }
            finish { ambient 0.1 diffuse 0.7 specular 0.7 roughness 1/200 } }
  translate <0.6, 0.6, -0.6> }
box { <-0.5, 0, -0.5>, <0.5, 1.4, 0.5>
  texture { pigment { granite scale 1.5 color_map { [0 rgb <0.85, 0.8, 0.78>] [0.4 rgb <0.55, 0.45, 0.45>] [1 rgb 0.1] } }
            finish { ambient 0.1 diffuse 0.7 specular 0.3 } }
  rotate <0, 30, 0> translate <2.1, 0, 0.8> }
