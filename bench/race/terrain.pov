// Race scene "terrain" (bench/race.sh): the same picture as terrain.rts; the mesh2 include is
// written by bench/race/gen_terrain.py. max_trace_level 1: camera and shadow rays only.
#version 3.7;
#include "terrain.inc"
global_settings { assumed_gamma 1.0 max_trace_level 1 ambient_light rgb 1 adc_bailout 0.0001 }
background { rgb <0.5, 0.6, 0.8> }
camera { perspective location <0, 6, -14> look_at <0, 0, 0> right x*image_width/image_height angle 60 }
light_source { <-10, 20, -10> rgb 1 }
object { Terrain pigment { rgb <0.45, 0.6, 0.3> } finish { ambient 0.1 diffuse 0.9 } }
