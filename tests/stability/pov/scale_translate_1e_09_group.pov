#declare Place = transform { translate <1e9, 1e9, -1e9> }
#include "sweep.inc"
