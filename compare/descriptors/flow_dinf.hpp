// D-infinity flow directions and accumulation (Tarboton 1997).
//
// dinf_flow(filled) -> DinfFlow
//   filled     Heightmap in metres, normally the output of fill_depressions; cell_size_x/y in
//              metres, and they may differ.
//   angle_rad  per cell, the direction of steepest descent over the 8 triangular facets around
//              the cell, in [0, 2π): 0 = east, counter-clockwise, π/2 = north (row − 1). NaN for
//              no-data and for cells without a downslope facet (outlets).
//   area_m2    contributing area in m², the cell's own dx·dy included, 0 for no-data. A cell
//              passes its area to the two neighbours bounding its facet, in proportion to how
//              close the angle is to each: r/r_max to the diagonal one, the rest to the cardinal
//              one (r measured from the cardinal direction, r_max the facet's opening angle).
//   Every cell with flow drains to strictly lower cells, so no area is lost or created: the
//   outlets' areas sum to the valid area (to rounding).
//   Throws InputError for the grids fill_depressions refuses.
#pragma once

#include <vector>

#include "core/grid.hpp"

namespace gt {

struct DinfFlow {
  std::vector<double> angle_rad;
  std::vector<double> area_m2;
};

DinfFlow dinf_flow(const Heightmap& filled);

}  // namespace gt
