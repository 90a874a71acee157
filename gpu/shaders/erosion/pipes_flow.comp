#version 450
// Stages 3-5 and the first half of 6 of the virtual-pipe erosion (Mei 2007, digest 000
// eqs. 2.14-2.23), all per cell from the fluxes of pipes_outflow.comp:
//   3 depth     d_B = (0 if K < 1 drained the cell, else max(0, d_A - Δt·Σf_out/(l_x·l_y))) + Δt·Σf_in/(l_x·l_y)
//   4 velocity  u = ½((f_in,L - f_L) + (f_R - f_in,R))/(l_y·d̄), d̄ = max(floor, ½(d_A + d_B)); v alike;
//               with PIPES_8 the diagonals add (l_x/l_d)·Σ dx_k·(f_k - f_in,k) inside the ½(...)
//   5 erosion   C = K_c·max(sin α, T)·|v|·min(1, d_B/K_w); the terrain change Δb and s move by
//               k_s·(C - s) or -k_d·(s - C); sin α from central differences of b0 + Δb
//               over the block's spans (2l, or 1 for seed 001's code: raw differences)
//   5' layers   (LAYERS = N ≥ 1, Šťava et al. 2008, eqs. 2.27-2.29, Algorithm 1) T_k = C_k·(tilt, speed,
//               ramp as stage 5), C_0 = K_c; from layer N down while T̂_k = T_k − Σ_{i>k} b_i > s
//               (LAYERS_AS_PRINTED: < s) take min(k_s·gap, b_k) (the bedrock without limit), going on
//               only through an emptied layer; s > T_N puts k_d·(s − T_N) on layer N
//   5b regolith (REGOLITH, seed 001 §3.9) r_max = min(d_B, K_r); r < r_max: Δb and r move by
//               k_re·(r_max - r); else by -k_rd·(r - r_max)
//   6a shares   what each pipe (4 or 8) carries, s_A·f_k·Δt/(d_A·l_x·l_y) (flux transport: `sent`, the
//               rest `staying`), or the sediment kept after the exterior pipes' share
//               (semi-Lagrangian: `staying`, and what left in sent.x); the regolith likewise
// Reads neighbours' Δb (the tilt) and fluxes; writes its own d_B, velocity, Δb into the next
// buffer, staying and sent. TRANSPORT_FLUX selects the flux form.
// Inputs:  PipeBlock (uniform binding 0), cells (1), delta (2), water (4: d_A, drained), outflow (5),
//          sediment (7), regolith (12), layers (18) (pipes_block.glsl).
// Outputs: water (4: d_B), delta_next (3), velocity (6), staying (8), sent (9), regolith_staying (13),
//          regolith_sent (14), layers (18).
// Twin:    reference/erosion/pipes.cpp (update_water_depth, update_velocity, erode_and_deposit,
//          carried_shares, transport_*).
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"

// (b_high - b_low)/span along one axis; at an exterior neighbour the cell itself stands in
// (one-sided difference), with both neighbours exterior the slope is 0.
float axis_slope(ivec2 cell, uint index, uint flags, int lower_pipe, int upper_pipe, vec2 spans) {
  int lower = exterior(flags, lower_pipe) ? 0 : 1;
  int upper = exterior(flags, upper_pipe) ? 0 : 1;
  if (lower + upper == 0) return 0.0;
  uint low = lower == 1 ? neighbour_index(cell, lower_pipe) : index;
  uint high = upper == 1 ? neighbour_index(cell, upper_pipe) : index;
  precise float slope = terrain_difference(high, low) / spans[lower + upper - 1];
  return slope;
}

float tilt_sine(ivec2 cell, uint index, uint flags) {
  precise float slope_x = axis_slope(cell, index, flags, pipe_left, pipe_right, slope_span_x);
  precise float slope_y = axis_slope(cell, index, flags, pipe_bottom, pipe_top, slope_span_y);
  precise float squared = slope_x * slope_x + slope_y * slope_y;
  precise float sine = sqrt(squared / (1.0 + squared));
  return ref_max(min_tilt_sine, sine);
}

// The share of the cell's water each pipe moved, f_k·Δt/(d_A·l_x·l_y), scaled down to sum to 1
// where rounding made the total exceed it; 0 for a dry cell.
vec4[2] carried_shares(float depth_before, vec4 out_flux[2]) {
  precise vec4 shares[2] = vec4[2](vec4(0.0), vec4(0.0));
  if (!(depth_before > 0.0)) return shares;
  for (int k = 0; k < pipe_count; ++k) shares[k / 4][k % 4] = out_flux[k / 4][k % 4] * volume_to_depth / depth_before;
  precise float total = pipe_total(shares);
  if (total > 1.0) {
    for (int k = 0; k < pipe_count; ++k) shares[k / 4][k % 4] = shares[k / 4][k % 4] / total;
  }
  return shares;
}

// The share that left through exterior pipes (semi-Lagrangian transport): the exterior axis pipes'
// shares added in the order L, R, T, B, then with 8 pipes the exterior diagonals' pipe_sum.
float exterior_share(uint flags, vec4 shares[2]) {
  precise float leaving = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (exterior(flags, k)) leaving = leaving + shares[0][k];
  }
  if (pipe_groups > 1) {
    precise vec4 exterior_diagonals = vec4(0.0);
    for (int k = 4; k < 8; ++k) {
      if (exterior(flags, k)) exterior_diagonals[k % 4] = shares[1][k % 4];
    }
    leaving = leaving + pipe_sum(exterior_diagonals);
  }
  return leaving;
}

// The diagonals' pipe_sum of dx_k·(f_k - f_in,k) (axis 0) or dy_k·(f_k - f_in,k) (axis 1), each
// term formed as f_k - f_in,k or f_in,k - f_k (the reference's directed_outflow).
float diagonal_outflow(vec4 out_flux, vec4 in_flux, int axis) {
  precise vec4 terms = vec4(0.0);
  for (int k = 4; k < 8; ++k) {
    int j = k % 4;
    if (pipe_offsets[k][axis] > 0) {
      terms[j] = out_flux[j] - in_flux[j];
    } else {
      terms[j] = in_flux[j] - out_flux[j];
    }
  }
  return pipe_sum(terms);
}

// f_k of the cell's neighbours through its pipes towards it (f_in,k = neighbour k's pipe k ^ 1),
// 0 through exterior pipes.
vec4[2] inflows(ivec2 cell, uint flags) {
  vec4 in_flux[2] = vec4[2](vec4(0.0), vec4(0.0));
  for (int k = 0; k < pipe_count; ++k) {
    if (!exterior(flags, k)) in_flux[k / 4][k % 4] = outflow[pipe_slot(neighbour_index(cell, k), k)][opposite(k) % 4];
  }
  return in_flux;
}

// What the water takes from the cell's ground (> 0) or leaves on it (< 0): Šťava's walk over the
// LAYERS layers (stage 5'), the layers of cell `index` updated in place; with LAYERS = 0 Mei's
// stage 5 (k_s·(C − s) or −k_d·(s − C)). The reference's layered_exchange, operation by operation.
float layered_exchange(uint index, float tilt, float speed, float ramp, float suspended) {
  precise float capacities[LAYERS + 1];
  capacities[0] = capacity_constant * tilt * speed * ramp;
  for (int k = 1; k <= LAYERS; ++k) capacities[k] = layer_capacity[k - 1] * tilt * speed * ramp;
  precise float taken_total = 0.0;
  precise float above = 0.0;
  for (int k = LAYERS; k >= 0; --k) {
#ifdef GT_MUTANT_EROSION_PIPE_LAYERS_ABOVE_IGNORED
    precise float reach = capacities[k];  // mutant (both twins): T̂_k = T_k, eq. 2.29 left out
#else
    precise float reach = capacities[k] - above;
#endif
#ifdef LAYERS_AS_PRINTED
    if (!(reach < suspended)) break;
    precise float gap = suspended - reach;
#else
    if (!(reach > suspended)) break;
    precise float gap = reach - suspended;
#endif
    precise float wanted = dissolving * gap;
    if (k == 0) {
      taken_total = taken_total + wanted;
      break;
    }
#if LAYERS > 0
    uint slot = uint(LAYERS) * index + uint(k - 1);
    float held = layers[slot];
    precise float taken = ref_min(wanted, held);
    precise float left = held - taken;
    layers[slot] = left;
    taken_total = taken_total + taken;
    if (taken < held) break;
    above = above + held;
#endif
  }
  float top = capacities[LAYERS];
  precise float deposited = 0.0;
  if (suspended > top) deposited = deposition * (suspended - top);
#if LAYERS > 0
#ifdef GT_MUTANT_EROSION_PIPE_GPU_DEPOSIT_ON_BOTTOM_LAYER
  uint top_slot = uint(LAYERS) * index;  // mutant: the deposit settles on layer 1, not on the top
#else
  uint top_slot = uint(LAYERS) * index + uint(LAYERS - 1);
#endif
  precise float settled = layers[top_slot] + deposited;
  layers[top_slot] = settled;
#endif
  precise float moved = taken_total - deposited;
  return moved;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  uint flags = cells[index].flags;
  if (!cell_valid(flags)) return;  // no-data cells keep Δb = 0 in both buffers, s = 0, v = 0

  // 3 water depth
  vec4 out_flux[2] = vec4[2](vec4(0.0), vec4(0.0));
  for (int group = 0; group < pipe_groups; ++group) out_flux[group] = outflow[group_slot(index, group)];
  vec4 in_flux[2] = inflows(cell, flags);
  precise float depth_before = water[index].y;
  precise float drained = depth_before - pipe_total(out_flux) / area_per_time;
  precise float remaining = water[index].w > 0.0 ? 0.0 : ref_max(0.0, drained);
  precise float depth = remaining + pipe_total(in_flux) / area_per_time;
  water[index].z = depth;

  // 4 velocity
  vec4 out_axis = out_flux[0];
  vec4 in_axis = in_flux[0];
  precise float twice_flow_x = (in_axis[pipe_left] - out_axis[pipe_left]) + (out_axis[pipe_right] - in_axis[pipe_right]);
  precise float twice_flow_y = (in_axis[pipe_bottom] - out_axis[pipe_bottom]) + (out_axis[pipe_top] - in_axis[pipe_top]);
  if (pipe_groups > 1) {
    twice_flow_x = twice_flow_x + diagonal_share.x * diagonal_outflow(out_flux[1], in_flux[1], 0);
    twice_flow_y = twice_flow_y + diagonal_share.y * diagonal_outflow(out_flux[1], in_flux[1], 1);
  }
#ifdef GT_MUTANT_EROSION_PIPE_GPU_VELOCITY_WITHOUT_HALF
  precise float flow_x = twice_flow_x;  // mutant: ΔW_X without its ½
#else
  precise float flow_x = 0.5 * twice_flow_x;
#endif
  precise float flow_y = 0.5 * twice_flow_y;
  precise float mean_depth = ref_max(depth_floor, 0.5 * (depth_before + depth));
  precise float u = flow_x / (length_y * mean_depth);
  precise float v = flow_y / (length_x * mean_depth);
#if defined(GT_MUTANT_EROSION_PIPE_VELOCITY_OFF_ABOVE_BOUND)
  u = u * (1.0 + 1.0 / 65536.0);  // mutant: u scaled by 1 + 2^-16 (the calibrated pair's killed half)
#elif defined(GT_MUTANT_EROSION_PIPE_VELOCITY_OFF_BELOW_BOUND)
  u = u * (1.0 + 1.0 / 8388608.0);  // mutant: u one ulp high (1 + 2^-23), which an honest twin may be
#endif
  velocity[index] = vec2(u, v);

  // 5 erosion and deposition
  precise float ramp = 1.0;
  if (depth_ramp > 0.0) ramp = ref_min(1.0, depth / depth_ramp);
  precise float tilt = tilt_sine(cell, index, flags);
  precise float speed = sqrt(u * u + v * v);
  precise float suspended = sediment[index];
  precise float moved = layered_exchange(index, tilt, speed, ramp, suspended);
  precise float changed = delta[index] - moved;
#ifdef GT_MUTANT_EROSION_PIPE_SEDIMENT_GAIN_DOUBLED
  precise float carried = suspended + 2.0 * moved;  // mutant: s gains twice what b loses
#else
  precise float carried = suspended + moved;
#endif

#ifdef REGOLITH
  // 5b regolith exchange, after the erosion's terrain change
#ifdef GT_MUTANT_EROSION_PIPE_REGOLITH_DEEPEST
  precise float loosened = ref_max(depth, regolith_depth);  // mutant (both twins): r_max = max(d_B, K_r)
#else
  precise float loosened = ref_min(depth, regolith_depth);
#endif
  precise float held = regolith[index];
  precise float exchanged;
  if (held < loosened) {
    exchanged = regolith_dissolving * (loosened - held);
  } else {
    exchanged = -(regolith_deposition * (held - loosened));
  }
  changed = changed - exchanged;
  precise float loose = held + exchanged;
#endif
  delta_next[index] = changed;

  // 6a what leaves the cell
  vec4 shares[2] = carried_shares(depth_before, out_flux);
#ifdef TRANSPORT_FLUX
  precise float kept_share = 1.0 - ref_min(1.0, pipe_total(shares));
  for (int group = 0; group < pipe_groups; ++group) {
    vec4 share = shares[group];
    precise vec4 sent_down = vec4(carried * share[0], carried * share[1], carried * share[2], carried * share[3]);
    sent[group_slot(index, group)] = sent_down;
#ifdef REGOLITH
    precise vec4 regolith_down = vec4(loose * share[0], loose * share[1], loose * share[2], loose * share[3]);
    regolith_sent[group_slot(index, group)] = regolith_down;
#endif
  }
  staying[index] = carried * kept_share;
#ifdef REGOLITH
  regolith_staying[index] = loose * kept_share;
#endif
#else
  precise float leaving = exterior_share(flags, shares);
  precise float kept_share = 1.0 - ref_min(1.0, leaving);
  precise float kept = carried * kept_share;
  sent[group_slot(index, 0)] = vec4(carried - kept, 0.0, 0.0, 0.0);
  staying[index] = kept;
#ifdef REGOLITH
  precise float loose_kept = loose * kept_share;
  regolith_sent[group_slot(index, 0)] = vec4(loose - loose_kept, 0.0, 0.0, 0.0);
  regolith_staying[index] = loose_kept;
#endif
#endif
}
