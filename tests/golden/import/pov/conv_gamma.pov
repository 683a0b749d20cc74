// No #version, no assumed_gamma: POV-Ray writes the image without gamma encoding.
camera { location <0, 0, -3> look_at 0 angle 60 }
light_source { <2, 3, -4> color rgb 1 }
sphere { 0, 1 pigment { color rgb <0.5, 0.6, 0.7> } }
plane { y, -1 pigment { color rgb 0.4 } }
