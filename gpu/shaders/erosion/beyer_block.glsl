// Buffers, parameters and sample access of Beyer's particle (droplet) erosion (seed 000 §2.7,
// digest 000 §3.7): beyer_droplets.comp and beyer_apply.comp. The uniform block is mirrored by
// BeyerBlock in gpu/erosion/beyer.cpp, whose offsets are checked against this block when the program links (GlProgram::check_block).
//
// Heights are samples at integer points (sample (i, j) = cell (i, j), row-major), in the caller's
// units; positions in texels. A droplet only reads and changes samples inside the grid and valid
// (open_cell): its bilinear cell must have four of them (it is off the map otherwise) and the brush
// skips the others, so no access ever leaves the grid.
//
// Orderings (core/params/droplets.hpp): without BEYER_BATCH (race, disjoint) the droplets read
// and write `heights` in place, racing on purpose (no atomics, no barriers inside a pass). With
// BEYER_BATCH (batch) the droplets only read `heights` and add what they move, as integer counts
// of `quantum`, into `delta` with atomicAdd; beyer_apply.comp adds delta·quantum to the heights
// when the pass ends and clears it.
// Inputs:  declares BeyerBlock (uniform binding 0), heights (1), valid (2), delta (3, BEYER_BATCH);
//          local size 8 x 8.
// Outputs: the sample access (open_cell, load_height, store_height, add_quanta, quanta) the two
//          passes use.
// Twin:    reference/erosion/beyer.cpp (its terrain access); host: gpu/erosion/beyer.cpp.
#ifndef BEYER_BLOCK_GLSL
#define BEYER_BLOCK_GLSL

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform BeyerBlock {
  ivec2 grid_size;          // width, height (samples)
  ivec2 droplet_grid;       // ceil(width / spacing), ceil(height / spacing): droplets per pass
  int droplet_spacing;      // S: one droplet per S x S block and pass
  int lifetime;             // steps of one droplet (p_maxPath)
  uint seed;                // of the random compass directions
  uint printed_speed;       // 1: eq. 2.44 as printed (v² + dh·c_g); 0: physical (v² - dh·c_g)
  float inertia;            // c_i (p_inertia)
  float capacity_factor;    // c_c (p_capacity)
  float min_slope;          // c_min (p_minSlope)
  float deposition;         // c_d (p_deposition)
  float erosion;            // c_e of eq. 2.41 (p_erosion)
  float gravity;            // c_g (p_gravity)
  float evaporation;        // c_e of eq. 2.45 (p_evaporation)
  float radius;             // c_r (p_radius), texels
  float initial_speed;      // v_0, texels per step
  float initial_water;      // w_0
  float quantum;            // batch: height of one fixed-point unit (a power of two); else 0
  float inverse_quantum;    // batch: 1 / quantum (a power of two); else 0
};

layout(std430, binding = 1) buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };  // 1 = valid, 0 = no data
#ifdef BEYER_BATCH
layout(std430, binding = 3) buffer Delta { int delta[]; };  // quanta added to each cell this pass
#endif

// std::max(a, b) = a < b ? b : a and std::min(a, b) = b < a ? b : a, signed zeros and NaN as the
// float reference evaluates them (GLSL's max/min leave those cases open).
float ref_max(float a, float b) { return a < b ? b : a; }
float ref_min(float a, float b) { return b < a ? b : a; }

// Whether a droplet may read and change the sample `cell`: inside the grid and valid.
bool open_cell(ivec2 cell) {
  if (!inside_grid(cell, grid_size)) return false;
  return valid[cell_index(cell, grid_size)] != 0u;
}

// The height of an open sample (callers check open_cell first).
float load_height(ivec2 cell) { return heights[cell_index(cell, grid_size)]; }

#ifdef BEYER_BATCH
// `amount` as a count of quanta: (amount · inverse_quantum) rounded to nearest, ties to even. The
// product is exact (a power of two) unless it overflows.
int quanta(float amount) {
  precise float scaled = amount * inverse_quantum;
  return int(roundEven(scaled));
}

// Adds `count` quanta to an open sample's delta.
void add_quanta(ivec2 cell, int count) { atomicAdd(delta[cell_index(cell, grid_size)], count); }
#else
// Writes an open sample.
void store_height(ivec2 cell, float height) { heights[cell_index(cell, grid_size)] = height; }
#endif

#endif
