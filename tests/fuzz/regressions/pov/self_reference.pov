// fuzz_pov: a declaration naming itself means the earlier value; following the name at each
// use recursed without end (a stack overflow).
#declare F = finish { phong 1 }
#declare F = finish { F diffuse 0.5 }
#declare I = interior { ior 1.5 }
#declare I = interior { I }
#declare T = transform { translate x }
#declare T = transform { T transform T }
#declare A = sphere { 0, 1 }
#declare A = object { A }
object { A finish { F } interior { I } transform T }
