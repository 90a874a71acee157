#version 450
// One pass of seed 000's particle (droplet) water erosion (digest 000 §4.4, Appendix A: Hydra's
// erosion.frag at 1a1a8c9, Algorithms 4-7), one invocation per droplet: droplet (i, j) of the pass
// with offset (ox, oy) starts at texel (i·S + ox, j·S + oy), centre + 0.5, at rest and without
// sediment, and runs `lifetime` steps of acceleration (upstream's nested branches, Algorithm 4),
// drag, normalisation with the clamp to v_max (upstream, not Algorithm 5's rescale), erosion
// (bilinear over 4 texels, Algorithm 6, or at the texel) or deposition (at the texel), a unit step
// along the normalised velocity, and the stop at pos.x <= 0 or pos.y <= 0. Droplets whose start lies
// off the grid run too (they read zeros). Every droplet marks the side maps at its texel (what it
// eroded, what it deposited). With PARTICLE_COLOUR it carries a colour (§4.5, Algorithm 8, eq. 4.9):
// its start texel's; on erosion (inside h > min_h, after it) col = f_col·C(ipos) + (1 - f_col)·col;
// on deposition (after the height) colorize4 over erode4's corners with factor f_col·w,
// C = C·(1 - factor) + col·factor, or without interpolation C(ipos) = C(ipos)·(1 - f_col) + f_col·col.
//
// Decisions, shared with the reference:
//   - Texels: ipos = ivec2(pos) and erode4's corner ivec2(pos - 0.5) truncate toward zero, as
//     upstream (not floor): for pos.x in (0, 0.5) the corner is 0 and its fraction negative.
//   - Off the grid or masked: read 0, writes ignored (particle_block.glsl). The upper edges are not
//     checked, as upstream: a droplet there sees zero-height neighbours.
//   - max/min are std::max/std::min (ref_max/ref_min).
//   - Batch ordering (PARTICLE_BATCH): heights are frozen during the pass; every amount a droplet
//     moves is rounded once to a count of quanta (roundEven(amount · inverse_quantum)), added to
//     the cell's delta with atomicAdd, and the droplet's sediment is an integer count sat_q with
//     sat = float(sat_q) · quantum. Without interpolation the texel loses the quanta of
//     h - max(h - add, 0) and the droplet gains those of add. The side maps count the quanta the
//     droplet picked up (the corners' summed) and deposited. Colour (PARTICLE_COLOUR) is frozen too:
//     pick-ups read the pass's start colour, and each deposit adds roundEven(factor·2^20) and
//     roundEven((factor·col[ch])·2^20) to the cell's colour sums, which particle_apply.comp turns
//     into the weighted mean of the start colour (weight 1) and the deposits (weights factor).
//   - Colour factors: (1 - f_col) and (1 - factor) are each rounded once; colorize4's weights are
//     erode4's products (bilinear_weights), with the same truncated corner, so they leave [0, 1]
//     within half a texel of x = 0 or y = 0, as upstream.
// All arithmetic is `precise` (no fused multiply-add, no reassociation), in the reference's order,
// so ref<float> repeats it bit for bit. Division and sqrt are GLSL's (not correctly rounded in
// general; correctly rounded on llvmpipe), as in cave/lattice.glsl, and GPUs may flush subnormals
// (a velocity decaying for ~180 steps over a flat stretch gets there): either may part the twins.
// Units: positions and velocities in texels (per step), heights in the caller's units.
// Mutants (compare/mutants/particle.cpp): FALL_THROUGH_ACCELERATION, DEPOSIT_BESIDE,
// CORNER_WEIGHTS_SWAPPED, COLOUR_MIXING_REVERSED, COLOUR_DEPOSIT_UNWEIGHTED (GPU only),
// RESCALED_VELOCITY, KEPT_SEDIMENT_ON_DEPOSIT, UNBOUNDED_EROSION, COLOUR_KEPT_WHOLE (both twins).
// Inputs:  ParticleBlock (uniform binding 0), heights (1), valid (2), with PARTICLE_COLOUR colour (6)
//          (particle_block.glsl); the uniform pass_offset.
// Outputs: heights (1) in place, or delta (3) by atomicAdd (PARTICLE_BATCH); the side maps
//          eroded_at_droplet (4) and deposited_at_droplet (5); colour (6) in place, or colour_sums (7)
//          (PARTICLE_COLOUR with PARTICLE_BATCH).
// Twin:    reference/erosion/particle.cpp.
#include "common/grid.glsl"
#include "erosion/particle_block.glsl"

uniform ivec2 pass_offset;  // (ox, oy) of this pass, each in [0, S)

// Algorithm 4 along one axis (hydra_motion.glsl's accelerated_axis with drop_max; as printed, with
// its if/else-if fall-through, under the mutant).
float accelerated(float speed, float height, float plus_height, float minus_height) {
#ifdef GT_MUTANT_EROSION_PARTICLE_FALL_THROUGH_ACCELERATION
  precise float result = speed;
  precise float plus_drop = height - plus_height;
  precise float minus_drop = height - minus_height;
  if (speed > 0.0 && plus_drop <= max_jump) {
    result = speed + acceleration * plus_drop;
  } else if (minus_drop <= max_jump) {
    result = speed - acceleration * minus_drop;
  }
  return result;
#else
  return accelerated_axis(speed, height, plus_height, minus_height, acceleration, max_jump);
#endif
}

// The amount to erode: bite·(cap - sat) bounded by the height above the neighbourhood minimum.
float erosion_amount(float wanted, float height, float lowest) {
#ifdef GT_MUTANT_EROSION_PARTICLE_UNBOUNDED_EROSION
  precise float amount = wanted;
#else
  precise float above_lowest = height - lowest;
  precise float amount = ref_min(wanted, above_lowest);
#endif
  return amount;
}

// erode4's weights (bilinear_weights, swapped under the mutant).
vec4 corner_weights(vec2 point, ivec2 corner) {
  precise vec4 weights = bilinear_weights(point, corner);
#ifdef GT_MUTANT_EROSION_PARTICLE_CORNER_WEIGHTS_SWAPPED
  weights = weights.xzyw;
#endif
  return weights;
}

// The texel that receives a deposit (beside the droplet under the mutant).
ivec2 deposit_texel(ivec2 texel) {
#ifdef GT_MUTANT_EROSION_PARTICLE_DEPOSIT_BESIDE
  return texel + ivec2(1, 0);
#else
  return texel;
#endif
}

#ifdef PARTICLE_BATCH
// Batch erosion of `amount`: the quanta taken from the cells (into delta) and returned for the
// droplet's sediment. Interpolated: each corner above `lowest` gives the quanta of amount·w_k.
int erode(ivec2 texel, vec2 position, float height, float lowest, float amount) {
  if (interpolated_erosion == 0u) {
    precise float remaining = height - amount;
    precise float lowered = ref_max(remaining, 0.0);
    precise float removed = height - lowered;
    add_quanta(texel, -quanta(removed));
    return quanta(amount);
  }
  precise vec2 point = corner_point(position);
  ivec2 corner = ivec2(point);
  precise vec4 weights = corner_weights(point, corner);
  int taken = 0;
  for (int k = 0; k < 4; ++k) {
    ivec2 cell = corner + corner_offsets[k];
    precise float corner_height = load_height(cell);
    if (corner_height > lowest) {
      precise float share = amount * weights[k];
      int count = quanta(share);
      add_quanta(cell, -count);
      taken = taken + count;
    }
  }
  return taken;
}

// Batch deposition of `amount` at the deposit texel: the quanta added there (and returned).
int deposit(ivec2 texel, float amount) {
  int count = quanta(amount);
  add_quanta(deposit_texel(texel), count);
  return count;
}
#else
// In-place erosion of `amount`: returns what the droplet takes into its sediment.
// Interpolated (erode4): each corner above `lowest` loses amount·w_k; returns amount·Σ w_k.
// At the texel: h becomes max(h - amount, 0); returns amount.
float erode(ivec2 texel, vec2 position, float height, float lowest, float amount) {
  if (interpolated_erosion == 0u) {
    precise float remaining = height - amount;
    precise float lowered = ref_max(remaining, 0.0);
    store_height(texel, lowered);
    return amount;
  }
  precise vec2 point = corner_point(position);
  ivec2 corner = ivec2(point);
  precise vec4 weights = corner_weights(point, corner);
  precise float eroded_weight = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 cell = corner + corner_offsets[k];
    precise float corner_height = load_height(cell);
    if (corner_height > lowest) {
      precise float share = amount * weights[k];
      precise float lowered = corner_height - share;
      store_height(cell, lowered);
      eroded_weight = eroded_weight + weights[k];
    }
  }
  precise float taken = amount * eroded_weight;
  return taken;
}

// In-place deposition of `amount` at the deposit texel (`height` is the droplet texel's).
void deposit(ivec2 texel, float height, float amount) {
  ivec2 target = deposit_texel(texel);
#ifdef GT_MUTANT_EROSION_PARTICLE_DEPOSIT_BESIDE
  precise float target_height = load_height(target);
#else
  precise float target_height = height;
#endif
  precise float raised = target_height + amount;
  store_height(target, raised);
}
#endif

#ifdef PARTICLE_COLOUR
// Eq. 4.9 on erosion: the droplet's colour `col` after picking up the colour of its texel
// (batch: the pass's start colour): f_col·C(ipos) + (1 - f_col)·col.
vec4 picked_up_colour(vec4 col, ivec2 texel) {
  precise vec4 texel_colour = load_colour(texel);
  precise float kept = 1.0 - colour_mixing;
#ifdef GT_MUTANT_EROSION_PARTICLE_COLOUR_MIXING_REVERSED
  precise vec4 mixed = kept * texel_colour + colour_mixing * col;
#else
  precise vec4 mixed = colour_mixing * texel_colour + kept * col;
#endif
  return mixed;
}

// `factor` of the droplet's colour into the cell: C·(1 - factor) + col·factor in place, or (batch)
// a weighted deposit into the cell's colour sums.
void blend_colour(ivec2 cell, float factor, vec4 col) {
#ifdef PARTICLE_BATCH
  add_colour(cell, factor, col);
#else
#ifdef GT_MUTANT_EROSION_PARTICLE_COLOUR_KEPT_WHOLE
  precise float rest = 1.0;
#else
  precise float rest = 1.0 - factor;
#endif
  precise vec4 cell_colour = load_colour(cell);
  precise vec4 blended = cell_colour * rest + col * factor;
  store_colour(cell, blended);
#endif
}

// The colour deposit after a height deposit: colorize4 (Algorithm 8: erode4's corners, factor
// f_col·w, no height condition) or, without interpolation, C(ipos) = C(ipos)·(1 - f_col) + f_col·col.
void deposit_colour(ivec2 texel, vec2 position, vec4 col) {
  if (interpolated_colour != 0u) {
    precise vec2 point = corner_point(position);
    ivec2 corner = ivec2(point);
    precise vec4 weights = bilinear_weights(point, corner);
    for (int k = 0; k < 4; ++k) {
#ifdef GT_MUTANT_EROSION_PARTICLE_COLOUR_DEPOSIT_UNWEIGHTED
      precise float factor = colour_mixing;
#else
      precise float factor = colour_mixing * weights[k];
#endif
      blend_colour(corner + corner_offsets[k], factor, col);
    }
    return;
  }
#ifdef PARTICLE_BATCH
  add_colour(texel, colour_mixing, col);
#else
  precise float kept = 1.0 - colour_mixing;
  precise vec4 cell_colour = load_colour(texel);
  precise vec4 blended = cell_colour * kept + colour_mixing * col;
  store_colour(texel, blended);
#endif
}
#endif

void main() {
  ivec2 droplet = ivec2(gl_GlobalInvocationID.xy);
  if (droplet.x >= droplet_grid.x || droplet.y >= droplet_grid.y) return;
  ivec2 texel = droplet * droplet_spacing + pass_offset;  // ipos
  precise vec2 position = vec2(texel) + vec2(0.5);       // pos
  precise vec2 velocity = vec2(0.0);
#ifdef PARTICLE_BATCH
  int sediment_quanta = 0;  // sat_q
#else
  precise float sediment = 0.0;  // sat
#endif
#ifdef PARTICLE_COLOUR
  precise vec4 carried_colour = load_colour(texel);  // col
#endif
  for (int age = 0; age < lifetime; ++age) {
    // Neighbours n0..n3 at (0,-1), (-1,0), (1,0), (0,1), their extremes, the height under the droplet.
    precise float minus_y = load_height(texel + ivec2(0, -1));
    precise float minus_x = load_height(texel + ivec2(-1, 0));
    precise float plus_x = load_height(texel + ivec2(1, 0));
    precise float plus_y = load_height(texel + ivec2(0, 1));
    precise float highest = ref_max(ref_max(minus_y, minus_x), ref_max(plus_x, plus_y));
    precise float lowest = ref_min(ref_min(minus_y, minus_x), ref_min(plus_x, plus_y));
    precise float height = load_height(texel);

    velocity.x = accelerated(velocity.x, height, plus_x, minus_x);
    velocity.y = accelerated(velocity.y, height, plus_y, minus_y);
    if (height < lowest) velocity = vec2(0.0);  // in a pit: stop
    velocity = vec2(velocity.x * drag, velocity.y * drag);

    precise float speed = sqrt(velocity.x * velocity.x + velocity.y * velocity.y);
    precise vec2 direction = velocity;  // norm
    if (speed != 0.0) direction = vec2(velocity.x / speed, velocity.y / speed);
#ifdef GT_MUTANT_EROSION_PARTICLE_RESCALED_VELOCITY
    if (speed != 0.0) {
#else
    if (speed > max_velocity) {
#endif
      speed = max_velocity;
      velocity = vec2(direction.x * max_velocity, direction.y * max_velocity);
    }
    precise float capacity = capacity_factor * speed;
#ifdef PARTICLE_BATCH
    precise float sediment = float(sediment_quanta) * quantum;
#endif
    precise float difference = capacity - sediment;

    height = load_height(texel);  // re-read, as upstream
    if (difference > 0.0) {
      precise float wanted = difference * bite;
      if (height > lowest) {
        precise float amount = erosion_amount(wanted, height, lowest);
#ifdef PARTICLE_BATCH
        int taken = erode(texel, position, height, lowest, amount);
        sediment_quanta = sediment_quanta + taken;
#else
        precise float taken = erode(texel, position, height, lowest, amount);
        sediment = sediment + taken;
#endif
#ifdef PARTICLE_COLOUR
        carried_colour = picked_up_colour(carried_colour, texel);
#endif
        mark_eroded(texel, taken);
      }
    } else if (height < highest) {
      precise float released = difference * release;
      precise float headroom = highest - height;
      precise float amount = ref_min(-released, headroom);
#ifdef PARTICLE_BATCH
      int deposited = deposit(texel, amount);
#ifndef GT_MUTANT_EROSION_PARTICLE_KEPT_SEDIMENT_ON_DEPOSIT
      sediment_quanta = sediment_quanta - deposited;
#endif
#else
      deposit(texel, height, amount);
#ifndef GT_MUTANT_EROSION_PARTICLE_KEPT_SEDIMENT_ON_DEPOSIT
      sediment = sediment - amount;
#endif
#endif
#ifdef PARTICLE_COLOUR
      deposit_colour(texel, position, carried_colour);
#endif
#ifdef PARTICLE_BATCH
      mark_deposited(texel, deposited);
#else
      mark_deposited(texel, amount);
#endif
    }

#ifdef GT_MUTANT_EROSION_PARTICLE_STEP_BY_VELOCITY
    direction = velocity;  // the step taken by the velocity, not its direction
#endif
    position = vec2(position.x + direction.x, position.y + direction.y);
    texel = ivec2(position);  // truncation
    if (position.x <= 0.0 || position.y <= 0.0) break;
  }
}
