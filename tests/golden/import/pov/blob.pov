// A blob: sphere components with and without the 'strength' keyword, the old 'component'
// form, a cylinder component, the blob's own texture and transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
blob {
  threshold 0.6
  sphere { <-0.6, 0, 0>, 0.8, 1 }
  sphere { <0.6, 0, 0>, 0.8, strength 1 }
  component 1, 0.6, <0, 0.7, 0>
  cylinder { <-1.1, -0.3, 0>, <1.1, -0.3, 0>, 0.35, 1 }
  pigment { color rgb <0.9, 0.3, 0.2> }
  rotate y*20 translate <0, 0.55, 0>
}
plane { y, 0 pigment { color rgb 1 } }
