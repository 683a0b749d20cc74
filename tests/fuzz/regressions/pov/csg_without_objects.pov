// fuzz_pov (a long run, seed 11): a CSG block holding only values placed nothing and was
// written as an empty rts merge, which rts refuses; now an empty group and a warning.
merge { y, 0 pigment { color rgb 1 } }
union { merge { 1 } }
