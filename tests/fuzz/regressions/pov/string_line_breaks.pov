// A carriage return inside a string, and a backslash before a line break: POV-Ray reads both
// inside one string; rts strings hold neither raw (fuzz_pov, 2026-11-25).
#declare S = "0 pigm y,";
#declare T = "a\
b";
#declare U = "end\\";
sphere { 0, 1 pigment { rgb 1 } }
