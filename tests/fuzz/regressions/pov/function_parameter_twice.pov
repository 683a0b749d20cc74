// fuzz_pov (a long run, seed 7): a function parameter named twice translated to an rts macro
// rts refuses (duplicate parameter); the import now says so at the second name.
#declare G = function(c, b, c) { c + b }
