#version 450
// Dissolution on the layered ground (digest 001 §3.13), GPU twin of
// reference/erosion/layered/dissolution.cpp, operation for operation in float: the regolith grows
// toward r_max = min(w, K_r), half from organic matter and half from sand (erode_component), or
// K_rd of its excess settles with its composition. One invocation per column, in place (the host
// skips the pass when K_r = 0). Units: metres.
// Inputs:  the ground state of layered.glsl (LayeredBlock 0, surface 1, soil 2, bedrock 3), the
//          LayeredWaterBlock (uniform binding 1) and the water state (10) of water.glsl.
// Outputs: the column's soil and surface, and its regolith in the water state (10), in place.
// Twin:    reference/erosion/layered/dissolution.cpp.
#include "erosion/layered/column.glsl"
#include "erosion/layered/water.glsl"

// The share of a regolith kind that settles (all of it when less than NEGLIGIBLE would stay).
float settle_share(uint at, float amount, float share) {
  precise float part = amount * share;
  precise float left = amount - part;
  bool whole = left < NEGLIGIBLE;
  water_state[at] = whole ? 0.0 : left;
  return whole ? amount : part;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  uint organic_at = water_at(CURRENT, CARRIED + uint(REGOLITH), c);
  uint sand_at = water_at(CURRENT, CARRIED + uint(REGOLITH + 1), c);
  float organic = water_state[organic_at];
  float sand = water_state[sand_at];
  precise float regolith = organic + sand;
  float most = min(water_state[water_at(CURRENT, WATER, c)], regolith_depth);
  if (regolith < most) {
    precise float wanted = regolith_erosion * (most - regolith);
    precise float half_wanted = 0.5 * wanted;
    precise float organic_after = organic + erode_component(c, 0, half_wanted, least_share, transparency_depth,
                                                            share_code != 0);
    precise float sand_after = sand + erode_component(c, 1, half_wanted, least_share, transparency_depth,
                                                      share_code != 0);
    water_state[organic_at] = organic_after;
    water_state[sand_at] = sand_after;
  } else if (regolith > most) {
    precise float excess = regolith_deposition * (regolith - most);
    float share = gt_div(excess, regolith);
    float settled[5] = float[5](settle_share(organic_at, organic, share), settle_share(sand_at, sand, share), 0.0, 0.0,
                                0.0);
    deposit_soil(c, settled);
  }
}
