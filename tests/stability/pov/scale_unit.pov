#declare Place = transform { scale 1 }
#include "sweep.inc"
