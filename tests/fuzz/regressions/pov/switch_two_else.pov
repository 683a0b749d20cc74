// fuzz_pov (seed 13): a #switch with two #else clauses wrote two else branches, which rts
// cannot parse; a clause after the #else is never reached and is left out with a warning.
#declare S = sphere { 0, 1 }
#switch (1) #case (1) object { S } #break #else object { S } #break #else #end
