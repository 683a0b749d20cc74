// A fog whose colour filters and transmits: what it lets through is tinted by its colour and
// never falls below its transmit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 10> }
light_source { <-10, 20, -10> color rgb 1 }
fog { distance 12 color rgbft <0.6, 0.3, 0.2, 0.8, 0.15> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 scale 2 } }
sphere { <-2, 1, 6>, 1 pigment { rgb <0.2, 0.6, 0.9> } }
sphere { <2, 1, 20>, 1 pigment { rgb <0.9, 0.9, 0.2> } }
