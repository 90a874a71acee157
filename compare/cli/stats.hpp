// `groundtruth stats DEM [--json] [--out DIR] [--cell-size M] [--image-vertical-scale S]
//  [--stream-threshold CELLS]`: the terrain descriptors of compare/descriptors/ on any heightmap the
// loaders accept (issue 16), for ad-hoc use like check-mesh.
//
// Prints a table of the scalar descriptors (or, with as_json, one JSON object {file, format, notes,
// descriptors}) with what the reader decided and what could not be measured and why. With `out`,
// writes DIR/stats.json and DIR/descriptors.png (hypsometric curve, slope distribution, power
// spectrum, Horton plot) atomically, like a report folder. Exit status: 0 something was measured,
// 2 the file cannot be read or nothing at all can be measured (no valid cell, reason on stderr).
#pragma once

#include <filesystem>

namespace gt {

struct StatsOptions {
  bool as_json = false;
  std::filesystem::path out;           // empty: print only
  double cell_size = 0.0;              // > 0 overrides the file's
  double image_vertical_scale = 1.0;   // metres per unit of an 8/16-bit image
  double stream_threshold_cells = 50.0;
};

int stats_command(const std::filesystem::path& file, const StatsOptions& options);

}  // namespace gt
