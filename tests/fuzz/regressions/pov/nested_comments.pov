// fuzz_pov: forty unterminated nested block comments. The PEG comment rule retried each inner
// one as text after it failed: exponential (a stall); the lexer now counts depth.
/* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a /* a 
sphere { 0, 1 }
