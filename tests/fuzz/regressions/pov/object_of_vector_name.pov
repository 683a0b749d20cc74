// fuzz_pov (a long run, seed 11): object { z A } named a vector; the translation wrote the
// vector where an object goes, which rts cannot parse. Now a located import error.
#declare A = sphere { 0, 1 }
union { object { A } object {z A } }
