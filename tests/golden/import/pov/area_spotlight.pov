// A spotlight with an area_light: rts's area_light with the spot's point_at, radius and
// falloff (the cone's factor from the light's centre, as POV-Ray attenuates it), casting a
// soft shadow inside the cone. Before, the area was dropped (a hard-edged spot_light).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> }
light_source { <0, 5, 0> color rgb 1.2 spotlight point_at <1, 0, 1> radius 20 falloff 35
  area_light x * 1.5, z * 1.5, 5, 5 }
light_source { <-6, 6, -6> color rgb 0.2 }
sphere { <0.6, 0.7, 0.6>, 0.7 pigment { rgb <0.9, 0.4, 0.3> } }
plane { y, 0 pigment { rgb 0.8 } }
