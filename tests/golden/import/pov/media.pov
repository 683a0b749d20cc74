// Media (docs/rendering.md#media): smoke scattering a light (with POV-Ray's `extinction 4 * pi`
// its medium is rts's exactly; the light's media_attenuation on is rts's only behaviour),
// amber glass absorbing inside, a glowing ball, and clear containers whose transparent pigment
// takes the finish's ambient and diffuse away.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.8, -6.5> look_at <0, 0.8, 0> angle 60 }
background { rgb <0.05, 0.06, 0.08> }
light_source { <-3, 6, -4> color rgb <1, 0.95, 0.9> media_attenuation on }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.45 } }
sphere { <-2.1, 1, 0.5>, 1 hollow pigment { rgbt 1 }
         interior { media { scattering { 1, rgb 0.08 extinction 4 * pi } absorption rgb 0.1 } } }
sphere { <0.3, 0.8, 0>, 0.8 hollow pigment { rgbt 1 } finish { reflection { 0, 1 fresnel on } conserve_energy }
         interior { ior 1.5 media { absorption rgb <0.15, 0.6, 1.8> } } }
sphere { <2.3, 0.9, 0.6>, 0.9 hollow pigment { rgbt 1 }
         interior { media { emission rgb <1.2, 0.5, 0.1> absorption 0.4 } } }
