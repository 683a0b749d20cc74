// Two facing perfect mirrors; POV-Ray's max_trace_level stops at 256.
global_settings { assumed_gamma 1.0 max_trace_level 256 }
#default { finish { ambient 0.1 diffuse 0.7 } }
background { rgb <0.2, 0.3, 0.5> }
camera { location <0, 0, 0> look_at <0.05, 0.02, 1> angle 20 right x * 16 / 12 }
light_source { <0, 0.5, 0> color rgb 1 }
box { <-1e4, -1e4, 1>, <1e4, 1e4, 1.1> pigment { rgb 0.1 } finish { reflection 1 } }
box { <-1e4, -1e4, -1.1>, <1e4, 1e4, -1> pigment { rgb 0.1 } finish { reflection 1 } }
