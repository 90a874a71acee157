#version 450
// Stage 6 of the virtual-pipe erosion with MacCormack transport (Selle et al. 2008), the pass after
// pipes_sediment.comp has written the semi-Lagrangian result φ̂ into sediment (and regolith), per
// cell: φ̌ = φ̂ traced forward, at x + (u, v)·Δt, with the backtrace's bilinear rule; the
// corrected value φ̂ + ½(φ − φ̌), φ what stayed before transport; clamped (the limiter) to the
// least and largest φ of the cell and its 8 neighbours (the reference says why not Selle's four
// corners). Written to corrected
// (regolith_corrected), which the host then swaps with sediment (regolith).
// Inputs:  PipeBlock (uniform binding 0), cells (1), velocity (6), sediment (7: φ̂), staying (8: φ),
//          regolith (12: φ̂), regolith_staying (13: φ) (pipes_block.glsl).
// Outputs: corrected (16), regolith_corrected (17, with REGOLITH).
// Twin:    reference/erosion/pipes.cpp (maccormack_correction).
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"
#include "erosion/pipes_trace.glsl"

layout(std430, binding = 16) writeonly buffer Corrected { float corrected[]; };
layout(std430, binding = 17) writeonly buffer RegolithCorrected { float regolith_corrected[]; };

// The least and largest of `source` over the cell and its 8 neighbours (off the grid or no data:
// the cell's own).
vec2 neighbourhood_range(ivec2 cell, uint index, int source) {
  float lowest = source_at(index, source), highest = lowest;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      float around = corner(cell, index, ivec2(dx, dy), source);
      lowest = ref_min(lowest, around);
      highest = ref_max(highest, around);
    }
  }
  return vec2(lowest, highest);
}

float maccormack(ivec2 cell, uint index, AxisTaps ahead_x, AxisTaps ahead_y, int stayed, int forward) {
  precise float returned = traced(cell, index, ahead_x, ahead_y, forward);
#ifdef GT_MUTANT_EROSION_PIPE_GPU_MACCORMACK_UNHALVED
  precise float correction = source_at(index, stayed) - returned;  // mutant: the ½ left out
#else
  precise float correction = 0.5 * (source_at(index, stayed) - returned);
#endif
#ifdef GT_MUTANT_EROSION_PIPE_MACCORMACK_CORRECTION_NEGATED
  precise float value = source_at(index, forward) - correction;  // mutant: the correction subtracted
#else
  precise float value = source_at(index, forward) + correction;
#endif
  vec2 range = neighbourhood_range(cell, index, stayed);
  return ref_max(range.x, ref_min(range.y, value));
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  if (!cell_valid(cells[index].flags)) return;
  vec2 speed = velocity[index];
  precise float ahead_x = speed.x * backtrace_x;
  precise float ahead_y = speed.y * backtrace_y;
  AxisTaps taps_ahead_x = axis_taps(ahead_x), taps_ahead_y = axis_taps(ahead_y);
  corrected[index] = maccormack(cell, index, taps_ahead_x, taps_ahead_y, from_staying, from_sediment);
#ifdef REGOLITH
  regolith_corrected[index] = maccormack(cell, index, taps_ahead_x, taps_ahead_y, from_regolith_staying, from_regolith);
#endif
}
