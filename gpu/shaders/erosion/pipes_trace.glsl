// Bilinear tracing of the sediment fields along the cell's velocity, shared by the semi-Lagrangian
// pass (pipes_sediment.comp, Mei's backtrace) and MacCormack's correction (pipes_maccormack.comp,
// which also traces forward): linear interpolation weights per axis at a displacement in cells,
// clamped to ±reach, ceil(p) − p and p − floor(p); a corner off the grid or on a no-data cell reads
// the cell being updated. `source` picks the field read: what stayed of s or r before transport
// (staying, regolith_staying) or the semi-Lagrangian result (sediment, regolith).
// Guarded: two pipe passes include it.
// Inputs:  PipeBlock (reach), cells (1), sediment (7), staying (8), regolith (12),
//          regolith_staying (13) (erosion/pipes_block.glsl).
// Outputs: axis_taps(), corner(), traced(): the bilinear value.
// Twin:    reference/erosion/pipes.cpp (axis_taps, traced_sediment).
#ifndef GT_EROSION_PIPES_TRACE_GLSL
#define GT_EROSION_PIPES_TRACE_GLSL

const int from_staying = 0, from_regolith_staying = 1, from_sediment = 2, from_regolith = 3;

struct AxisTaps {
  int low;
  float low_weight;
  float high_weight;
};

// Linear interpolation along one axis at a displacement of `displacement` cells, clamped to
// ±reach; a NaN displacement gives NaN weights (the step check then reports it).
AxisTaps axis_taps(float displacement) {
  if (is_nan_bits(displacement)) {
    float not_a_number = uintBitsToFloat(0x7fc00000u);
    return AxisTaps(0, not_a_number, not_a_number);
  }
  // std::clamp(v, lo, hi) = v < lo ? lo : (hi < v ? hi : v)
  precise float offset = displacement < -reach ? -reach : (reach < displacement ? reach : displacement);
  precise float low = floor(offset);
  precise float high = ceil(offset);
  if (low == high) return AxisTaps(int(low), 1.0, 0.0);
  precise float low_weight = high - offset;
  precise float high_weight = offset - low;
  return AxisTaps(int(low), low_weight, high_weight);
}

float source_at(uint index, int source) {
  if (source == from_staying) return staying[index];
  if (source == from_regolith_staying) return regolith_staying[index];
  if (source == from_sediment) return sediment[index];
  return regolith[index];
}

float corner(ivec2 cell, uint index, ivec2 offset, int source) {
  ivec2 target = cell + offset;
  if (!inside_grid(target, grid_size)) return source_at(index, source);
  uint target_index = cell_index(target, grid_size);
  return cell_valid(cells[target_index].flags) ? source_at(target_index, source) : source_at(index, source);
}

float traced(ivec2 cell, uint index, AxisTaps taps_x, AxisTaps taps_y, int source) {
  ivec2 low = ivec2(taps_x.low, taps_y.low);
  precise float lower_row = taps_x.low_weight * corner(cell, index, low, source) +
                            taps_x.high_weight * corner(cell, index, low + ivec2(1, 0), source);
  precise float upper_row = taps_x.low_weight * corner(cell, index, low + ivec2(0, 1), source) +
                            taps_x.high_weight * corner(cell, index, low + ivec2(1, 1), source);
  precise float value = taps_y.low_weight * lower_row + taps_y.high_weight * upper_row;
  return value;
}

#endif
