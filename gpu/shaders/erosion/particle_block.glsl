// Buffers, parameters and texel access of seed 000's particle (droplet) erosion (digest 000 §4.4,
// Appendix A): particle_droplets.comp and particle_apply.comp. The uniform block is mirrored by
// ParticleBlock in gpu/erosion/particle.cpp, whose offsets are checked against this block when the program links (GlProgram::check_block).
//
// Texel access emulates Hydra's r32f image: load() of a cell off the grid or masked (valid == 0)
// returns 0, store() there is ignored (GLSL's out-of-bounds imageLoad/imageStore; masked cells
// behave like cells outside). Heights are in the caller's units, positions in texels.
//
// Orderings (core/params/particle.hpp): without PARTICLE_BATCH (race, disjoint) the droplets read
// and write `heights` in place, racing on purpose (no atomics, no barriers inside a pass). With
// PARTICLE_BATCH (batch) the droplets only read `heights` and add what they move, as integer
// counts of `quantum`, into `delta` with atomicAdd; particle_apply.comp adds delta·quantum to the
// heights when the pass ends and clears it.
//
// Side maps (always written): what each droplet eroded and deposited at its texel when open; float
// sums by plain read-modify-write (race, disjoint: Hydra's D.store(ipos, D(ipos) + ...)) or int
// counts of quanta by atomicAdd (batch), no contrast applied.
// Colour (PARTICLE_COLOUR, §4.5): an RGBA map read and written like the heights (off the grid and
// masked: (0, 0, 0, 0), writes lost). Batch: frozen during the pass; the deposits collect in
// `colour_sums`, 5 ints per cell (Σ factor, Σ factor·r, ·g, ·b, ·a in units of 2^-20) by
// atomicAdd, and particle_apply.comp sets C = (C + Σ factor·col·2^-20) / (1 + Σ factor·2^-20).
// Inputs:  declares ParticleBlock (uniform binding 0), heights (1), valid (2), delta (3), the side
//          maps (4, 5), colour (6) and colour_sums (7); local size 8 x 8.
// Outputs: the texel access (open_cell, load_height, store_height, mark_eroded, mark_deposited, the
//          colour's load, store and add) the two passes use.
// Twin:    reference/erosion/particle.cpp (its texel access); host: gpu/erosion/particle.cpp.
#ifndef PARTICLE_BLOCK_GLSL
#define PARTICLE_BLOCK_GLSL

#include "erosion/hydra_motion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform ParticleBlock {
  ivec2 grid_size;             // width, height (texels)
  ivec2 droplet_grid;          // ceil(width / spacing), ceil(height / spacing): droplets per pass
  int droplet_spacing;         // S (subdiv): one droplet per S x S block and pass
  int lifetime;                // steps of one droplet
  uint interpolated_erosion;   // 1: erosion spread bilinearly over 4 texels (Algorithm 6)
  float acceleration;          // a
  float bite;                  // erosion strength
  float release;               // deposition strength
  float max_velocity;          // v_max, texels per step
  float drag;                  // velocity multiplier (1 - UI drag)
  float capacity_factor;       // f_c
  float max_jump;              // drop_max
  float quantum;               // batch: height of one fixed-point unit (a power of two); else 0
  float inverse_quantum;       // batch: 1 / quantum (a power of two); else 0
  float colour_mixing;         // f_col
  uint interpolated_colour;    // 1: colour deposited over 4 texels (colorize4, Algorithm 8)
};

layout(std430, binding = 1) buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };  // 1 = valid, 0 = no data
#ifdef PARTICLE_BATCH
layout(std430, binding = 3) buffer Delta { int delta[]; };  // quanta added to each cell this pass
// Side maps: quanta eroded / deposited by the droplets standing on each cell, over the whole run.
layout(std430, binding = 4) buffer ErodedAtDroplet { int eroded_at_droplet[]; };
layout(std430, binding = 5) buffer DepositedAtDroplet { int deposited_at_droplet[]; };
#else
// Side maps: what the droplets standing on each cell eroded / deposited, over the whole run.
layout(std430, binding = 4) buffer ErodedAtDroplet { float eroded_at_droplet[]; };
layout(std430, binding = 5) buffer DepositedAtDroplet { float deposited_at_droplet[]; };
#endif
#ifdef PARTICLE_COLOUR
layout(std430, binding = 6) buffer Colour { vec4 colour[]; };  // RGBA per cell
#ifdef PARTICLE_BATCH
// Per cell: Σ factor, then Σ factor·colour for r, g, b, a, in units of 2^-20, this pass.
layout(std430, binding = 7) buffer ColourSums { int colour_sums[]; };
#endif
#endif

// Whether a droplet may read and write `cell`: inside the grid and valid.
bool open_cell(ivec2 cell) {
  if (!inside_grid(cell, grid_size)) return false;
  return valid[cell_index(cell, grid_size)] != 0u;
}

// load(): the height of an open cell, 0 elsewhere.
float load_height(ivec2 cell) {
  if (!open_cell(cell)) return 0.0;
  return heights[cell_index(cell, grid_size)];
}

#ifdef PARTICLE_COLOUR
// The colour of an open cell, (0, 0, 0, 0) elsewhere.
vec4 load_colour(ivec2 cell) {
  if (!open_cell(cell)) return vec4(0.0);
  return colour[cell_index(cell, grid_size)];
}
#endif

#ifdef PARTICLE_BATCH
// `amount` as a count of quanta: (amount · inverse_quantum) rounded to nearest, ties to even. The
// product is exact (a power of two) unless it overflows.
int quanta(float amount) {
  precise float scaled = amount * inverse_quantum;
  return int(roundEven(scaled));
}

// Adds `count` quanta to the cell's delta; ignored off the grid and on masked cells, as store().
void add_quanta(ivec2 cell, int count) {
  if (open_cell(cell)) atomicAdd(delta[cell_index(cell, grid_size)], count);
}

// The side maps: `count` quanta eroded / deposited by a droplet standing on `cell`, when open.
void mark_eroded(ivec2 cell, int count) {
  if (open_cell(cell)) atomicAdd(eroded_at_droplet[cell_index(cell, grid_size)], count);
}
void mark_deposited(ivec2 cell, int count) {
  if (open_cell(cell)) atomicAdd(deposited_at_droplet[cell_index(cell, grid_size)], count);
}

#ifdef PARTICLE_COLOUR
// `amount` as a count of 2^-20: roundEven(amount · 2^20), the product exact unless it overflows.
int colour_units(float amount) {
  precise float scaled = amount * 1048576.0;
  return int(roundEven(scaled));
}

// A deposit of `col` with weight `factor` into the cell's colour sums (ignored off the grid and on
// masked cells): the units of factor and of each factor·col[ch], the product rounded to float first.
void add_colour(ivec2 cell, float factor, vec4 col) {
  if (!open_cell(cell)) return;
  uint base = 5u * cell_index(cell, grid_size);
  atomicAdd(colour_sums[base], colour_units(factor));
  for (int ch = 0; ch < 4; ++ch) {
    precise float weighted = factor * col[ch];
    atomicAdd(colour_sums[base + 1u + uint(ch)], colour_units(weighted));
  }
}
#endif
#else
// store(): writes an open cell, ignored elsewhere.
void store_height(ivec2 cell, float height) {
  if (open_cell(cell)) heights[cell_index(cell, grid_size)] = height;
}

// The side maps: `amount` eroded / deposited by a droplet standing on `cell`, when open (read, add,
// write: racing droplets may lose each other's marks, as Hydra's).
void mark_eroded(ivec2 cell, float amount) {
  if (!open_cell(cell)) return;
  uint index = cell_index(cell, grid_size);
  precise float sum = eroded_at_droplet[index] + amount;
  eroded_at_droplet[index] = sum;
}
void mark_deposited(ivec2 cell, float amount) {
  if (!open_cell(cell)) return;
  uint index = cell_index(cell, grid_size);
  precise float sum = deposited_at_droplet[index] + amount;
  deposited_at_droplet[index] = sum;
}

#ifdef PARTICLE_COLOUR
// Writes an open cell's colour, ignored elsewhere.
void store_colour(ivec2 cell, vec4 value) {
  if (open_cell(cell)) colour[cell_index(cell, grid_size)] = value;
}
#endif
#endif

#endif
