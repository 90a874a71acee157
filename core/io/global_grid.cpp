// Global latitude-longitude grids through libnetcdf; see global_grid.hpp.
#include "core/io/global_grid.hpp"

#include <netcdf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/io/netcdf_header.hpp"
#include "core/io/text_file.hpp"
#include "core/memory.hpp"

namespace gt {
namespace {

class NetcdfFile {
 public:
  explicit NetcdfFile(const std::string& path) : path_(path) {
    require_regular_file(path, "");
    detail::check_netcdf_header(path);  // before libnetcdf allocates what the header declares
    const int status = nc_open(path.c_str(), NC_NOWRITE, &id_);
    if (status != NC_NOERR) {
      throw InputError(fmt::format("{}: not a netCDF file libnetcdf can read ({})", path, nc_strerror(status)));
    }
  }
  ~NetcdfFile() { nc_close(id_); }
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;

  int id() const { return id_; }
  const std::string& path() const { return path_; }

  void check(int status, const std::string& doing) const {
    if (status != NC_NOERR) throw InputError(fmt::format("{}: {}: {}", path_, doing, nc_strerror(status)));
  }

 private:
  std::string path_;
  int id_ = -1;
};

int variable_dimensions(const NetcdfFile& file, int variable) {
  int dimensions = 0;
  file.check(nc_inq_varndims(file.id(), variable, &dimensions), "reading a variable's dimensions");
  return dimensions;
}

std::string variable_name(const NetcdfFile& file, int variable) {
  std::array<char, NC_MAX_NAME + 1> name{};
  file.check(nc_inq_varname(file.id(), variable, name.data()), "reading a variable's name");
  return name.data();
}

// The named variable, or the file's only 2-D one.
int find_variable(const NetcdfFile& file, const std::string& name) {
  if (!name.empty()) {
    int variable = -1;
    if (nc_inq_varid(file.id(), name.c_str(), &variable) != NC_NOERR) {
      throw InputError(fmt::format("{}: no variable named {}", file.path(), name));
    }
    return variable;
  }
  int count = 0;
  file.check(nc_inq_nvars(file.id(), &count), "counting variables");
  std::vector<int> grids;
  for (int variable = 0; variable < count; ++variable) {
    if (variable_dimensions(file, variable) == 2) grids.push_back(variable);
  }
  if (grids.size() != 1) {
    throw InputError(fmt::format("{}: {} two-dimensional variables; name the one to read", file.path(), grids.size()));
  }
  return grids.front();
}

std::optional<double> double_attribute(const NetcdfFile& file, int variable, const char* name) {
  double value = 0.0;
  std::size_t length = 0;
  if (nc_inq_attlen(file.id(), variable, name, &length) != NC_NOERR || length != 1) return std::nullopt;
  if (nc_get_att_double(file.id(), variable, name, &value) != NC_NOERR) return std::nullopt;
  return value;
}

std::string text_attribute(const NetcdfFile& file, int variable, const char* name, const std::string& fallback) {
  nc_type type = NC_NAT;
  std::size_t length = 0;
  if (nc_inq_att(file.id(), variable, name, &type, &length) != NC_NOERR || type != NC_CHAR || length == 0) return fallback;
  std::string text(length, '\0');
  file.check(nc_get_att_text(file.id(), variable, name, text.data()), fmt::format("reading attribute {}", name));
  text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
  return text;
}

// The coordinate variable of a dimension (a 1-D variable of the dimension's name), as doubles.
std::vector<double> coordinates(const NetcdfFile& file, int dimension, const std::string& variable) {
  std::array<char, NC_MAX_NAME + 1> name{};
  std::size_t length = 0;
  file.check(nc_inq_dim(file.id(), dimension, name.data(), &length), "reading a dimension");
  int coordinate = -1;
  if (nc_inq_varid(file.id(), name.data(), &coordinate) != NC_NOERR || variable_dimensions(file, coordinate) != 1) {
    throw InputError(fmt::format("{}: dimension {} of {} has no coordinate variable", file.path(), name.data(), variable));
  }
  std::vector<double> values(length);
  file.check(nc_get_var_double(file.id(), coordinate, values.data()), fmt::format("reading coordinates {}", name.data()));
  const bool increasing = std::adjacent_find(values.begin(), values.end(), std::greater_equal<>()) == values.end();
  const bool decreasing = std::adjacent_find(values.begin(), values.end(), std::less_equal<>()) == values.end();
  if (values.size() < 2 || !(increasing || decreasing) ||
      !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
    throw InputError(fmt::format("{}: coordinates {} are not at least two strictly monotonic finite values",
                                 file.path(), name.data()));
  }
  return values;
}

}  // namespace

GlobalGrid read_global_grid(const std::string& path, const std::string& variable_name_wanted) {
  const NetcdfFile file(path);
  const int variable = find_variable(file, variable_name_wanted);
  GlobalGrid grid;
  grid.variable = variable_name(file, variable);
  if (variable_dimensions(file, variable) != 2) {
    throw InputError(fmt::format("{}: variable {} is not two-dimensional (latitude, longitude)", path, grid.variable));
  }
  std::array<int, 2> dimensions{};
  file.check(nc_inq_vardimid(file.id(), variable, dimensions.data()), "reading the variable's dimensions");
  grid.latitudes = coordinates(file, dimensions[0], grid.variable);
  grid.longitudes = coordinates(file, dimensions[1], grid.variable);
  if (!std::all_of(grid.latitudes.begin(), grid.latitudes.end(), [](double v) { return v >= -90.0 && v <= 90.0; })) {
    throw InputError(fmt::format("{}: the first dimension of {} is not latitude: values outside [-90, 90]", path,
                                 grid.variable));
  }
  const double rows = double(grid.latitudes.size()), columns = double(grid.longitudes.size());
  const MemoryEstimate need = memory_for(rows * columns, "cells", 2 * sizeof(double) + 1);
  require_memory(need.bytes, need.basis, path);

  Grid<double>& elevation = grid.elevation;
  elevation.width = static_cast<int>(grid.longitudes.size());
  elevation.height = static_cast<int>(grid.latitudes.size());
  elevation.cell_size_x = std::abs(grid.longitudes[1] - grid.longitudes[0]);
  elevation.cell_size_y = std::abs(grid.latitudes[1] - grid.latitudes[0]);
  elevation.horizontal_unit = "degree";
  elevation.vertical_unit = text_attribute(file, variable, "units", "m");
  elevation.values.resize(grid.latitudes.size() * grid.longitudes.size());
  file.check(nc_get_var_double(file.id(), variable, elevation.values.data()), fmt::format("reading {}", grid.variable));

  const std::optional<double> fill = double_attribute(file, variable, "_FillValue");
  const std::optional<double> missing = double_attribute(file, variable, "missing_value");
  elevation.valid.assign(elevation.values.size(), 1);
  std::size_t valid_cells = 0;
  for (std::size_t cell = 0; cell < elevation.values.size(); ++cell) {
    const double value = elevation.values[cell];
    if (std::isinf(value)) {
      throw InputError(fmt::format("{}: {} is {} at latitude {}°, longitude {}°: a height is finite, and no-data is "
                                   "_FillValue, missing_value or NaN",
                                   path, grid.variable, value, grid.latitudes[cell / grid.longitudes.size()],
                                   grid.longitudes[cell % grid.longitudes.size()]));
    }
    const bool no_data = std::isnan(value) || (fill && value == *fill) || (missing && value == *missing);
    elevation.valid[cell] = no_data ? 0 : 1;
    if (no_data) elevation.values[cell] = 0.0;
    valid_cells += no_data ? 0 : 1;
  }
  if (valid_cells == 0) throw InputError(fmt::format("{}: {} has no valid cell", path, grid.variable));
  return grid;
}

}  // namespace gt
