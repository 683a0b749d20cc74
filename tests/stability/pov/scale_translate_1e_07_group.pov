#declare Place = transform { translate <1e7, 1e7, -1e7> }
#include "sweep.inc"
