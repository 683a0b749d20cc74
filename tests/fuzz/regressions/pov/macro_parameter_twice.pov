// A #macro parameter named twice: a located import error (rts refuses such a macro).
#macro M(a, a)
  sphere { 0, a }
#end
M(1, 2)
