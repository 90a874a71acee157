#version 450
// Sediment diffusion on the layered ground (digest 001 §3.8, step 8 of §4), GPU twin of
// reference/erosion/layered/diffusion.cpp, operation for operation in float: a column's shares σ_k
// toward its edge neighbours are the uniform σ (the thesis) or ½·w_k/(w + Σ ½·w_n) (its code, nothing
// where the base is 0); each diffused kind becomes max(q − Σ_k q·σ_k, 0) + Σ_k q_{n_k}·σ_{n_k, k^1},
// reading the snapshot half (copied by the host before the pass). The diffused kinds: the suspended
// org .. boulders, and the regolith's two with regolith_diffusion. One invocation per column, writing
// only its own words; the host skips the pass when σ = 0. Units: metres.
// Inputs:  LayeredWaterBlock (uniform binding 1) and the water state (10) with its snapshot half
//          (water.glsl).
// Outputs: the carried kinds in the current half of the water state (10).
// Twin:    reference/erosion/layered/diffusion.cpp.
#include "erosion/layered/water.glsl"

float snapshot_depth(int n) { return water_state[water_at(SNAPSHOT, WATER, uint(n))]; }

// σ_k of column `cell` (index c) toward its neighbours.
void diffusion_shares(ivec2 cell, uint c, out float shares[4]) {
  int neighbours[4];
  for (int k = 0; k < PIPES; ++k) {
    neighbours[k] = neighbour(cell, k);
    shares[k] = 0.0;
  }
  if (diffusion_water == 0) {
    for (int k = 0; k < PIPES; ++k) shares[k] = neighbours[k] >= 0 ? sediment_diffusion : 0.0;
    return;
  }
  float neighbour_weights[4];
  precise float base = snapshot_depth(int(c));
  for (int k = 0; k < PIPES; ++k) {
    neighbour_weights[k] = 0.0;
    if (neighbours[k] < 0) continue;
    precise float weight = 0.5 * snapshot_depth(neighbours[k]);
    neighbour_weights[k] = weight;
    base += weight;
  }
  if (!(base > 0.0)) return;
  for (int k = 0; k < PIPES; ++k) shares[k] = gt_div(neighbour_weights[k], base);
}

ivec2 cell_of(int n) { return ivec2(n % grid_size.x, n / grid_size.x); }

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  float own[4];
  diffusion_shares(cell, c, own);
  int neighbours[4];
  float arriving[4];  // σ of neighbour k toward this column
  for (int k = 0; k < PIPES; ++k) {
    neighbours[k] = neighbour(cell, k);
    arriving[k] = 0.0;
    if (neighbours[k] < 0) continue;
    float theirs[4];
    diffusion_shares(cell_of(neighbours[k]), uint(neighbours[k]), theirs);
    arriving[k] = theirs[k ^ 1];
  }
#ifdef GT_MUTANT_EROSION_LAYERED_GPU_DIFFUSION_SKIPS_REGOLITH
  int kinds = REGOLITH;  // mutant (this twin alone): the regolith never diffuses
#else
  int kinds = regolith_diffusion != 0 ? CARRIED_KINDS : REGOLITH;
#endif
  for (int kind = 0; kind < kinds; ++kind) {
    uint section = CARRIED + uint(kind);
    float amount = water_state[water_at(SNAPSHOT, section, c)];
    precise float sent = 0.0;
    for (int k = 0; k < PIPES; ++k) sent += amount * own[k];
#ifdef GT_MUTANT_EROSION_LAYERED_DIFFUSION_SENT_KEPT
    precise float result = amount;  // mutant (both twins): what a column sends it keeps as well
#else
    precise float kept = amount - sent;
    precise float result = max(kept, 0.0);
#endif
    for (int k = 0; k < PIPES; ++k) {
      if (neighbours[k] < 0) continue;
      result += water_state[water_at(SNAPSHOT, section, uint(neighbours[k]))] * arriving[k];
    }
    water_state[water_at(CURRENT, section, c)] = result;
  }
}
