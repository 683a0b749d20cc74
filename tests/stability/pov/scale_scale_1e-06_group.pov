#declare Place = transform { scale 1e-6 }
#include "sweep.inc"
