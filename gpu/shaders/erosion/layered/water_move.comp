#version 450
// Pass 2 of the pipe flow on the layered ground (digest 001 §3.3, §3.7), GPU twin of `fractions`
// and `moved` in reference/erosion/layered/water.cpp: a donor's fraction through pipe k is
// Δt·F_k/(l_x·l_y·w) (0 when dry); water and each carried kind q become
// kept + Σ_k q_{n_k}·f_{n_k, k^1} with kept = max(q − Σ_k q·f_k, 0), or 0 for a drained column,
// reading the snapshot half (copied by the host after pass 1); PREVIOUS ← w before the move. One invocation per column, writing only its own words.
// Units: m.
// Inputs:  LayeredWaterBlock (uniform binding 1) and the water state (10), its snapshot half
//          (water.glsl).
// Outputs: water, carried kinds and PREVIOUS in the current half of the water state (10).
// Twin:    reference/erosion/layered/water.cpp (fractions, moved).
#include "erosion/layered/water.glsl"

void fractions(uint c, out float fraction[4]) {
  float depth = water_state[water_at(SNAPSHOT, WATER, c)];
  for (int k = 0; k < PIPES; ++k) fraction[k] = 0.0;
  if (depth <= 0.0) return;
  precise float held = cell_area * depth;
  for (int k = 0; k < PIPES; ++k) {
    precise float volume = time_step * water_state[water_at(SNAPSHOT, FLUX + uint(k), c)];
    fraction[k] = gt_div(volume, held);
  }
}

// q' of one section: what stays, then what arrives in pipe order.
void move_section(uint section, uint c, float own[4], int neighbours[4], float arriving[4]) {
  float amount = water_state[water_at(SNAPSHOT, section, c)];
  precise float sent = 0.0;
  for (int k = 0; k < PIPES; ++k) sent += amount * own[k];
  precise float kept = amount - sent;
#ifdef GT_MUTANT_EROSION_LAYERED_GPU_DRAINED_KEEPS_REST
  bool drained = false;  // mutant (this twin alone): a drained column keeps its rounding residue
#else
  bool drained = water_state[water_at(SNAPSHOT, DRAINED, c)] != 0.0;
#endif
  precise float result = drained ? 0.0 : max(kept, 0.0);
  for (int k = 0; k < PIPES; ++k) {
#ifdef GT_MUTANT_EROSION_LAYERED_SEDIMENT_STAYS_BEHIND
    if (section != WATER) break;
#endif
    if (neighbours[k] < 0) continue;
    result += water_state[water_at(SNAPSHOT, section, uint(neighbours[k]))] * arriving[k];
  }
  water_state[water_at(CURRENT, section, c)] = result;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  float own[4];
  fractions(c, own);
  int neighbours[4];
  float arriving[4];  // the fraction of neighbour k's quantity that comes here
  for (int k = 0; k < PIPES; ++k) {
    neighbours[k] = neighbour(cell, k);
    arriving[k] = 0.0;
    if (neighbours[k] < 0) continue;
    float theirs[4];
    fractions(uint(neighbours[k]), theirs);
    arriving[k] = theirs[k ^ 1];
  }
  move_section(WATER, c, own, neighbours, arriving);
  for (int kind = 0; kind < CARRIED_KINDS; ++kind) move_section(CARRIED + uint(kind), c, own, neighbours, arriving);
#ifdef GT_MUTANT_EROSION_LAYERED_GPU_PREVIOUS_AFTER_MOVE
  // mutant (this twin alone): PREVIOUS takes the depth after the move, not before it
  water_state[water_at(CURRENT, PREVIOUS, c)] = water_state[water_at(CURRENT, WATER, c)];
#else
  water_state[water_at(CURRENT, PREVIOUS, c)] = water_state[water_at(SNAPSHOT, WATER, c)];
#endif
}
