// A transparent pigment lets its filtered and transmitted light past the surface instead of
// lighting it: POV-Ray scales the finish's ambient and diffuse by 1 - (filter * max(colour) +
// transmit), and the importer writes the scaled values.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> }
light_source { <-3, 6, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-1.1, 0.8, 0>, 0.8 pigment { rgbt <1, 0.6, 0.3, 0.5> } }
sphere { <1.1, 0.8, 0>, 0.8 pigment { rgbf <0.3, 0.6, 1, 0.7> } }
