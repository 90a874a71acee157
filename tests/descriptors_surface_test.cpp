// Hypsometry, slope and curvature (compare/descriptors/) against closed forms and against GDAL.
#include <cfloat>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "compare/descriptors/distribution.hpp"
#include "compare/descriptors/hypsometry.hpp"
#include "compare/descriptors/surface_derivatives.hpp"
#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

using gt::Heightmap;

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

// A grid whose height at (x east, y north) in metres, measured from cell (cx, cy), is f(x, y);
// cells beyond `radius` metres of the centre are no-data when radius > 0.
template <class Surface>
Heightmap surface_grid(int width, int height, double dx, double dy, Surface f, double radius = 0.0) {
  Heightmap grid(width, height);
  grid.cell_size_x = dx;
  grid.cell_size_y = dy;
  if (radius > 0.0) grid.valid.assign(grid.size(), 1);
  const int cx = width / 2, cy = height / 2;
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const double x = (column - cx) * dx, y = (cy - row) * dy;  // row 0 is north
      grid.at(column, row) = f(x, y);
      if (radius > 0.0 && std::hypot(x, y) > radius) grid.valid[grid.index(column, row)] = 0;
    }
  }
  return grid;
}

TEST(Hypsometry, APlaneHasIntegralOneHalfAndALinearCurve) {
  // Heights 0.5·column: the cells' heights are evenly spaced, so their mean is the midpoint to
  // rounding (a compensated sum of exact halves: within a few ulps of 0.5).
  const auto plane = surface_grid(101, 40, 1.0, 1.0, [](double x, double) { return 0.5 * (x + 50.0); });
  const auto curve = gt::hypsometry(plane, 11);
  EXPECT_NEAR(curve.integral, 0.5, 1e-14);
  // a/A at h/H = k/10 counts columns at or above 5k of 101: exactly (101 - 10k) / 101.
  for (int level = 0; level <= 10; ++level) {
    EXPECT_DOUBLE_EQ(curve.relative_area[level], (101.0 - 10.0 * level) / 101.0) << "level " << level;
  }
  std::size_t histogram_total = 0;
  for (auto count : curve.histogram) histogram_total += count;
  EXPECT_EQ(histogram_total, plane.size());
}

// Over a disc of radius R cells sampled at cell centres, the lowest valid height sits within one
// cell of the rim (an error of at most 1/R of the relief in min) and the mean of any radial
// function differs from its integral over the disc by the rim's cells, a share of about 2/R of them
// whose value is off by at most the relief: together below 1.5/R·(2/3 + 1) < 3/R. The bound is 3/R.
TEST(Hypsometry, AConeHasOneThirdAndAParaboloidOneHalf) {
  const double radius_cells = 150.0;
  const double bound = 3.0 / radius_cells;
  const auto cone = surface_grid(301, 301, 2.0, 2.0,
                                 [](double x, double y) { return 300.0 - std::hypot(x, y); }, 300.0);
  EXPECT_NEAR(gt::hypsometry(cone).integral, 1.0 / 3.0, bound);
  const auto bowl = surface_grid(301, 301, 2.0, 2.0, [](double x, double y) { return x * x + y * y; }, 300.0);
  EXPECT_NEAR(gt::hypsometry(bowl).integral, 0.5, bound);
}

TEST(Hypsometry, FlatAndEmptyTerrainsAreRefusedWithTheReason) {
  Heightmap flat(8, 8, 3.0);
  try {
    gt::hypsometry(flat);
    FAIL() << "a flat terrain has no hypsometry";
  } catch (const gt::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("flat"), std::string::npos) << error.what();
  }
  flat.valid.assign(flat.size(), 0);
  EXPECT_THROW(gt::hypsometry(flat), gt::InputError);
}

// Horn's weighted differences and Zevenbergen & Thorne's second differences are exact on planes and
// on quadratics: only rounding remains, a few ulps of the heights (≤ 1e3 m here) over the spacing.
TEST(SurfaceDerivatives, ExactOnAPlaneWithUnequalSpacing) {
  const double east = 0.3, north = -0.2, dx = 2.0, dy = 5.0;
  const auto plane = surface_grid(20, 15, dx, dy, [&](double x, double y) { return 100.0 + east * x + north * y; });
  const auto derivatives = gt::surface_derivatives(plane);
  const double expected = std::atan(std::hypot(east, north)) * degrees_per_radian;
  for (int y = 1; y + 1 < plane.height; ++y) {
    for (int x = 1; x + 1 < plane.width; ++x) {
      ASSERT_TRUE(derivatives.slope_deg.is_valid(x, y));
      EXPECT_NEAR(derivatives.slope_deg.at(x, y), expected, 1e-10);
      EXPECT_NEAR(derivatives.laplacian_per_m.at(x, y), 0.0, 1e-12);
      EXPECT_NEAR(derivatives.profile_per_m.at(x, y), 0.0, 1e-12);
    }
  }
}

TEST(SurfaceDerivatives, ExactOnAParaboloid) {
  const double k = 0.01, dx = 1.5, dy = 2.5;
  const auto bowl = surface_grid(41, 31, dx, dy, [&](double x, double y) { return k * (x * x + y * y); });
  const auto derivatives = gt::surface_derivatives(bowl);
  for (int row = 1; row + 1 < bowl.height; ++row) {
    for (int column = 1; column + 1 < bowl.width; ++column) {
      const double x = (column - 20) * dx, y = (15 - row) * dy;
      EXPECT_NEAR(derivatives.slope_deg.at(column, row), std::atan(2.0 * k * std::hypot(x, y)) * degrees_per_radian,
                  1e-9);
      EXPECT_NEAR(derivatives.laplacian_per_m.at(column, row), 4.0 * k, 1e-10);
      if (derivatives.profile_per_m.is_valid(column, row)) {
        EXPECT_NEAR(derivatives.profile_per_m.at(column, row), 2.0 * k, 1e-10);
      } else {
        EXPECT_TRUE(x == 0.0 && y == 0.0) << "profile curvature is undefined only where the gradient vanishes";
      }
    }
  }
}

TEST(SurfaceDerivatives, EdgesAndNeighboursOfNoDataHaveNoSlope) {
  auto plane = surface_grid(10, 10, 1.0, 1.0, [](double x, double) { return x; });
  plane.valid.assign(plane.size(), 1);
  plane.valid[plane.index(5, 5)] = 0;
  const auto derivatives = gt::surface_derivatives(plane);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      const bool edge = x == 0 || y == 0 || x == 9 || y == 9;
      const bool touches_hole = std::abs(x - 5) <= 1 && std::abs(y - 5) <= 1;
      EXPECT_EQ(derivatives.slope_deg.is_valid(x, y), !edge && !touches_hole) << x << "," << y;
    }
  }
  EXPECT_THROW(gt::surface_derivatives(Heightmap(2, 9)), gt::InputError);
}

TEST(Distribution, QuantilesInterpolateBetweenOrderStatistics) {
  std::vector<double> values;
  for (int i = 100; i >= 0; --i) values.push_back(i);  // 0..100, unsorted
  const auto distribution = gt::distribution_of(values);
  EXPECT_EQ(distribution.count, 101u);
  EXPECT_DOUBLE_EQ(distribution.mean, 50.0);
  for (double level : gt::quantile_levels()) EXPECT_NEAR(distribution.quantile(level), 100.0 * level, 1e-12);
  EXPECT_THROW(gt::distribution_of({}), gt::InputError);
}

// GDAL's gdaldem slope (Horn, its default) on the same float32 heights as ours, a real DEM with a
// real cell size. GDAL reads the window in float32 and writes float32 degrees. Error model: each
// weighted sum (c + 2f + i) of heights up to max|h| is rounded at most 3 times in float32
// (3·2^-24·4·max|h|), the difference of two sums over 8·spacing gives the gradient's error, atan
// is 1-Lipschitz, and the written angle is rounded once more (2^-24·90°).
TEST(SurfaceDerivatives, SlopeAgreesWithGdaldemOnARealDem) {
  const gt::testing::TemporaryFolder folder("gt_gdaldem");
  auto dem = gt::read_heightmap(std::filesystem::path(GT_DATASET_DIR) / "real" / "jacksboro_fault_dem.npz").heights;
  for (auto& h : dem.values) h = static_cast<float>(h);
  const auto plain = folder.path() / "dem.tif", georeferenced = folder.path() / "dem_geo.tif",
             slope_file = folder.path() / "slope.tif";
  gt::write_heightmap(dem, plain);
  const auto translate = gt::testing::run_program(
      "/usr/bin/gdal_translate",
      {"-q", "-a_ullr", "0", "0", std::to_string(dem.width * dem.cell_size_x), std::to_string(-dem.height * dem.cell_size_y),
       plain.string(), georeferenced.string()});
  ASSERT_EQ(translate.status, 0) << "gdal-bin missing? scripts/install-deps.sh installs it\n" << translate;
  const auto gdaldem = gt::testing::run_program("/usr/bin/gdaldem", {"slope", "-q", georeferenced.string(), slope_file.string()});
  ASSERT_EQ(gdaldem.status, 0) << gdaldem;
  const auto theirs = gt::read_heightmap(slope_file).heights;
  const auto ours = gt::surface_derivatives(dem).slope_deg;
  ASSERT_EQ(theirs.width, dem.width);
  ASSERT_EQ(theirs.height, dem.height);

  double highest = 0.0;
  for (double h : dem.values) highest = std::max(highest, std::abs(h));
  const double unit = std::ldexp(1.0, -24);
  const double gradient_error = 2.0 * 3.0 * unit * 4.0 * highest / (8.0 * std::min(dem.cell_size_x, dem.cell_size_y));
  const double bound = gradient_error * degrees_per_radian + unit * 90.0;
  int compared = 0;
  for (int y = 1; y + 1 < dem.height; ++y) {
    for (int x = 1; x + 1 < dem.width; ++x) {
      if (!ours.is_valid(x, y)) continue;
      ASSERT_NEAR(ours.at(x, y), theirs.at(x, y), bound) << "cell " << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, (dem.width - 2) * (dem.height - 2) / 2);
}

}  // namespace
