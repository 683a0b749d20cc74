// sky_sphere: a gradient of three colours under a layer of stripes that lets the lower layer
// through (rgbt in its color_map), the sky turned by its own rotate; a mirror ball shows it in
// reflection. Every pattern here is exact arithmetic (no noise), so rts's render of the
// translation must match POV-Ray's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 1.3, 0> angle 70 }
light_source { <5, 10, -5> color rgb 1 }
sky_sphere {
  pigment {
    gradient y
    color_map { [0.0 color rgb <0.9, 0.6, 0.3>] [0.3 color rgb <0.3, 0.5, 0.9>] [1.0 color rgb <0.1, 0.15, 0.5>] }
  }
  pigment {
    gradient x
    color_map { [0.0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 0.9, 0.8, 0.3>] [1.0 rgbt <1, 1, 1, 1>] }
    scale 0.5
  }
  rotate <0, 0, 10>
}
sphere { <0, 1, 0>, 1 pigment { rgb 0.9 } finish { reflection 0.8 ambient 0 diffuse 0.2 } }
