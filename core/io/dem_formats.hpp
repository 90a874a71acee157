// Internal to core/io: readers of the DEM files that are not images (vega-datasets volcano JSON,
// matplotlib's sample .npz DEMs), and the helpers shared with the image reader (no-data marking,
// degree-to-metre conversion).
//
// Conventions: every reader returns a HeightmapFile in metres (cells and heights), rows in file
// order, no-data cells stored as 0 with valid = 0, and throws InputError naming the file.
#pragma once

#include <cstddef>
#include <filesystem>

#include "core/io/heightmap_io.hpp"

namespace gt::detail {

HeightmapFile read_volcano_json(const std::filesystem::path& path);

// jacksboro_fault_dem.npz (array `elevation`) or topobathy.npz (array `topo`), told apart by the
// arrays the archive holds.
HeightmapFile read_matplotlib_npz(const std::filesystem::path& path);

// A plain .npy file holding one 2-D array (rows, columns) of '<i2', '<i4', '<f4' or '<f8' (what
// write_heightmap writes, or numpy.save of a DEM): NaN cells become no-data; no cell size is
// stored, so 1 m is assumed and said in the notes.
HeightmapFile read_npy_heightmap(const std::filesystem::path& path);

// Marks cell `index` as no-data: value 0, valid 0 (allocating the mask on first use).
void mark_invalid(Heightmap& heights, std::size_t index);

struct CellSizeMetres {
  double x = 0.0;
  double y = 0.0;
};

// Size in metres of a cell spanning `degrees_longitude` x `degrees_latitude` at `latitude`
// (degrees). Locally flat approximation: 111320 m per degree of longitude at the equator times
// cos(latitude), and 110574 m per degree of latitude (its equatorial value; the true value grows
// to 111229 m at 50 degrees, so cell_y is up to 0.6 % short at mid-latitudes).
CellSizeMetres degrees_to_metres(double degrees_longitude, double degrees_latitude, double latitude);

}  // namespace gt::detail
