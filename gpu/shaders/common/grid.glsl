// Grid addressing shared by the compute shaders: row-major cells, x east, y along rows, as
// core/grid.hpp. `grid_size` is (width, height).
// Inputs:  a cell and grid_size.
// Outputs: cell_index (row-major), inside_grid.
// Twin:    core/grid.hpp.
uint cell_index(ivec2 cell, ivec2 grid_size) { return uint(cell.y) * uint(grid_size.x) + uint(cell.x); }

bool inside_grid(ivec2 cell, ivec2 grid_size) {
  return cell.x >= 0 && cell.y >= 0 && cell.x < grid_size.x && cell.y < grid_size.y;
}
