// fuzz_pov: a one-component vector <0.1> was written to rts as it is, which rts cannot read;
// it is a located error, as in POV-Ray.
sphere { <0.1>, 1 }
