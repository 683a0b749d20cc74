// docs/images/media.rts for POV-Ray 3.7 (povray +W480 +H240 +A0.1 +Imedia.pov). rts's media
// dim the light that crosses them, so the light here has media_attenuation on (POV-Ray's
// default is off: smoke that casts no shadow). POV-Ray's phase functions are not normalised (its
// isotropic one is 1, not 1 / 4 pi), so the scattering colour here is rts's / 4 pi, with extinction
// 4 pi to dim the light as rts's does.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.8, -6.5> look_at <0, 0.8, 0> angle 55 right x * 2 }
background { rgb <0.05, 0.06, 0.08> }
light_source { <-3, 6, -4> color rgb <1, 0.95, 0.9> media_attenuation on }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.45 } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-2.1, 1, 0.5>, 1 hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
         interior { media { scattering { 1, rgb 0.9 / (4 * pi) extinction 4 * pi } absorption rgb 0.1 samples 16 } } }
sphere { <0.3, 0.8, 0>, 0.8 hollow pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
         interior { ior 1.5 media { absorption rgb <0.15, 0.6, 1.8> } } }
sphere { <2.3, 0.9, 0.6>, 0.9 hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
         interior { media { emission rgb <1.2, 0.5, 0.1> absorption rgb 0.4 } } }
