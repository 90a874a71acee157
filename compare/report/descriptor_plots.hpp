// The terrain descriptors as plots (issue 16): the same four panels for `groundtruth stats` and
// for every erosion and terrain case, where before, after and a real DEM share each panel.
//   hypsometric curve   relative height h/H against the share of area at or above it (Strahler 1952)
//   slope distribution  the cumulative share of cells against slope, from the quantiles
//   power spectrum      radially averaged periodogram against frequency, log-log, with the fitted
//                       slope β over its band (dashed)
//   Horton plot         number of Strahler streams against order, log-linear (R_B is the slope)
#pragma once

#include <string>
#include <vector>

#include "compare/descriptors/terrain_descriptors.hpp"
#include "compare/report/plots.hpp"

namespace gt {

struct DescribedTerrain {
  std::string label;                      // e.g. "before", "after (CPU)", "Jacksboro (real)"
  const TerrainDescriptors* descriptors;  // not owned
};

// Panels without any series (nothing measured in any terrain) are left out.
std::vector<SeriesPlot> descriptor_panels(const std::vector<DescribedTerrain>& terrains);

}  // namespace gt
