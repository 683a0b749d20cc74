// The POV-Ray 3.7 counterpart of ../sky_sphere.rts (render: povray +W480 +H270 +A0.1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 1.8, 0> angle 70 right x*480/270 }
light_source { <-4, 8, -6> color rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.85, 0.9, 1.0>] [0.5 rgb <0.25, 0.45, 0.9>] [1 rgb <0.1, 0.2, 0.6>] } }
  pigment { bozo turbulence 0.6
            color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 1>] [0.7 rgbt <1, 1, 1, 0.2>] [1 rgbt <0.8, 0.8, 0.8, 0>] }
            scale <0.2, 0.05, 0.2> }
  rotate <0, 20, 0>
}
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } finish { ambient 0.1 diffuse 0.6 } }
sphere { <0, 1, 0>, 1 pigment { rgb 0.1 } finish { ambient 0 diffuse 0.1 reflection 0.9 } }
