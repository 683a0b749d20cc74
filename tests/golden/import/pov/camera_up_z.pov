// POV-Ray's prism samples write `up z` beside `right x*image_width/image_height` and look_at:
// up along the default direction makes the vectors' handedness zero, which POV-Ray's look_at
// takes as mirrored. An L of boxes shows which way the picture is turned.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-10, 10, -10> right x*image_width/image_height up z look_at <0, 0, 0> angle 20 }
light_source { <-30, 20, -50> rgb 1 }
plane { y, -1 pigment { rgb 0.3 } }
box { <-1, 0, -1>, <1, 0.5, -0.5> pigment { rgb <1, 0.2, 0.1> } }
box { <-1, 0, -0.5>, <-0.5, 0.5, 1.5> pigment { rgb <0.1, 0.4, 1> } }
