#declare A = <1 2 3>;
#while (A.x < 3) sphere { A, 1 } #declare A = A + x; #end
/* nested /* comment */ still */
box { <1,1,1> <0,0,0> }
