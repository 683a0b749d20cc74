// A declared sky_sphere used by name, turned where it is used: its layers (one a pigment_map)
// are written once as an rts sky value. With skies.inc, `sky_sphere { S_Cloud1 }` names rts's
// S_Cloud1 the same way.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at <0, 1, 0> angle 70 }
light_source { <-5, 5, -5> color rgb 1 }
#declare Banded = sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.6, 0.4>] [0.4 rgb <0.2, 0.3, 0.8>] [1 rgb <0.05, 0.1, 0.4>] } }
  pigment { gradient y
    pigment_map { [0.1 rgbt 1] [0.2 onion color_map { [0 rgbt <1, 1, 1, 0>] [0.5 rgbt <1, 1, 1, 1>] [1 rgbt <1, 1, 1, 0>] } scale 0.05] [0.3 rgbt 1] }
  }
}
sky_sphere { Banded rotate <0, 0, 10> }
sphere { <0, 1, 0>, 0.6 pigment { rgb <0.8, 0.8, 0.7> } finish { reflection 0.5 } }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.3 } }
