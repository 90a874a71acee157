// Other half of the include cycle of cycle.comp; line 3 closes the cycle.

#include "lib/cycle_b.glsl"
