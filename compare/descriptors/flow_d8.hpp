// D8 flow directions and accumulation (O'Callaghan & Mark 1984).
//
// d8_flow(filled) -> D8Flow
//   filled     Heightmap in metres, normally the output of fill_depressions; cell_size_x/y in
//              metres. On an unfilled DEM every pit is an outlet.
//   receiver   per cell, the index (y·width + x) of the neighbour of steepest descent, the largest
//              drop/distance with distances dx, dy and sqrt(dx² + dy²) from the cell sizes; -1 for
//              a valid cell with no strictly lower valid neighbour (an outlet) and for no-data.
//              Equal slopes: the first in d8_steps' order (E, NE, N, NW, W, SW, S, SE) wins.
//   area_m2    contributing area, the cell's own dx·dy included; 0 for no-data.
//   upstream_length_m  length of the longest D8 flow path from a divide (a cell nothing drains
//              into, where it is 0) to the cell centre, summing centre-to-centre step lengths.
//   order      the valid cells, every cell before its receiver (upstream before downstream).
//   Throws InputError for the grids fill_depressions refuses.
//
// d8_from_receivers(grid, receiver) -> D8Flow
//   The accumulation alone, for receivers from elsewhere (hand-built networks in tests): `grid`
//   gives the size, cell sizes and mask (its values are not read); receiver[i] is -1 or the index
//   of a valid cell, any distance away (a step's length is the distance between the centres).
//   Throws InputError when the sizes differ, a receiver is out of range, no-data gives or
//   receives flow, or the receivers form a cycle.
//
// step_length_m(grid, from, to): distance in metres between the centres of cells `from` and `to`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/grid.hpp"

namespace gt {

struct D8Flow {
  std::vector<std::int64_t> receiver;
  std::vector<double> area_m2;
  std::vector<double> upstream_length_m;
  std::vector<std::int64_t> order;
};

D8Flow d8_flow(const Heightmap& filled);

D8Flow d8_from_receivers(const Heightmap& grid, std::vector<std::int64_t> receiver);

double step_length_m(const Heightmap& grid, std::size_t from, std::size_t to);

}  // namespace gt
