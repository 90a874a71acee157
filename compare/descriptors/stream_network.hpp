// Stream network by a drainage-area threshold, its Strahler orders (Strahler 1957), Horton's
// bifurcation and length ratios (Horton 1945) and the drainage density.
//
// stream_network(flow, dem, threshold_area_m2) -> StreamNetwork
//   flow       D8 routing of `dem` (d8_flow or d8_from_receivers).
//   dem        the grid the flow was computed on: its size, cell sizes (m) and mask are used, not
//              its heights.
//   threshold_area_m2  a valid cell is a stream cell when its D8 contributing area is at least
//              this (m², > 0). Receivers of stream cells are stream cells (area grows downstream).
//   strahler   per cell, 0 off the network; 1 for a stream cell no stream cell drains into; else
//              the highest order among its stream donors, plus one when two or more donors have it.
//   max_order  the highest order (0 without stream cells).
//   streams_per_order[w]  N_w, the number of streams of order w ([0] unused, 0). A stream of
//              order w is a maximal chain of cells of order w: it starts at a cell with no donor of
//              order w and ends where it joins a higher order or leaves the grid.
//   mean_length_per_order_m[w]  mean length of the streams of order w: the sum, over a stream's
//              cells, of the D8 step to the receiver (0 at an outlet), so the step into the
//              higher-order stream it joins counts and the step out of the grid does not.
//   bifurcation_ratio  R_B = exp(−slope) of the least-squares line of ln N_w against w over the
//              orders 1..max_order; nullopt with fewer than 2 orders.
//   length_ratio       R_L = exp(slope) of ln(mean L_w) against w, over the orders below the
//              highest (whose streams the grid's edge cuts) whose mean length is positive;
//              nullopt with fewer than 2 such orders.
//   total_length_m     sum of the stream cells' step lengths (m).
//   drainage_density_per_m  total_length_m / valid area (m⁻¹), at the DEM's resolution.
//   Throws InputError when flow and dem differ in size, the threshold is not a positive finite
//   area, or dem is unusable (see check_drainage_dem).
#pragma once

#include <optional>
#include <vector>

#include "compare/descriptors/flow_d8.hpp"
#include "core/grid.hpp"

namespace gt {

struct StreamNetwork {
  double threshold_area_m2 = 0.0;
  std::vector<int> strahler;
  int max_order = 0;
  std::vector<int> streams_per_order;
  std::vector<double> mean_length_per_order_m;
  std::optional<double> bifurcation_ratio;
  std::optional<double> length_ratio;
  double total_length_m = 0.0;
  double drainage_density_per_m = 0.0;
};

StreamNetwork stream_network(const D8Flow& flow, const Heightmap& dem, double threshold_area_m2);

}  // namespace gt
