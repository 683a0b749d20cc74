// #for (R, 0, !1): a range end that is a logical not (rts reads `not` below `..`), found by fuzz_pov.
#declare G = array[1][3];
#for (R, 0, !1)
  #for (C, 0, 2)
    #declare G[R][C] = <C, 0, R>;
  #end
#end
