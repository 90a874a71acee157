// Column operations of the layered ground (digest 001 §3.1, §3.10, §3.12), GPU twin of
// reference/erosion/layered/column.cpp (decisions there), operation for operation in float:
// remove_soil, organize_horizon, deposit_soil (reserve, then deposit), fragments, and force
// erosion's erode_component (eq. 3.10 with the transparency rule), soil_transparency and
// erode_bedrock. Each works on column c's current half and keeps the surface in step. Guarded:
// several passes include it. Units: metres.
// Inputs:  column c of the layered.glsl state (LayeredBlock, surface, soil, bedrock, bedrock_type,
//          bedrock_types), current half.
// Outputs: the column operations, which change that column in place.
// Twin:    reference/erosion/layered/column.cpp (column.hpp).
#ifndef GT_EROSION_LAYERED_COLUMN_GLSL
#define GT_EROSION_LAYERED_COLUMN_GLSL

#include "erosion/layered/layered.glsl"

float composition_total(float material[5]) {
  precise float sum = 0.0;
  for (int i = 0; i < COMPONENTS; ++i) sum += material[i];
  return sum;
}

// Takes the share `fraction` of every component of current soil layer `layer` into `taken`.
void take_share(int layer, uint c, float fraction, out float taken[5]) {
  for (int i = 0; i < COMPONENTS; ++i) {
    uint at = soil_at(CURRENT, layer, i, c);
    precise float stored = soil[at];
    precise float part = fraction == 1.0 ? stored : stored * fraction;
    soil[at] = stored - part;
    taken[i] = part;
  }
}

// Takes up to `left` from soil layer `layer` proportionally into `removed`; a layer thicker than
// the request meets it whole.
void take_from_soil_layer(int layer, uint c, inout float left, inout float removed[5]) {
  float thickness = soil_thickness(CURRENT, layer, c);
  if (thickness <= 0.0 || left <= 0.0) return;
  bool whole_layer = left >= thickness;
  float taken[5];
  take_share(layer, c, whole_layer ? 1.0 : gt_div(left, thickness), taken);
  for (int i = 0; i < COMPONENTS; ++i) {
    precise float sum = removed[i] + taken[i];
    removed[i] = sum;
  }
  precise float rest = left - thickness;
  left = whole_layer ? rest : 0.0;
}

// remove_soil: topsoil, subsoil, then the first non-empty bedrock layer, at most what it holds.
// Returns the bedrock layer taken from (−1 none) and its amount in `rock`.
int remove_soil(uint c, float amount, out float rock) {
  float removed[5] = float[5](0.0, 0.0, 0.0, 0.0, 0.0);
  precise float left = amount;
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) take_from_soil_layer(layer, c, left, removed);
  int top = top_nonempty_layer(CURRENT, c);
  int rock_layer = -1;
  rock = 0.0;
  if (left > 0.0 && top >= SOIL_LAYERS) {
    rock_layer = top - SOIL_LAYERS;
    uint at = bedrock_at(CURRENT, rock_layer, c);
    precise float thickness = bedrock[at];
    rock = min(left, thickness);
    bedrock[at] = thickness - rock;
  }
  precise float total = composition_total(removed) + rock;
  precise float lowered = surface[c] - total;
#ifndef GT_MUTANT_EROSION_LAYERED_SURFACE_NOT_LOWERED
  surface[c] = lowered;
#endif
  return rock_layer;
}

// organize_horizon: when topsoil + needed > max, the share (topsoil + needed − max)/topsoil of
// every topsoil component moves into the subsoil.
void organize_horizon(uint c, float needed) {
  float topsoil = soil_thickness(CURRENT, 0, c);
  precise float wanted = topsoil + needed;
  if (topsoil <= 0.0 || wanted <= topsoil_max) return;
  precise float excess = wanted - topsoil_max;
  float moved[5];
  take_share(0, c, clamp(gt_div(excess, topsoil), 0.0, 1.0), moved);
  for (int i = 0; i < COMPONENTS; ++i) {
    uint at = soil_at(CURRENT, 1, i, c);
    precise float sum = soil[at] + moved[i];
    soil[at] = sum;
  }
}

// Mutants erosion.layered.deposit_without_reserve (both twins) and gpu_deposit_without_reserve
// (this shader alone): deposit_soil makes no room and pushes nothing down.
#if defined(GT_MUTANT_EROSION_LAYERED_DEPOSIT_WITHOUT_RESERVE) || \
    defined(GT_MUTANT_EROSION_LAYERED_GPU_DEPOSIT_WITHOUT_RESERVE)
#define DEPOSIT_WITHOUT_RESERVE
#endif

// deposit_soil: reserve room for the whole material, add it to the topsoil, push the excess down.
void deposit_soil(uint c, float material[5]) {
  float total = composition_total(material);
  if (total <= 0.0) return;
#ifndef DEPOSIT_WITHOUT_RESERVE
  organize_horizon(c, total);
#endif
  for (int i = 0; i < COMPONENTS; ++i) {
    uint at = soil_at(CURRENT, 0, i, c);
    precise float sum = soil[at] + material[i];
    soil[at] = sum;
  }
#ifndef DEPOSIT_WITHOUT_RESERVE
  organize_horizon(c, 0.0);
#endif
  precise float raised = surface[c] + total;
  surface[c] = raised;
}

// The calibrated pair of ledger.conversions' model, in both float twins (reference/erosion/
// layered/column.cpp's calibrated_broken alike): the rock breaks into 1 − 2^-16 (above the bound)
// or 1 − 2^-22 (below it) of itself.
#if defined(GT_MUTANT_EROSION_LAYERED_FRAGMENTS_SHORT_ABOVE_BOUND)
const float broken_share = 1.0 - 1.0 / 65536.0;
#elif defined(GT_MUTANT_EROSION_LAYERED_FRAGMENTS_SHORT_BELOW_BOUND)
const float broken_share = 1.0 - 1.0 / 4194304.0;
#else
const float broken_share = 1.0;
#endif

// fragments(type, amount): sand, gravel, stones by K_rock, boulders the remainder.
void fragments(int type, float amount, out float broken[5]) {
  precise float whole = amount * broken_share;
  precise float given = 0.0;
  broken[0] = 0.0;
  for (int size = 0; size < 3; ++size) {
    precise float part = bedrock_types[type].fragments[size] * whole;
    broken[size + 1] = part;
    given += part;
  }
  precise float rest = whole - given;
#ifdef GT_MUTANT_EROSION_LAYERED_FRAGMENTS_WITHOUT_BOULDERS
  broken[4] = 0.0;
#else
  broken[4] = max(rest, 0.0);
#endif
}

// erode_component: force erosion's removal of `component` (§3.12): per non-empty soil layer, top
// down, min(m·max(K_emin, V_j/V), V_j) (thesis) or min(V_j, m)·max(K_emin, V_j/V) (share_code),
// then m ← max(m − V_j, 0)·max(1 − V/K_pmin, 0). Returns the amount taken; lowers the surface.
// take_from_layer: one soil layer's part of erode_component, min(m·max(K_emin, V_j/V), V_j) (or the
// code's share form) of `component` taken from layer `layer` (thickness V > 0); the surface is the
// caller's to lower.
float take_from_layer(uint c, int layer, int component, float request, float least_share, bool share_code) {
  float thickness = soil_thickness(CURRENT, layer, c);
  uint at = soil_at(CURRENT, layer, component, c);
  float before = soil[at];
  float share = max(least_share, gt_div(before, thickness));
  precise float wanted = request * share;
  precise float code_take = min(before, request) * share;
  float take = share_code ? code_take : min(wanted, before);
  precise float after = before - take;
  soil[at] = after;
  return take;
}

float erode_component(uint c, int component, float request, float least_share, float transparency_depth,
                      bool share_code) {
  precise float taken = 0.0;
  precise float left = request;
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
    if (!(left > 0.0)) break;
    float thickness = soil_thickness(CURRENT, layer, c);
    if (thickness <= 0.0) continue;
    float before = soil[soil_at(CURRENT, layer, component, c)];
    taken += take_from_layer(c, layer, component, left, least_share, share_code);
    precise float passed = max(left - before, 0.0);
    precise float opening = 1.0 - gt_div(thickness, transparency_depth);
    precise float next = passed * max(opening, 0.0);
    left = next;
  }
  precise float lowered = surface[c] - taken;
  surface[c] = lowered;
  return taken;
}

// Π over the non-empty soil layers of max(1 − V/K_pmin, 0).
float soil_transparency(uint c, float transparency_depth) {
  precise float through = 1.0;
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
    float thickness = soil_thickness(CURRENT, layer, c);
    if (!(thickness > 0.0)) continue;
    precise float opening = 1.0 - gt_div(thickness, transparency_depth);
    through *= max(opening, 0.0);
  }
  return through;
}

// Takes min(amount, thickness) from the first non-empty bedrock layer (its index in `layer`, −1
// none); lowers the surface; returns the amount.
float erode_bedrock(uint c, float amount, out int layer) {
  layer = -1;
  for (int k = 0; k < bedrock_layer_count; ++k) {
    uint at = bedrock_at(CURRENT, k, c);
    float thickness = bedrock[at];
    if (thickness <= 0.0) continue;
    float taken = min(amount, thickness);
    precise float left = thickness - taken;
    bedrock[at] = left;
    precise float lowered = surface[c] - taken;
    surface[c] = lowered;
    layer = k;
    return taken;
  }
  return 0.0;
}

#endif
