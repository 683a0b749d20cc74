// docs/images/fog_turbulence.rts for POV-Ray 3.7 (povray +W400 +H200 +A0.1): rts's noise is its
// own, so the patches lie elsewhere; their size, contrast and fading with distance should match.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 4> angle 60 right x * 2 }
background { rgb <0.2, 0.35, 0.8> }
fog { fog_type 2 distance 1.5 color rgb <0.8, 0.82, 0.85> fog_offset 0.4 fog_alt 0.3
      turbulence <0.6, 0.6, 0.6> turb_depth 0.6 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.2 } finish { ambient 0.1 diffuse 0.7 } }
#for (i, 0, 7)
  sphere { <mod(i, 2) * 2.4 - 1.2, 0.8, i * 3>, 0.8 pigment { rgb <0.85, 0.25, 0.15> }
           finish { ambient 0.1 diffuse 0.7 specular 0.4 roughness 1 / 40 reflection 0.1 } }
#end
