// text: two lines in a font (kerning: AVAWAY), an offset after each character, and letters cut
// out of a box (a difference); rts's text block, the glyphs as prisms. The font is Debian's
// fonts-dejavu-core (scripts/ensure-deps installs it), named by its full path.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.5, 1.2, -4> look_at <1.5, 0.4, 0> angle 50 }
light_source { <2, 5, -5> color rgb 1 }
plane { y, -0.01 pigment { rgb <0.8, 0.8, 0.7> } }
#declare Font = "/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf";
text { ttf Font "Hello, POV" 0.3, 0 pigment { rgb <0.9, 0.3, 0.2> } scale 0.8 }
text { ttf "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" "AVAWAY" 0.1, <0.05, 0, 0>
  pigment { rgb <0.3, 0.5, 0.9> } translate <0.3, 1, 0.5> }
difference {
  box { <0, -0.3, 1>, <3, 0.6, 1.2> }
  text { ttf Font "rts" 0.5, 0 scale 0.8 translate <0.5, -0.2, 0.9> }
  pigment { rgb <0.9, 0.8, 0.3> }
  translate <0, 0, 0.5>
}
