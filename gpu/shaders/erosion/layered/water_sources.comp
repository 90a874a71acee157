#version 450
// Water sources and sinks on the layered ground (digest 001 §3.19), GPU twin of water_sources in
// reference/erosion/layered/water.cpp: rain w += Δt·rain_rate on iterations below rain_steps (all
// with 0); with the river, the source column's w = river_depth and every sink row's column loses its
// water and what it carries. DRAIN_ALL (the code's "Drain water", run by the host before the sources
// at iteration drain_step): every column a sink, nothing else. One invocation per column, in place.
// Per column it writes 8 floats of `source_record` for the host to count in double: the water before
// the river touched it (the source's and the sinks'), then the 7 carried kinds a sink took. Units:
// metres.
// Inputs:  LayeredBlock (uniform binding 0), LayeredWaterBlock (uniform binding 1) and the water state
//          (10) (water.glsl).
// Outputs: the water state (10) in place; source_record (11): 8 floats per column.
// Twin:    reference/erosion/layered/water.cpp (water_sources).
#include "erosion/layered/water.glsl"

layout(std430, binding = 11) writeonly buffer SourceRecords { float source_record[]; };

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  uint at = water_at(CURRENT, WATER, c);
#ifndef DRAIN_ALL
  precise float rained = water_state[at] + rain_depth;
#ifdef GT_MUTANT_EROSION_LAYERED_GPU_RAIN_PAST_ITS_STEPS
  bool raining = true;  // mutant (this twin alone): rain past rain_steps
#else
  bool raining = rain_steps == 0 || step_number < uint(rain_steps);
#endif
  if (rain_depth > 0.0 && raining) water_state[at] = rained;
  if (river == 0) return;
#endif
  source_record[8u * c] = water_state[at];
  for (int kind = 0; kind < CARRIED_KINDS; ++kind) source_record[8u * c + 1u + uint(kind)] = 0.0;
#ifndef DRAIN_ALL
  if (int(c) == river_source) water_state[at] = river_depth;
  if (cell.y < sink_row_start) return;
#endif
  water_state[at] = 0.0;
  for (int kind = 0; kind < CARRIED_KINDS; ++kind) {
    uint carried = water_at(CURRENT, CARRIED + uint(kind), c);
    source_record[8u * c + 1u + uint(kind)] = water_state[carried];
    water_state[carried] = 0.0;
  }
}
