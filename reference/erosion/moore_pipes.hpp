// The 8 pipes of the Moore neighbourhood along which the 8-neighbour cellular models exchange
// material or water (Jákó & Tóth's thermal erosion, Beneš's dissolution erosion), CPU reference.
//
// moore_pipes[k] -> the offset (dx, dy) of pipe k (core/grid.hpp's moore_offsets): pipes 0-3 the
//   cardinal (-1,0) (0,1) (1,0) (0,-1), pipes 4-7 the diagonals (-1,-1) (-1,1) (1,1) (1,-1).
// opposite_pipe(k) -> the pipe of the neighbour that points back at the cell.
// pipe_open(grid, x, y, k) -> whether pipe k of cell (x, y) leads to a cell inside the grid and valid:
//   neighbours outside the grid or masked are absent (no exchange across the border).
//
// Inputs:  a pipe number 0-7; a Grid and a cell of it.
// Outputs: offsets, pipe numbers, whether a pipe is open.
// Units:   cells.
// Throws:  nothing.
// Twin:    gpu/shaders/common/moore_pipes.glsl (included by thermal_jako_block.glsl and
//          dissolution_block.glsl); the users: reference/erosion/thermal_jako.cpp and
//          reference/erosion/dissolution.cpp.
#pragma once

#include <array>

#include "core/grid.hpp"

namespace gt::reference {

inline constexpr const auto& moore_pipes = moore_offsets;  // core/grid.hpp

constexpr int opposite_pipe(int k) { return k < 4 ? (k + 2) % 4 : 4 + (k - 2) % 4; }

template <class Real>
bool pipe_open(const Grid<Real>& grid, int x, int y, int k) {
  const int nx = x + moore_pipes[k].dx;
  const int ny = y + moore_pipes[k].dy;
  return grid.inside(nx, ny) && grid.is_valid(nx, ny);
}

}  // namespace gt::reference
