// fuzz_pov (CI seed 1, a longer run): #case (a & b) wrote pov_switch == a != 0 and b != 0,
// a chained comparison rts refuses; a case value with operators is now in parentheses.
#declare A = 1;
#declare B = 0;
#switch (1) #case (A & B) sphere { 0, 1 } #range (A - 1, A + 1) sphere { 0, 2 } #end
