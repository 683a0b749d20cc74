// pigment_map: a pattern choosing between whole pigments (patterns with their own transforms,
// plain colours, a declared pigment and pigment_map), blended between entries; the outer
// transform moves them all. The sky's layer picks between a clear and a cloudy pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.6, -4> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 5, -5> color rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.8>] [1 rgb <0.6, 0.8, 1>] } }
  pigment { gradient x
    pigment_map { [0.3 rgbt 1] [0.5 leopard color_map { [0 rgbt <1, 1, 1, 0.2>] [1 rgbt <1, 1, 1, 1>] } scale 0.02] [0.7 rgbt 1] }
    translate <0.5, 0, 0>
  }
}
#declare Stripes = pigment { gradient y color_map { [0 rgb <1, 0, 0>] [0.5 rgb <1, 0, 0>] [0.5 rgb 1] [1 rgb 1] } scale 0.2 }
#declare Map = pigment_map { [0 Stripes] [0.4 Stripes] [0.6 checker rgb <0, 0, 1> rgb <0, 1, 0> scale 0.3] [1 rgb <1, 1, 0>] }
sphere { <-0.9, 0.5, 0>, 0.8 pigment { gradient x pigment_map { Map } scale 2 translate <-1.9, 0, 0> } }
sphere { <0.9, 0.5, 0>, 0.8
  pigment { radial frequency 4
    pigment_map { [0.5 marble color_map { [0 rgb 1] [1 rgb <0.2, 0.1, 0>] } scale 0.3 rotate 30*z] [0.5 rgb <0.1, 0.5, 0.1>] }
  }
}
plane { y, -0.3 pigment { checker pigment { rgb 0.8 } pigment { rgb 0.3 } } }
