// Global elevation grids (core/io/global_grid.hpp) and their area-weighted relief
// (compare/descriptors/global_relief.hpp): a netCDF file written here with libnetcdf, whose land
// lies north of 30° N, so that its land fraction is (sin 90° - sin 30°) / 2 = 1/4 exactly up to
// the roundings of a few sines and sums (1e-12), and Debian's ETOPO 1° (datasets/fetch.sh).
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compare/descriptors/global_relief.hpp"
#include "core/errors.hpp"
#include "core/io/global_grid.hpp"

namespace gt {
namespace {

namespace fs = std::filesystem;

constexpr double ocean_floor = -4000.0, land = 100.0;
constexpr float fill_value = -1e34f;

struct SyntheticGrid {
  int rows = 18;         // 10° rows, centres -85 .. 85
  int columns = 36;      // 10° columns, centres 5 .. 355 (and 365 with repeat_first_column)
  bool repeat_first_column = false;
  int fill_cells = 0;    // the first cells of row 0 get the fill value
  bool infinite_last = false;  // the last cell is +inf
};

fs::path write_grid(const SyntheticGrid& spec, const std::string& name) {
  const fs::path path = fs::temp_directory_path() / name;
  int file = -1, latitude_dimension = -1, longitude_dimension = -1, latitude = -1, longitude = -1, height = -1;
  const int columns = spec.columns + (spec.repeat_first_column ? 1 : 0);
  EXPECT_EQ(nc_create(path.c_str(), NC_CLOBBER, &file), NC_NOERR);
  nc_def_dim(file, "lat", static_cast<std::size_t>(spec.rows), &latitude_dimension);
  nc_def_dim(file, "lon", static_cast<std::size_t>(columns), &longitude_dimension);
  nc_def_var(file, "lat", NC_DOUBLE, 1, &latitude_dimension, &latitude);
  nc_def_var(file, "lon", NC_DOUBLE, 1, &longitude_dimension, &longitude);
  const int dimensions[2] = {latitude_dimension, longitude_dimension};
  nc_def_var(file, "height", NC_FLOAT, 2, dimensions, &height);
  nc_put_att_text(file, height, "units", 1, "m");
  nc_put_att_float(file, height, "_FillValue", NC_FLOAT, 1, &fill_value);
  nc_enddef(file);
  std::vector<double> latitudes, longitudes;
  for (int row = 0; row < spec.rows; ++row) latitudes.push_back(-85.0 + 10.0 * row);
  for (int column = 0; column < columns; ++column) longitudes.push_back(5.0 + 10.0 * column);
  std::vector<float> heights;
  for (const double centre : latitudes) {
    for (int column = 0; column < columns; ++column) heights.push_back(centre > 30.0 ? float(land) : float(ocean_floor));
  }
  for (int cell = 0; cell < spec.fill_cells; ++cell) heights[static_cast<std::size_t>(cell)] = fill_value;
  if (spec.infinite_last) heights.back() = std::numeric_limits<float>::infinity();
  nc_put_var_double(file, latitude, latitudes.data());
  nc_put_var_double(file, longitude, longitudes.data());
  nc_put_var_float(file, height, heights.data());
  EXPECT_EQ(nc_close(file), NC_NOERR);
  return path;
}

TEST(GlobalGrid, ReadsTheVariableItsCoordinatesAndItsFillValue) {
  const fs::path path = write_grid({.fill_cells = 3}, "gt_global_grid_fill.nc");
  const GlobalGrid grid = read_global_grid(path.string());
  EXPECT_EQ(grid.variable, "height");
  EXPECT_EQ(grid.elevation.width, 36);
  EXPECT_EQ(grid.elevation.height, 18);
  EXPECT_EQ(grid.latitudes.front(), -85.0) << "rows as stored, south first here";
  EXPECT_EQ(grid.elevation.vertical_unit, "m");
  EXPECT_EQ(grid.elevation.valid[2], 0);
  EXPECT_EQ(grid.elevation.valid[3], 1);
  EXPECT_EQ(grid.elevation.values.back(), land);
  fs::remove(path);
}

TEST(GlobalRelief, LandNorthOf30DegreesIsAQuarterOfTheSphere) {
  const fs::path path = write_grid({}, "gt_global_grid_quarter.nc");
  const GlobalRelief relief = global_relief(read_global_grid(path.string()));
  EXPECT_NEAR(relief.land_fraction, 0.25, 1e-12);
  EXPECT_NEAR(relief.valid_area, 4 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(relief.mean, 0.75 * ocean_floor + 0.25 * land, 1e-9);
  EXPECT_EQ(relief.min, ocean_floor);
  EXPECT_EQ(relief.max, land);
  EXPECT_EQ(relief.hypsometry[74], ocean_floor) << "three quarters of the area lie at the ocean floor";
  EXPECT_EQ(relief.hypsometry[76], land);
  EXPECT_EQ(relief.histogram_start, ocean_floor);
  ASSERT_EQ(relief.histogram.size(), 9u) << "bins of 500 m from -4000 m to the bin holding 100 m";
  EXPECT_NEAR(relief.histogram.front(), 0.75, 1e-12);
  EXPECT_NEAR(relief.histogram.back(), 0.25, 1e-12);
  fs::remove(path);
}

TEST(GlobalRelief, ARepeatedWrapColumnCountsOnce) {
  const fs::path path = write_grid({.repeat_first_column = true}, "gt_global_grid_wrap.nc");
  const GlobalRelief relief = global_relief(read_global_grid(path.string()));
  EXPECT_NEAR(relief.valid_area, 4 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(relief.land_fraction, 0.25, 1e-12);
  fs::remove(path);
}

// datasets/real/etopo60.cdf (Debian's ferret-datasets): the figures of ../shared/data-sources.md,
// an area-weighted ocean fraction (below 0 m) of 0.710 given to three digits (so land 0.290 ±
// 0.0005) and the range -7473 .. 5731 m, rounded to metres.
TEST(GlobalRelief, Etopo60HasTheEarthsLandFractionAndRange) {
  const GlobalGrid earth = read_global_grid((fs::path(GT_DATASET_DIR) / "real" / "etopo60.cdf").string());
  EXPECT_EQ(earth.variable, "ROSE");
  EXPECT_EQ(earth.elevation.width, 360);
  EXPECT_EQ(earth.elevation.height, 180);
  EXPECT_EQ(earth.latitudes.front(), -89.5) << "south row first";
  const GlobalRelief relief = global_relief(earth);
  EXPECT_NEAR(relief.land_fraction, 0.290, 0.0005);
  EXPECT_NEAR(relief.min, -7473.0, 0.5);
  EXPECT_NEAR(relief.max, 5731.0, 0.5);
  EXPECT_NEAR(relief.mean, -2388.0, 0.5) << "the mean data-sources.md gives, rounded to metres";
  EXPECT_NEAR(relief.valid_area, 4 * std::numbers::pi, 1e-9);
}

// Sarle's coefficient from its moments: two equal point masses have γ = 0, κ = 1 (b = 1); a uniform
// distribution γ = 0, κ = 9/5 (b = 5/9); equal areas on a fine uniform grid approach it within
// O(1/n²); unequal areas weigh the samples (a 3:1 two-point mass: γ² = 4/3, κ = 7/3, b = 1).
TEST(GlobalRelief, BimodalityCoefficientOfKnownDistributions) {
  EXPECT_DOUBLE_EQ(bimodality_coefficient({{-4000.0, 1.0}, {100.0, 1.0}}), 1.0);
  std::vector<AreaSample> uniform;
  for (int i = 0; i < 1000; ++i) uniform.push_back({(i + 0.5) / 1000.0, 0.25});
  EXPECT_NEAR(bimodality_coefficient(uniform), 5.0 / 9.0, 1e-5);
  EXPECT_DOUBLE_EQ(bimodality_coefficient({{0.0, 3.0}, {1.0, 1.0}}), 1.0);
  EXPECT_EQ(bimodality_coefficient({{2.0, 1.0}, {2.0, 3.0}}), 0.0);
  const GlobalRelief weighted = weighted_relief({{-1.0, 3.0}, {1.0, 1.0}}, 0.0, 3, 1.0);
  EXPECT_DOUBLE_EQ(weighted.land_fraction, 0.25);
  EXPECT_DOUBLE_EQ(weighted.valid_area, 4.0);
}

// Elevations on a lattice (the fault-line planet's Δ·votes) alias with bins that are not a multiple
// of its step: 0.1-wide bins over values 0.08·k hold one or two values by turns. Bins of two steps
// with an edge halfway between two values hold two each, so a flat distribution stays flat.
TEST(GlobalRelief, LatticeElevationsFillBinsOfWholeStepsEvenly) {
  const double step = 0.08;
  std::vector<AreaSample> lattice;
  for (int k = -30; k <= 29; ++k) lattice.push_back({step * k, 1.0});
  const auto spread = [](const GlobalRelief& relief) {
    const auto [least, most] = std::minmax_element(relief.histogram.begin(), relief.histogram.end());
    return *most - *least;
  };
  const GlobalRelief aligned = weighted_relief(lattice, 0.0, 11, 2.0 * step, -step / 2.0);
  EXPECT_EQ(aligned.histogram.size(), 30u);
  EXPECT_NEAR(spread(aligned), 0.0, 1e-15);
  EXPECT_NEAR(aligned.histogram.front(), 2.0 / 60.0, 1e-15);
  EXPECT_GT(spread(weighted_relief(lattice, 0.0, 11, 0.1)), 0.9 / 60.0) << "the aliasing the edge removes";
}

std::string refusal_of(const fs::path& file) {
  try {
    read_global_grid(file.string());
  } catch (const InputError& error) {
    return error.what();
  }
  return "(read without complaint)";
}

TEST(GlobalGrid, RefusesFilesAndVariablesItCannotRead) {
  const fs::path text = fs::temp_directory_path() / "gt_global_grid_not_netcdf.nc";
  std::ofstream(text) << "not a netCDF file\n";
  EXPECT_THROW(read_global_grid(text.string()), InputError);
  fs::remove(text);
  const fs::path path = write_grid({}, "gt_global_grid_names.nc");
  EXPECT_THROW(read_global_grid(path.string(), "ROSE"), InputError) << "no such variable";
  EXPECT_THROW(read_global_grid(path.string(), "lat"), InputError) << "one-dimensional";
  fs::remove(path);
  // An infinite height is an error in the file, not no-data: refused where it lies.
  const fs::path infinite = write_grid({.infinite_last = true}, "gt_global_grid_infinite.nc");
  EXPECT_NE(refusal_of(infinite).find("height is inf at latitude 85°, longitude 355°"), std::string::npos)
      << refusal_of(infinite);
  fs::remove(infinite);
  EXPECT_THROW(global_relief(GlobalGrid{}, 0.0, 1), InputError);
  EXPECT_THROW(global_relief(GlobalGrid{}), InputError) << "no coordinates";
}

// Big-endian 32-bit words, as the classic header spells every number.
std::string words(std::initializer_list<std::uint32_t> values) {
  std::string bytes;
  for (const std::uint32_t value : values) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>(value >> shift & 0xFF);
  }
  return bytes;
}

// libnetcdf allocates what a classic header declares (2^31 variables in 96 bytes crashed it) and
// fills a truncated file's missing data with the fill value: both are refused before it opens them.
TEST(GlobalGrid, HeadersThatDeclareMoreThanTheFileHoldsAreRefused) {
  const fs::path file = fs::temp_directory_path() / "gt_global_grid_hostile.nc";
  const std::string absent = words({0, 0});
  const std::vector<std::pair<std::string, std::string>> headers = {
      {words({0, 0x0A, 0x80000000}), "declares 2147483648 dimensions"},
      {words({0}) + absent + absent + words({0x0B, 0x80000000}), "declares 2147483648 variables"},
      {words({0}) + absent + words({0x0C, 1, 1}) + std::string("a\0\0\0", 4) + words({2, 0x7FFFFFFF}),
       "declares 2147483647 values of attribute a"},
  };
  for (const auto& [body, message] : headers) {
    std::string bytes = "CDF\x01" + body;
    bytes.resize(std::max<std::size_t>(bytes.size(), 96), '\0');
    std::ofstream(file, std::ios::binary) << bytes;
    EXPECT_NE(refusal_of(file).find(message), std::string::npos) << refusal_of(file) << " (want " << message << ")";
  }
  fs::remove(file);

  const fs::path whole = write_grid({}, "gt_global_grid_truncated.nc");
  ASSERT_NO_THROW(read_global_grid(whole.string()));
  fs::resize_file(whole, fs::file_size(whole) * 7 / 10);
  EXPECT_NE(refusal_of(whole).find("truncated: variable"), std::string::npos) << refusal_of(whole);
  fs::remove(whole);
}

}  // namespace
}  // namespace gt
