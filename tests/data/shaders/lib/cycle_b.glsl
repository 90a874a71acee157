// Half of the include cycle of cycle.comp.
#include "lib/cycle_c.glsl"
