// Readers of the non-image DEM formats: the vega-datasets volcano JSON (nlohmann::json) and
// matplotlib's sample .npz DEMs (libzip for the archive, core/io/npy.hpp for its arrays, read
// straight from the archive member through a ByteSource).
//
// .npz arrays: npy.hpp's versions and dtypes, 0-D (matplotlib's scalars dx, dy, ymin, ymax), 1-D
// and 2-D shapes (within check_grid_fits); anything else is rejected with an InputError naming the
// archive and the member. NaN cells become invalid (value 0).
// Degrees are converted to metres with degrees_to_metres (see dem_formats.hpp).
#include "core/io/dem_formats.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <zip.h>

#include "core/errors.hpp"
#include "core/io/npy.hpp"
#include "core/io/text_file.hpp"
#include "core/json_keys.hpp"

namespace gt::detail {
namespace {

using std::filesystem::path;

// vega-datasets: "870 meters by 610 meters ... spacing approximately 10 meters in both directions".
constexpr double volcano_cell_size_m = 10.0;

// ---- volcano JSON ----------------------------------------------------------------------------

nlohmann::json parse_json_file(const path& file) {
  std::istringstream in(read_text_file(file, json_document_limits, "heightmap"));
  try {
    return parse_json_bounded(in, file.string());
  } catch (const nlohmann::json::exception& error) {  // syntax errors and numbers out of range
    throw InputError(fmt::format("{}: not valid JSON: {}", file.string(), error.what()));
  }
}

long long json_integer(const nlohmann::json& document, const char* key, const path& file) {
  const auto found = document.find(key);
  if (found == document.end() || !found->is_number_integer()) {
    throw InputError(fmt::format("{}: expected an integer '{}' (volcano format {{width, height, values}})",
                                 file.string(), key));
  }
  return found->get<long long>();
}

const nlohmann::json& json_values(const nlohmann::json& document, long long cells, const path& file) {
  const auto found = document.find("values");
  if (found == document.end() || !found->is_array()) {
    throw InputError(fmt::format("{}: expected an array 'values'", file.string()));
  }
  if (static_cast<long long>(found->size()) != cells) {
    throw InputError(fmt::format("{}: 'values' holds {} numbers, expected width x height = {}", file.string(),
                                 found->size(), cells));
  }
  return *found;
}

// ---- .npz / .npy -----------------------------------------------------------------------------

using ZipArchive = std::unique_ptr<zip_t, decltype(&zip_discard)>;
using ZipMember = std::unique_ptr<zip_file_t, decltype(&zip_fclose)>;

ZipArchive open_zip(const path& file) {
  int error_code = 0;
  zip_t* archive = zip_open(file.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &error_code);
  if (archive == nullptr) {
    zip_error_t error;
    zip_error_init_with_code(&error, error_code);
    const std::string message = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw InputError(fmt::format("{}: not a readable .npz (zip) archive: {}", file.string(), message));
  }
  return {archive, zip_discard};
}

bool has_member(zip_t* archive, const std::string& name) {
  return zip_name_locate(archive, name.c_str(), 0) >= 0;
}

// Elements of `shape`, after checking with check_grid_fits that it fits in memory (the last
// dimension as columns, the rest as rows).
std::size_t checked_element_count(const std::vector<long long>& shape, const std::string& where) {
  if (shape.size() > 2) throw InputError(fmt::format("{}: {}-D arrays are not supported", where, shape.size()));
  if (shape.empty()) return 1;
  const long long columns = shape.back();
  const long long rows = shape.size() == 2 ? shape.front() : 1;
  check_grid_fits(columns, rows, 8, where);
  return static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
}

// The .npy reader's view of an open archive member.
ByteSource member_bytes(zip_file_t* member, const std::string& where) {
  return [member, where](void* destination, std::size_t bytes) {
    const zip_int64_t read = zip_fread(member, destination, bytes);
    if (read < 0) throw InputError(fmt::format("{}: {}", where, zip_file_strerror(member)));
    return static_cast<std::size_t>(read);
  };
}

NpyArray read_npz_array(zip_t* archive, const std::string& key, const path& file) {
  const std::string name = key + ".npy";
  const std::string where = fmt::format("{} (array '{}')", file.string(), key);
  zip_stat_t stat;
  if (zip_stat(archive, name.c_str(), 0, &stat) != 0) {
    throw InputError(fmt::format("{}: missing array '{}'", file.string(), key));
  }
  ZipMember member(zip_fopen(archive, name.c_str(), 0), zip_fclose);
  if (!member) throw InputError(fmt::format("{}: {}", where, zip_strerror(archive)));
  const auto element_count = [&where](const std::vector<long long>& shape) {
    return checked_element_count(shape, where);
  };
  return read_npy(member_bytes(member.get(), where), stat.size, element_count, where);
}

double npy_scalar(zip_t* archive, const std::string& key, const path& file) {
  const NpyArray array = read_npz_array(archive, key, file);
  if (array.values.size() != 1) {
    throw InputError(fmt::format("{}: array '{}' should hold one number, holds {}", file.string(), key,
                                 array.values.size()));
  }
  return array.values.front();
}

std::vector<double> npy_vector(zip_t* archive, const std::string& key, std::size_t length, const path& file) {
  NpyArray array = read_npz_array(archive, key, file);
  if (array.shape.size() != 1 || array.values.size() != length) {
    throw InputError(fmt::format("{}: array '{}' should be 1-D of length {}", file.string(), key, length));
  }
  return std::move(array.values);
}

// A 2-D array (rows, columns), its shape checked by the caller, as a heightmap; NaN cells become
// invalid.
Heightmap heightmap_of(const NpyArray& array) {
  Heightmap heights(static_cast<int>(array.shape[1]), static_cast<int>(array.shape[0]));
  for (std::size_t i = 0; i < array.values.size(); ++i) {
    if (std::isnan(array.values[i])) {
      mark_invalid(heights, i);
    } else {
      heights.values[i] = array.values[i];
    }
  }
  return heights;
}

Heightmap npy_heightmap(zip_t* archive, const std::string& key, const path& file) {
  const NpyArray array = read_npz_array(archive, key, file);
  if (array.shape.size() != 2 || array.shape[0] < 2 || array.shape[1] < 2) {
    throw InputError(fmt::format("{}: array '{}' should be 2-D with at least 2 rows and columns", file.string(), key));
  }
  return heightmap_of(array);
}

void set_geographic_cell_size(HeightmapFile& file, double degrees_longitude, double degrees_latitude,
                              double latitude) {
  const CellSizeMetres cell = degrees_to_metres(degrees_longitude, degrees_latitude, latitude);
  file.heights.cell_size_x = cell.x;
  file.heights.cell_size_y = cell.y;
  file.notes.push_back(fmt::format(
      "cell {:.4g}\" x {:.4g}\" (longitude x latitude) converted to metres at latitude {:.4f}: {:.2f} m x {:.2f} m",
      degrees_longitude * 3600.0, degrees_latitude * 3600.0, latitude, cell.x, cell.y));
}

// jacksboro_fault_dem.npz: elevation int16 (rows, columns), row 0 north; dx and dy are the cell
// size in degrees (1/1200 = 3 arc-seconds), ymin and ymax the latitudes of the first and last row.
HeightmapFile read_jacksboro(zip_t* archive, const path& file) {
  HeightmapFile result;
  result.format = "npz";
  result.heights = npy_heightmap(archive, "elevation", file);
  const double latitude = 0.5 * (npy_scalar(archive, "ymin", file) + npy_scalar(archive, "ymax", file));
  set_geographic_cell_size(result, npy_scalar(archive, "dx", file), npy_scalar(archive, "dy", file), latitude);
  result.notes.push_back("jacksboro_fault_dem: 'elevation' in metres, dx/dy in degrees");
  return result;
}

// topobathy.npz: topo float32 (rows, columns) in metres (negative below sea level); longitude per
// column and latitude per row in degrees. Latitude steps shrink northwards (Mercator rows), so the
// mean step is used and the spread reported in a note.
HeightmapFile read_topobathy(zip_t* archive, const path& file) {
  HeightmapFile result;
  result.format = "npz";
  result.heights = npy_heightmap(archive, "topo", file);
  const Heightmap& heights = result.heights;
  const std::vector<double> longitude = npy_vector(archive, "longitude", heights.width, file);
  const std::vector<double> latitude = npy_vector(archive, "latitude", heights.height, file);

  std::vector<double> latitude_steps(latitude.size());
  std::adjacent_difference(latitude.begin(), latitude.end(), latitude_steps.begin());
  const auto [smallest_step, largest_step] = std::minmax_element(latitude_steps.begin() + 1, latitude_steps.end());
  const double longitude_step = (longitude.back() - longitude.front()) / (heights.width - 1);
  const double latitude_step = std::abs(latitude.back() - latitude.front()) / (heights.height - 1);
  set_geographic_cell_size(result, longitude_step, latitude_step, 0.5 * (latitude.front() + latitude.back()));
  result.notes.push_back(fmt::format(
      "topobathy: latitude steps range over {:.6f}..{:.6f} degrees, their mean is used; row 0 is at latitude "
      "{:.4f}, the last row at {:.4f} (rows kept in file order)",
      std::abs(*smallest_step), std::abs(*largest_step), latitude.front(), latitude.back()));
  return result;
}

}  // namespace

void mark_invalid(Heightmap& heights, std::size_t index) {
  if (heights.valid.empty()) heights.valid.assign(heights.values.size(), 1);
  heights.valid[index] = 0;
  heights.values[index] = 0.0;
}

CellSizeMetres degrees_to_metres(double degrees_longitude, double degrees_latitude, double latitude) {
  constexpr double metres_per_degree_longitude_at_equator = 111320.0;
  constexpr double metres_per_degree_latitude = 110574.0;
  const double latitude_radians = latitude * std::numbers::pi / 180.0;
  return {degrees_longitude * metres_per_degree_longitude_at_equator * std::cos(latitude_radians),
          degrees_latitude * metres_per_degree_latitude};
}

HeightmapFile read_volcano_json(const path& file) {
  const nlohmann::json document = parse_json_file(file);
  if (!document.is_object()) {
    throw InputError(fmt::format("{}: expected a JSON object {{width, height, values}}", file.string()));
  }
  const long long width = json_integer(document, "width", file);
  const long long height = json_integer(document, "height", file);
  check_grid_fits(width, height, 8, file.string());
  const nlohmann::json& values = json_values(document, width * height, file);

  HeightmapFile result;
  result.format = "volcano-json";
  result.heights = Heightmap(static_cast<int>(width), static_cast<int>(height));
  result.heights.cell_size_x = result.heights.cell_size_y = volcano_cell_size_m;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].is_null()) {
      mark_invalid(result.heights, i);
    } else if (values[i].is_number()) {
      result.heights.values[i] = values[i].get<double>();
    } else {
      throw InputError(fmt::format("{}: values[{}] is not a number", file.string(), i));
    }
  }
  result.notes.push_back("volcano JSON: heights in metres, 10 m cells (vega-datasets), null values invalid");
  return result;
}

HeightmapFile read_npy_heightmap(const path& file) {
  const std::string where = file.string();
  const auto element_count = [&where](const std::vector<long long>& shape) {
    if (shape.size() != 2 || shape[0] < 1 || shape[1] < 1) {
      throw InputError(fmt::format("{}: a heightmap .npy is a non-empty 2-D array (rows, columns); this one has "
                                   "shape ({})",
                                   where, fmt::join(shape, ", ")));
    }
    return checked_element_count(shape, where);
  };
  const NpyArray array = read_npy_file(file, element_count, "the heightmap");
  HeightmapFile result;
  result.format = "npy";
  result.heights = heightmap_of(array);
  const auto no_data = std::count(result.heights.valid.begin(), result.heights.valid.end(), 0);
  if (no_data > 0) {
    result.notes.push_back(fmt::format("{} NaN cells of {} taken as no-data and masked: no algorithm reads or "
                                       "changes them",
                                       no_data, array.values.size()));
  }
  result.notes.push_back(fmt::format("no cell size in the file: 1 m assumed (set it with {})", cell_size_settings));
  return result;
}

HeightmapFile read_matplotlib_npz(const path& file) {
  const ZipArchive archive = open_zip(file);
  if (has_member(archive.get(), "elevation.npy")) return read_jacksboro(archive.get(), file);
  if (has_member(archive.get(), "topo.npy")) return read_topobathy(archive.get(), file);
  throw InputError(fmt::format(
      "{}: missing array 'elevation' (jacksboro_fault_dem.npz) or 'topo' (topobathy.npz)", file.string()));
}

}  // namespace gt::detail
