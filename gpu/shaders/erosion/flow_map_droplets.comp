#version 450
// One pass of seed 000's flow map (§4.7, eq. 4.12; digest 000 §4.7 and Appendix A's notes on
// upstream's flow.glsl), one invocation per droplet: droplet (i, j) of the pass with offset (ox, oy)
// starts at rest at the centre of texel (i·S + ox, j·S + oy) and runs up to `lifetime` steps on the
// read-only heights: Algorithm 4 without drop_max (accelerated_axis with no_limit), a stop in a pit
// (h < lowest neighbour) or at rest (|v| = 0), drag, the v_max clamp, the concentration left before
// the unit step along the velocity, and the stop at pos.x <= 0 or pos.y <= 0.
// Eq. 4.12: F = F·(1 - factor) + factor in place (race, disjoint: racing on purpose, as upstream's
// imageLoad/imageStore), factor = f_c·w over erode4's corners (interpolated_flow) or f_c at the
// droplet's texel; FLOW_BATCH: the weight's count of 2^-10 (roundEven(w·1024)) added with atomicAdd.
// All arithmetic `precise`, in the reference's order. Units: texels, texels per step.
// Mutants (compare/mutants/particle.cpp): FLOW_CORNER_WEIGHTS_SWAPPED (GPU only).
// Inputs:  FlowBlock (uniform binding 0), heights (1, read only), valid (2) (flow_map_block.glsl);
//          the uniform pass_offset.
// Outputs: flow (3) in place (race, disjoint), or flow_weights (3) by atomicAdd (FLOW_BATCH).
// Twin:    reference/erosion/flow_map.cpp, whose comment gives the decisions.
#include "common/grid.glsl"
#include "erosion/flow_map_block.glsl"

uniform ivec2 pass_offset;  // (ox, oy) of this pass, each in [0, S)

// Eq. 4.12 at an open cell for a visit of weight `weight` (or its count, FLOW_BATCH).
void leave_flow(ivec2 cell, float weight) {
  if (!open_cell(cell)) return;
  uint index = cell_index(cell, grid_size);
#ifdef FLOW_BATCH
  precise float scaled = weight * 1024.0;
  atomicAdd(flow_weights[index], int(roundEven(scaled)));
#else
  precise float factor = flow_factor * weight;
  precise float rest = 1.0 - factor;
  precise float concentration = flow[index] * rest + factor;
  flow[index] = concentration;
#endif
}

void main() {
  ivec2 droplet = ivec2(gl_GlobalInvocationID.xy);
  if (droplet.x >= droplet_grid.x || droplet.y >= droplet_grid.y) return;
  ivec2 texel = droplet * droplet_spacing + pass_offset;
  precise vec2 position = vec2(texel) + vec2(0.5);
  precise vec2 velocity = vec2(0.0);
  for (int age = 0; age < lifetime; ++age) {
    precise float minus_y = load_height(texel + ivec2(0, -1));
    precise float minus_x = load_height(texel + ivec2(-1, 0));
    precise float plus_x = load_height(texel + ivec2(1, 0));
    precise float plus_y = load_height(texel + ivec2(0, 1));
    precise float lowest = ref_min(ref_min(minus_y, minus_x), ref_min(plus_x, plus_y));
    precise float height = load_height(texel);
    velocity.x = accelerated_axis(velocity.x, height, plus_x, minus_x, acceleration, no_limit);
    velocity.y = accelerated_axis(velocity.y, height, plus_y, minus_y, acceleration, no_limit);
    if (height < lowest) break;  // in a pit
    velocity = vec2(velocity.x * drag, velocity.y * drag);
    precise float speed = sqrt(velocity.x * velocity.x + velocity.y * velocity.y);
    if (speed == 0.0) break;  // at rest
    precise vec2 direction = vec2(velocity.x / speed, velocity.y / speed);
    if (speed > max_velocity) velocity = vec2(direction.x * max_velocity, direction.y * max_velocity);
    if (interpolated_flow != 0u) {
      precise vec2 point = corner_point(position);
      ivec2 corner = ivec2(point);
      precise vec4 weights = bilinear_weights(point, corner);
#ifdef GT_MUTANT_EROSION_PARTICLE_FLOW_CORNER_WEIGHTS_SWAPPED
      weights = weights.xzyw;
#endif
      for (int k = 0; k < 4; ++k) leave_flow(corner + corner_offsets[k], weights[k]);
    } else {
      leave_flow(texel, 1.0);
    }
    position = vec2(position.x + direction.x, position.y + direction.y);
    texel = ivec2(position);  // truncation
    if (position.x <= 0.0 || position.y <= 0.0) break;
  }
}
