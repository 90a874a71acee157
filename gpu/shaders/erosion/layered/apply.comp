#version 450
// Apply pass shared by talus collapse (§3.10) and soil creep (§3.11) of the layered ground: one
// invocation per column c moves the outflows the compute pass wrote. GPU twin of
// reference/erosion/layered/transfer.cpp (apply_outflows), with the column operations of
// column.glsl, operation for operation in float:
//   1. remove_soil(c, min(Σ_k out[c][k], thickness of c's topmost non-empty layer in the snapshot));
//   2. gather out[n_k][k^1] from the neighbours, k = 0..7, each carrying the composition of n_k's
//      topmost non-empty layer in the snapshot, or the fragments of its bedrock (a conversion);
//   3. deposit the sum once, reserve-then-deposit (§3.1);
//   with LAYERED_CLEAR_VEGETATION (talus, §3.15) a column that gives or receives loses its vegetation.
// Column c writes only its own entries of the current half, so no two invocations touch the same
// word. Per column it writes its conversions (fragments received, bedrock given) for the host to
// sum in double. Units: metres.
// Inputs:  LayeredBlock (uniform binding 0), the snapshot half of soil (2) and bedrock (3),
//          bedrock_type (4), bedrock_types (6), outflow (7) (layered.glsl).
// Outputs: column c's current half of surface (1), soil (2) and bedrock (3); vegetation (5) with
//          LAYERED_CLEAR_VEGETATION; conversions (8), one record per column.
// Twin:    reference/erosion/layered/transfer.cpp (apply_outflows).
#include "erosion/layered/column.glsl"

struct ColumnConversion {
  vec4 fragmented_into;  // sand, gravel, stones, boulders received as broken bedrock, m
  float fragmented_from; // bedrock this column gave, m
  int from_type;         // its bedrock type
};
layout(std430, binding = 8) writeonly buffer Conversions { ColumnConversion conversions[]; };

// What `amount` leaving donor n carries, from the snapshot; bedrock fragments are added to `into`.
void flux_composition(uint n, float amount, inout vec4 into, out float carried[5]) {
  int layer = top_nonempty_layer(SNAPSHOT, n);
  if (layer < SOIL_LAYERS) {
    float share = gt_div(amount, soil_thickness(SNAPSHOT, layer, n));
    for (int i = 0; i < COMPONENTS; ++i) {
      precise float part = soil[soil_at(SNAPSHOT, layer, i, n)] * share;
#ifdef GT_MUTANT_EROSION_LAYERED_FLUX_COMPONENTS_SHIFTED
      carried[(i + 1) % COMPONENTS] = part;
#else
      carried[i] = part;
#endif
    }
    return;
  }
  fragments(type_at(layer - SOIL_LAYERS, n), amount, carried);
  precise vec4 sum = into + vec4(carried[1], carried[2], carried[3], carried[4]);
  into = sum;
}

// The material arriving at `cell` from its neighbours, in neighbour order.
void gather(ivec2 cell, inout vec4 into, out float arriving[5]) {
  for (int i = 0; i < COMPONENTS; ++i) arriving[i] = 0.0;
  for (int order = 0; order < NEIGHBOURS; ++order) {
#ifdef GT_MUTANT_EROSION_LAYERED_GPU_GATHER_REVERSED
    int k = NEIGHBOURS - 1 - order;  // mutant (this twin alone): the neighbours summed last to first
#else
    int k = order;
#endif
#ifdef GT_MUTANT_EROSION_LAYERED_DIAGONAL_ARRIVALS_DROPPED
    if (k >= 4) continue;  // mutant (both twins): the diagonal neighbours' arrivals never gathered
#endif
    int n = neighbour(cell, k);
    if (n < 0) continue;
    float amount = outflow[uint(NEIGHBOURS) * uint(n) + uint(k ^ 1)];
    if (amount <= 0.0) continue;
    float carried[5];
    flux_composition(uint(n), amount, into, carried);
    for (int i = 0; i < COMPONENTS; ++i) {
      precise float sum = arriving[i] + carried[i];
      arriving[i] = sum;
    }
  }
}

float layer_thickness_before(int layer, uint c) {
  return layer < SOIL_LAYERS ? soil_thickness(SNAPSHOT, layer, c)
                             : bedrock[bedrock_at(SNAPSHOT, layer - SOIL_LAYERS, c)];
}

// The calibrated pair of the float ledger's model, in both float twins (reference/erosion/layered/
// transfer.cpp's calibrated_leak alike): every stored thickness of the column times 1 − 2^-16
// (above the bound) or 1 − 2^-22 (below it) after the pass.
#if defined(GT_MUTANT_EROSION_LAYERED_FLOAT_LEAK_ABOVE_BOUND)
const float kept_share = 1.0 - 1.0 / 65536.0;
#elif defined(GT_MUTANT_EROSION_LAYERED_FLOAT_LEAK_BELOW_BOUND)
const float kept_share = 1.0 - 1.0 / 4194304.0;
#else
const float kept_share = 1.0;
#endif

void calibrated_leak(uint c) {
  if (kept_share == 1.0) return;
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
    for (int i = 0; i < COMPONENTS; ++i) {
      uint at = soil_at(CURRENT, layer, i, c);
      precise float kept = soil[at] * kept_share;
      soil[at] = kept;
    }
  }
  for (int layer = 0; layer < bedrock_layer_count; ++layer) {
    uint at = bedrock_at(CURRENT, layer, c);
    precise float kept = bedrock[at] * kept_share;
    bedrock[at] = kept;
  }
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  precise float given = 0.0;
  for (int k = 0; k < NEIGHBOURS; ++k) given += outflow[uint(NEIGHBOURS) * c + uint(k)];
  float rock = 0.0;
  int rock_layer = -1;
  if (given > 0.0) {
    float available = layer_thickness_before(top_nonempty_layer(SNAPSHOT, c), c);
    rock_layer = remove_soil(c, min(given, available), rock);
  }
  vec4 into = vec4(0.0);
  float arriving[5];
  gather(cell, into, arriving);
  bool received = composition_total(arriving) > 0.0;
  if (received) deposit_soil(c, arriving);
#ifdef LAYERED_CLEAR_VEGETATION
  if (received || given > 0.0) vegetation[c] = 0.0;
#endif
  calibrated_leak(c);
  conversions[c] = ColumnConversion(into, rock, rock_layer >= 0 ? type_at(rock_layer, c) : 0);
}
