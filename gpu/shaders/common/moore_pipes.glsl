// The 8 pipes of the Moore neighbourhood along which the 8-neighbour cellular models exchange:
// pipes 0-3 the cardinal (-1,0) (0,1) (1,0) (0,-1), pipes 4-7 the diagonals (-1,-1) (-1,1) (1,1)
// (1,-1), numbered as the references number them.
// Inputs:  included after common/grid.glsl and the includer's `grid_size` (ivec2) and `valid`
//          (uint per cell, 0 = masked) declarations.
// Outputs: pipe_offsets, opposite_pipe(k), pipe_open(cell, k): the neighbour inside the grid and
//          valid (no exchange across the border).
// Twin:    reference/erosion/moore_pipes.hpp; included by erosion/thermal_jako_block.glsl and
//          erosion/dissolution_block.glsl.
const ivec2 pipe_offsets[8] = ivec2[8](ivec2(-1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(0, -1),
                                       ivec2(-1, -1), ivec2(-1, 1), ivec2(1, 1), ivec2(1, -1));

int opposite_pipe(int k) { return k < 4 ? (k + 2) % 4 : 4 + (k - 2) % 4; }

bool pipe_open(ivec2 cell, int k) {
  ivec2 target = cell + pipe_offsets[k];
  return inside_grid(target, grid_size) && valid[cell_index(target, grid_size)] != 0u;
}
