// A camera whose vectors the scene computes (declared values): POV-Ray's look_at turning,
// written as rts (the import's pov_look_at helper) instead of computed by the import. Left-
// handed right, a tilted sky and a zoom from a declared value.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Zoom = 1.6;
#declare CamLoc = <2, 2.5, -4>;
#declare Tilt = 10;
camera {
  location CamLoc
  direction z * Zoom
  right x * 1.5
  up y * 1.1
  sky vrotate(y, <0, 0, Tilt>)
  look_at <0, 0.5, 0>
}
light_source { <-5, 8, -6> color rgb 1 }
box { <-1, 0, -1>, <1, 1, 1> pigment { checker rgb <0.9, 0.2, 0.1> rgb <0.9, 0.9, 0.8> scale 0.5 } }
sphere { <1.6, 0.5, 0>, 0.5 pigment { rgb <0.2, 0.4, 0.9> } }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.3 } }
