// #local at an include file's top level belongs to that file (POV-Ray's symbol table per
// include): the include's Thing is a blue box, the scene's a red sphere before and after it.
// rts's include shares the scene's names, so the include's locals get the file's aliases
// (Thing_include_local); the include, named like the scene, translates to include_local_inc.rts.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -9> look_at 0 angle 35 }
light_source { <100, 1000, -1000> color rgb 1 }
background { rgb 0.4 }
#declare Thing = sphere { 0, 1 pigment { rgb <1, 0, 0> } }
object { Thing translate -2.5 * x }
#include "include_local.inc"
object { Thing translate 2.5 * x }
#ifdef (Local_Item)
  sphere { <0, 2, 0>, 0.3 pigment { rgb 1 } }
#end
