#version 450
// The fault-line planet (seed 002 §2.5 after Elias and Bourke; spec in core/params/fault_planet.hpp):
// one invocation per region counts the fault planes whose normal n puts the region's position p on
// the raised side, dot(n, p) > 0, minus those that put it on the lowered side, the dot `precise` as
// ((n.x·p.x + n.y·p.y) + n.z·p.z), the reference's order.
// Mutants (compare/mutants/planet.cpp): PLANET_FAULT_LINES_RAISE_ONLY and _PLANE_OFF_CENTRE (both
// twins: reference/planet/fault_lines.cpp alike), _FLOAT_DOT_NUDGED (both float twins: each dot
// 2^-12·Σ|n_c·p_c| too high), PLANET_FAULT_LINES_GPU_LAST_FAULT_SKIPPED (this
// twin only: the loop stops one fault early).
// Inputs:  uniforms region_count, fault_count; positions (binding 1: x, y, z per region), normals
//          (2: x, y, z per fault), float, each rounded once from core's doubles on the host.
// Outputs: votes (3), one int per region.
// Twin:    reference/planet/fault_lines.cpp; host: gpu/planet/fault_lines.cpp.
layout(local_size_x = 64) in;

uniform uint region_count;
uniform uint fault_count;

layout(std430, binding = 1) readonly buffer Positions { float positions[]; };
layout(std430, binding = 2) readonly buffer Normals { float normals[]; };
layout(std430, binding = 3) writeonly buffer Votes { int votes[]; };

void main() {
  uint region = gl_GlobalInvocationID.x;
  if (region >= region_count) return;
  vec3 p = vec3(positions[3u * region], positions[3u * region + 1u], positions[3u * region + 2u]);
#if defined(GT_MUTANT_PLANET_FAULT_LINES_PLANE_OFF_CENTRE)
  const float plane_offset = 0.05;
#else
  const float plane_offset = 0.0;
#endif
#if defined(GT_MUTANT_PLANET_FAULT_LINES_GPU_LAST_FAULT_SKIPPED)
  uint faults = fault_count - 1u;
#else
  uint faults = fault_count;
#endif
  int count = 0;
  for (uint fault = 0u; fault < faults; ++fault) {
    vec3 n = vec3(normals[3u * fault], normals[3u * fault + 1u], normals[3u * fault + 2u]);
    precise float xy = n.x * p.x + n.y * p.y;
    precise float dot_product = xy + n.z * p.z;
#if defined(GT_MUTANT_PLANET_FAULT_LINES_FLOAT_DOT_NUDGED)
    precise float magnitude = (abs(n.x * p.x) + abs(n.y * p.y)) + abs(n.z * p.z);
    dot_product = dot_product + (1.0 / 4096.0) * magnitude;
#endif
    if (dot_product > plane_offset) {
      count += 1;
    } else {
#if !defined(GT_MUTANT_PLANET_FAULT_LINES_RAISE_ONLY)
      count -= 1;
#endif
    }
  }
  votes[region] = count;
}
