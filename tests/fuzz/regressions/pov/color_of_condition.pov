// The fuzzer (CI of stop 37): `colour` of a condition kept no precedence, so `!colour !0`
// translated to `not not 0 != 0 != 0`, a chained comparison rts refuses.
#for (C, !colour !0, 2)
#end
#declare A = !color (1 = 2);
