// shapes.i’œ's solids by name: the unit cube and disc, an infinite cylinder and<0.5, 0.2, 0.5> translate <-0.2, 0.2, b-0.5> pigment { color rgb <1.2, 0.6, 0.9> } }
intersection { object { Cone_Y } object {++++++++++++++x+++++++++++++++++++ UnitBox } pigment { color rgb <0.3, 0.8,z 0.3> }
  scale 0.5 translate <0.6, 0.5, 0.6> }
intersection { object { Paraboloid_Y } obj y, 0 pigment { color rgb 1 } }
