// A macro that #declares its parameter changes the caller's variable (POV-Ray passes a
// variable by reference): Turn_Me(Thing, ...) turns Thing itself.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <3, 3, -10> look_at <0, 0, 0> angle 35 }
light_source { <1000, 1000, -1000> color rgb 1 }
plane { y, -2 pigment { rgb 0.8 } }
#macro Turn_Me(Stuff, Degrees, Axis)
  #declare Stuff = object { Stuff rotate Axis * Degrees }
#end
#declare Thing = cone { 0, 1/2, y, 0 }
object { Thing pigment { rgb <1, 0, 0> } translate -2.25 * x }
Turn_Me(Thing, -90, x)
object { Thing pigment { rgb <0, 1, 1> } }
Turn_Me(Thing, -90, y)
object { Thing pigment { rgb <1, 1, 0> } translate 2.25 * x }
