// POV-Ray 3.7 twin of examples/convergence/soft_shadows.rts for the equal-time comparison in
// docs/convergence.md (bench/convergence/povray.sh). AREA_N x AREA_N jittered light samples.
#version 3.7;
#ifndef (AREA_N) #declare AREA_N = 2; #end
// ADAPTIVE=1: POV-Ray's adaptive area light (corners first, subdivide where they differ).
#ifndef (ADAPTIVE) #declare ADAPTIVE = 0; #end
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
background { rgb 0 }
camera { perspective location <0, 2, -6> look_at <0, 0.6, 0> right x*128/96 angle 50 }
light_source { <-1.5, 5, -1.5> rgb 1
  area_light <3, 0, 0>, <0, 0, 3>, AREA_N, AREA_N jitter
  #if (ADAPTIVE) adaptive 0 #end }
plane { y, 0 pigment { rgb 0.75 } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 1.2, 0>, 0.6 pigment { rgb <0.85, 0.2, 0.15> } finish { ambient 0.1 diffuse 0.7 } }
