// A global elevation grid on latitude-longitude cells, for issue 13's comparison of generated planets
// with the real Earth: ETOPO as Debian's ferret-datasets packages it (etopo60.cdf, etopo20.cdf:
// netCDF-3, variable ROSE in metres, south row first, longitudes from 20° E; datasets/fetch.sh), or
// any netCDF file holding a 2-D variable over latitude and longitude coordinate variables. Read
// with libnetcdf (Debian's libnetcdf-dev), which reads classic, 64-bit-offset and netCDF-4 files.
//
// Output: elevation row r at latitudes[r], column c at longitudes[c], both as stored (no flip, no
// shift), in the variable's own unit (its `units` attribute, "m" when it has none); cells equal to
// the variable's _FillValue or missing_value, or NaN, are no-data. The cell sizes of the Grid are
// the coordinate spacings in degrees (horizontal_unit "degree").
// Throws InputError naming the file for a path that is not a regular file, a classic header whose
// counts exceed the file or whose data is cut short (core/io/netcdf_header.hpp), a file libnetcdf
// cannot open, a variable that is missing or not 2-D, dimensions without coordinate variables, a
// first dimension whose values are not latitudes within [-90, 90] or coordinates that are not
// strictly monotonic, a size beyond the memory limit (core/memory.hpp, estimated before reading),
// an infinite cell (named by its latitude and longitude), or no valid cell.
#pragma once

#include <string>
#include <vector>

#include "core/grid.hpp"

namespace gt {

struct GlobalGrid {
  Grid<double> elevation;
  std::vector<double> latitudes;   // degrees north, cell centres, one per row
  std::vector<double> longitudes;  // degrees east, cell centres, one per column
  std::string variable;            // the variable read
};

// `variable`: the name to read; empty takes the file's only 2-D variable (ROSE in ETOPO).
GlobalGrid read_global_grid(const std::string& path, const std::string& variable = "");

}  // namespace gt
