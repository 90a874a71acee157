// Included by counting.comp; includes a second level.
#include "lib/nested.glsl"

uint library_answer() { return nested_answer(); }
