#version 450
// One pass of Beyer's particle (droplet) hydraulic erosion (seed 000 §2.7, eqs. 2.35-2.45; digest
// 000 §3.7 and Appendix B item 6), one invocation per droplet: droplet (i, j) of the pass with offset
// (ox, oy) starts at (i·S + ox + 0.5, j·S + oy + 0.5) with direction 0, speed v_0, water w_0 and no
// sediment, and runs at most `lifetime` steps of: bilinear height and gradient (eq. 2.35) at its
// position p; the turn dir·c_i - g·(1 - c_i), normalised (eq. 2.36); the unit move p + dir (eq.
// 2.37); dh = h(p_new) - h(p) (eq. 2.38); uphill the deposit min(dh, s) at p, else with the capacity
// C = c_c·max(-dh, c_min)·v·w (eq. 2.39) the deposit c_d·(s - C) at p (eq. 2.40) or the erosion
// min(c_e·(C - s), -dh) (eq. 2.41) with the brush of eq. 2.42 around p; the speed (eq. 2.44) and the
// evaporation (eq. 2.45).
//
// Decisions, shared with the reference:
//   - Samples at integer points: a position's cell is ivec2(floor(p)), its offsets (u, v) = p - cell;
//     the droplet is on the map when the cell's four samples are open (inside the grid and valid),
//     so reads never leave the map. A droplet starting off the map does nothing; one whose move
//     leaves the map ends before eroding or depositing anything that step.
//   - A zero direction becomes compass[random_u32(seed, droplet_id, age, 0) % 8], the 8 directions
//     of unit length with s = float(0.70710678118654752) (exact below), not a random angle through
//     cos/sin; droplet_id = (pass_number·blocks_y + j)·blocks_x + i in uint32.
//   - Deposits are bilinear over the old cell's four samples; the erosion brush (eq. 2.42) is
//     centred at the old position (Beyer's choice) and renormalised over the open samples in it.
//   - Speed: physical sqrt(max(v² - dh·c_g, 0)), or as printed sqrt(max(v² + dh·c_g, 0)).
//   - max/min are std::max/std::min (ref_max/ref_min).
//   - Batch ordering (BEYER_BATCH): heights are frozen during the pass; every amount moved at a
//     sample is rounded once to a count of quanta (roundEven(amount · inverse_quantum)), added to
//     the sample's delta with atomicAdd, and the droplet's sediment is an integer count with
//     s = float(sediment_quanta) · quantum.
// All arithmetic is `precise` (no fused multiply-add, no reassociation), in the reference's order,
// so ref<float> repeats it bit for bit. Division and sqrt are GLSL's (not correctly rounded in
// general; correctly rounded on llvmpipe), and GPUs may flush subnormals: either may part the twins.
// Units: positions in texels, speed in texels per step, heights in the caller's units.
// Mutants (compare/mutants/beyer.cpp): GRADIENT_SWAPPED_CORNERS (eq. 2.35's y-component with the
// corner pairs swapped), BRUSH_UNNORMALISED (share amount·w), DEPOSIT_AT_NEW_POSITION (both deposits
// at the new cell) in this shader only; SEDIMENT_NOT_TAKEN_ON_EROSION (material destroyed) and
// UPHILL_DEPOSIT_UNBOUNDED (uphill deposit dh, the droplet's sediment clamped at 0: material
// created) in both twins.
// Inputs:  BeyerBlock (uniform binding 0), heights (1), valid (2) (beyer_block.glsl); the uniforms
//          pass_offset and pass_number.
// Outputs: heights (1) in place (race, disjoint), or the quanta added into delta (3) (BEYER_BATCH).
// Twin:    reference/erosion/beyer.cpp.
#include "common/grid.glsl"
#include "common/rng.glsl"
#include "erosion/beyer_block.glsl"

uniform ivec2 pass_offset;  // (ox, oy) of this pass, each in [0, S)
uniform uint pass_number;   // iteration·S² + oy·S + ox, in uint32 (wrapping)

// The bilinear corners in the order they are visited: (0,0), (1,0), (0,1), (1,1).
const ivec2 corner_offsets[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));

// float(0.70710678118654752) written out exactly, so no compiler's literal parsing can move it.
const float compass_diagonal = 0.707106769084930419921875;
const vec2 compass[8] = vec2[8](vec2(1.0, 0.0), vec2(compass_diagonal, compass_diagonal), vec2(0.0, 1.0),
                                vec2(-compass_diagonal, compass_diagonal), vec2(-1.0, 0.0),
                                vec2(-compass_diagonal, -compass_diagonal), vec2(0.0, -1.0),
                                vec2(compass_diagonal, -compass_diagonal));

// The cell of a position: the (0,0) corner of its bilinear interpolation.
ivec2 cell_of(vec2 position) { return ivec2(floor(position)); }

// Whether a droplet whose position lies in `cell` is on the map: the cell's four samples are open.
bool on_map(ivec2 cell) {
  for (int k = 0; k < 4; ++k) {
    if (!open_cell(cell + corner_offsets[k])) return false;
  }
  return true;
}

// The heights of the cell's four samples (h00, h10, h01, h11); the cell is on the map.
vec4 corner_heights(ivec2 cell) {
  return vec4(load_height(cell), load_height(cell + ivec2(1, 0)), load_height(cell + ivec2(0, 1)),
              load_height(cell + ivec2(1, 1)));
}

// The offsets (u, v) of a position inside its cell.
vec2 cell_offsets(vec2 position, ivec2 cell) {
  precise vec2 offset = vec2(position.x - float(cell.x), position.y - float(cell.y));
  return offset;
}

// (1 - u, 1 - v), computed once per position.
vec2 rests_of(vec2 offset) {
  precise vec2 rest = vec2(1.0 - offset.x, 1.0 - offset.y);
  return rest;
}

// The bilinear height: the bottom row (h00, h10) and the top row (h01, h11) blended along y.
float bilinear_height(vec4 corners, vec2 offset, vec2 rest) {
  precise float bottom = corners.x * rest.x + corners.y * offset.x;
  precise float top = corners.z * rest.x + corners.w * offset.x;
  precise float height = bottom * rest.y + top * offset.y;
  return height;
}

// Eq. 2.35 (the corner pairs of its y-component swapped under the mutant).
vec2 gradient_at(vec4 corners, vec2 offset, vec2 rest) {
  precise float gradient_x = (corners.y - corners.x) * rest.y + (corners.w - corners.z) * offset.y;
#ifdef GT_MUTANT_EROSION_BEYER_GRADIENT_SWAPPED_CORNERS
  precise float gradient_y = (corners.w - corners.y) * rest.x + (corners.z - corners.x) * offset.x;
#else
  precise float gradient_y = (corners.z - corners.x) * rest.x + (corners.w - corners.y) * offset.x;
#endif
  return vec2(gradient_x, gradient_y);
}

// Bilinear weights of the corners (0,0), (1,0), (0,1), (1,1): (1-u)(1-v), u(1-v), (1-u)v, uv.
vec4 corner_weights(vec2 offset, vec2 rest) {
  precise vec4 weights = vec4(rest.x * rest.y, offset.x * rest.y, rest.x * offset.y, offset.x * offset.y);
  return weights;
}

// Eq. 2.42's cone: max(radius - |cell - position|, 0).
float brush_weight(ivec2 cell, vec2 position) {
  precise float dx = float(cell.x) - position.x;
  precise float dy = float(cell.y) - position.y;
  precise float gap = sqrt(dx * dx + dy * dy);
  precise float inside = radius - gap;
  precise float weight = ref_max(inside, 0.0);
  return weight;
}

// The brush's square: samples from ceil(position - radius) to floor(position + radius).
ivec2 brush_first(vec2 position) {
  precise vec2 low = vec2(position.x - radius, position.y - radius);
  return ivec2(ceil(low));
}
ivec2 brush_last(vec2 position) {
  precise vec2 high = vec2(position.x + radius, position.y + radius);
  return ivec2(floor(high));
}

// Σ of the brush weights over the open samples of the square, row-major.
float brush_sum(vec2 position) {
  ivec2 first = brush_first(position);
  ivec2 last = brush_last(position);
  precise float sum = 0.0;
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) {
      ivec2 cell = ivec2(x, y);
      if (open_cell(cell)) sum = sum + brush_weight(cell, position);
    }
  }
  return sum;
}

// A sample's share of `amount`: amount·(w/Σw) (amount·w under the mutant).
float brush_share(float amount, float weight, float sum) {
#ifdef GT_MUTANT_EROSION_BEYER_BRUSH_UNNORMALISED
  precise float share = amount * weight;
#else
  precise float share = amount * (weight / sum);
#endif
  return share;
}

#ifdef BEYER_BATCH
// Batch erosion of `amount` with the brush at `position`: each open sample loses the quanta of its
// share (into delta); returns the quanta taken.
int erode(vec2 position, float amount) {
  precise float sum = brush_sum(position);
  if (sum == 0.0) return 0;
  ivec2 first = brush_first(position);
  ivec2 last = brush_last(position);
  int taken = 0;
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) {
      ivec2 cell = ivec2(x, y);
      if (!open_cell(cell)) continue;
      precise float weight = brush_weight(cell, position);
      precise float share = brush_share(amount, weight, sum);
      int count = quanta(share);
      add_quanta(cell, -count);
      taken = taken + count;
    }
  }
  return taken;
}

// Batch deposition of `amount` over the four samples of `cell`: each gets the quanta of amount·w_k;
// returns the quanta given.
int deposit(ivec2 cell, vec2 offset, vec2 rest, float amount) {
  precise vec4 weights = corner_weights(offset, rest);
  int given = 0;
  for (int k = 0; k < 4; ++k) {
    precise float share = amount * weights[k];
    int count = quanta(share);
    add_quanta(cell + corner_offsets[k], count);
    given = given + count;
  }
  return given;
}
#else
// In-place erosion of `amount` with the brush at `position`: each open sample loses its share and
// the droplet takes it up, one share after the other; returns the sediment afterwards.
float erode(vec2 position, float amount, float sediment) {
  precise float carried = sediment;
  precise float sum = brush_sum(position);
  if (sum == 0.0) return carried;
  ivec2 first = brush_first(position);
  ivec2 last = brush_last(position);
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) {
      ivec2 cell = ivec2(x, y);
      if (!open_cell(cell)) continue;
      precise float weight = brush_weight(cell, position);
      precise float share = brush_share(amount, weight, sum);
      precise float lowered = load_height(cell) - share;
      store_height(cell, lowered);
#ifndef GT_MUTANT_EROSION_BEYER_SEDIMENT_NOT_TAKEN_ON_EROSION
      carried = carried + share;
#endif
    }
  }
  return carried;
}

// In-place deposition of `amount` over the four samples of `cell`, each raised by amount·w_k.
void deposit(ivec2 cell, vec2 offset, vec2 rest, float amount) {
  precise vec4 weights = corner_weights(offset, rest);
  for (int k = 0; k < 4; ++k) {
    ivec2 corner = cell + corner_offsets[k];
    precise float share = amount * weights[k];
    precise float raised = load_height(corner) + share;
    store_height(corner, raised);
  }
}
#endif

void main() {
  ivec2 droplet = ivec2(gl_GlobalInvocationID.xy);
  if (droplet.x >= droplet_grid.x || droplet.y >= droplet_grid.y) return;
  uint droplet_id = (pass_number * uint(droplet_grid.y) + uint(droplet.y)) * uint(droplet_grid.x) + uint(droplet.x);
  ivec2 start = droplet * droplet_spacing + pass_offset;
  precise vec2 position = vec2(float(start.x) + 0.5, float(start.y) + 0.5);
  precise vec2 direction = vec2(0.0);
  precise float speed = initial_speed;
  precise float water = initial_water;
  precise float gradient_share = 1.0 - inertia;  // 1 - c_i
  precise float water_kept = 1.0 - evaporation;  // 1 - c_evap
#ifdef BEYER_BATCH
  int sediment_quanta = 0;
#else
  precise float sediment = 0.0;
#endif
  for (int age = 0; age < lifetime; ++age) {
    // 1. Where the droplet stands: its cell (off the map: it ends), height and gradient.
    ivec2 cell = cell_of(position);
    if (!on_map(cell)) break;
    vec4 corners = corner_heights(cell);
    precise vec2 offset = cell_offsets(position, cell);
    precise vec2 rest = rests_of(offset);
    precise float old_height = bilinear_height(corners, offset, rest);
    precise vec2 gradient = gradient_at(corners, offset, rest);

    // 2. The turn of eq. 2.36; a zero direction becomes a random compass direction.
    direction = vec2(direction.x * inertia - gradient.x * gradient_share,
                     direction.y * inertia - gradient.y * gradient_share);
    precise float norm = sqrt(direction.x * direction.x + direction.y * direction.y);
    if (norm != 0.0) {
      direction = vec2(direction.x / norm, direction.y / norm);
    } else {
      direction = compass[random_u32(seed, droplet_id, uint(age), 0u) % 8u];
    }

    // 3.-4. The move; off the map the droplet ends before eroding or depositing.
    precise vec2 next_position = vec2(position.x + direction.x, position.y + direction.y);
    ivec2 next_cell = cell_of(next_position);
    if (!on_map(next_cell)) break;
    vec4 next_corners = corner_heights(next_cell);
    precise vec2 next_offset = cell_offsets(next_position, next_cell);
    precise vec2 next_rest = rests_of(next_offset);
    precise float new_height = bilinear_height(next_corners, next_offset, next_rest);
    precise float dh = new_height - old_height;

    // 5. Deposit at the old cell (the new one under the mutant), or erode around the old position.
#ifdef GT_MUTANT_EROSION_BEYER_DEPOSIT_AT_NEW_POSITION
    ivec2 deposit_cell = next_cell;
    precise vec2 deposit_offset = next_offset;
    precise vec2 deposit_rest = next_rest;
#else
    ivec2 deposit_cell = cell;
    precise vec2 deposit_offset = offset;
    precise vec2 deposit_rest = rest;
#endif
#ifdef BEYER_BATCH
    precise float sediment = float(sediment_quanta) * quantum;
#endif
    bool depositing = false;
    precise float amount = 0.0;
    if (dh > 0.0) {
#ifdef GT_MUTANT_EROSION_BEYER_UPHILL_DEPOSIT_UNBOUNDED
      amount = dh;
#else
      amount = ref_min(dh, sediment);
#endif
      depositing = true;
    } else {
      precise float fall_or_least = ref_max(-dh, min_slope);
      precise float capacity = capacity_factor * fall_or_least * speed * water;
      if (sediment > capacity) {
        amount = deposition * (sediment - capacity);
        depositing = true;
      } else {
        precise float wanted = erosion * (capacity - sediment);
        amount = ref_min(wanted, -dh);
      }
    }
#ifdef BEYER_BATCH
    if (depositing) {
      sediment_quanta = sediment_quanta - deposit(deposit_cell, deposit_offset, deposit_rest, amount);
#ifdef GT_MUTANT_EROSION_BEYER_UPHILL_DEPOSIT_UNBOUNDED
      if (dh > 0.0) sediment_quanta = max(sediment_quanta, 0);
#endif
    } else {
      int taken = erode(position, amount);
#ifndef GT_MUTANT_EROSION_BEYER_SEDIMENT_NOT_TAKEN_ON_EROSION
      sediment_quanta = sediment_quanta + taken;
#endif
    }
#else
    if (depositing) {
      deposit(deposit_cell, deposit_offset, deposit_rest, amount);
      sediment = sediment - amount;
#ifdef GT_MUTANT_EROSION_BEYER_UPHILL_DEPOSIT_UNBOUNDED
      if (dh > 0.0) sediment = ref_max(sediment, 0.0);
#endif
    } else {
      sediment = erode(position, amount, sediment);
    }
#endif

    // 6.-8. Speed (eq. 2.44), evaporation (eq. 2.45), the move.
    precise float kinetic = speed * speed;
    precise float fall = dh * gravity;
    precise float radicand = printed_speed != 0u ? kinetic + fall : kinetic - fall;
    speed = sqrt(ref_max(radicand, 0.0));
    water = water * water_kept;
    position = next_position;
  }
}
