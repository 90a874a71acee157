// Readers of the non-image DEM formats: the vega-datasets volcano JSON (nlohmann::json) and
// matplotlib's sample .npz DEMs (libzip for the archive, a small .npy header parser for arrays).
//
// .npy support: format versions 1 to 3, dtypes '<i2' '<i4' '<f4' '<f8', fortran_order False,
// 0-D (matplotlib's scalars dx, dy, ymin, ymax), 1-D and 2-D shapes; anything else is rejected
// with an InputError naming the archive and the member. NaN cells become invalid (value 0).
// Degrees are converted to metres with degrees_to_metres (see dem_formats.hpp).
#include "core/io/dem_formats.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <numbers>
#include <numeric>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <zip.h>

#include "core/errors.hpp"

namespace gt::detail {
namespace {

static_assert(std::endian::native == std::endian::little, "the .npy reader copies little-endian data as is");

using std::filesystem::path;

// vega-datasets: "870 meters by 610 meters ... spacing approximately 10 meters in both directions".
constexpr double volcano_cell_size_m = 10.0;

// ---- volcano JSON ----------------------------------------------------------------------------

nlohmann::json parse_json_file(const path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("cannot open {}", file.string()));
  try {
    return nlohmann::json::parse(in);
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

void read_exact(zip_file_t* member, void* buffer, std::size_t bytes, const std::string& where) {
  const zip_int64_t read = zip_fread(member, buffer, bytes);
  if (read < 0) throw InputError(fmt::format("{}: {}", where, zip_file_strerror(member)));
  if (static_cast<std::size_t>(read) != bytes) {
    throw InputError(fmt::format("{}: truncated ({} of {} bytes)", where, read, bytes));
  }
}

struct NpyHeader {
  std::string descr;
  std::vector<long long> shape;
  std::size_t bytes = 0;  // magic, version, length field and header text
};

std::vector<long long> parse_shape(const std::string& tuple, const std::string& where) {
  std::vector<long long> shape;
  static const std::regex dimension_pattern(R"(\s*([^,\s]+)\s*(,|$))");
  for (auto it = std::sregex_iterator(tuple.begin(), tuple.end(), dimension_pattern); it != std::sregex_iterator();
       ++it) {
    const std::string text = (*it)[1];
    long long dimension = -1;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), dimension);
    if (error != std::errc{} || end != text.data() + text.size() || dimension < 0) {
      throw InputError(fmt::format("{}: bad .npy shape ({})", where, tuple));
    }
    shape.push_back(dimension);
  }
  return shape;
}

std::string header_field(const std::string& header, const std::regex& pattern, const char* key,
                         const std::string& where) {
  std::smatch match;
  if (!std::regex_search(header, match, pattern)) {
    throw InputError(fmt::format("{}: .npy header has no valid '{}': {}", where, key, header));
  }
  return match[1];
}

// The header is a Python dict literal, e.g. {'descr': '<i2', 'fortran_order': False, 'shape': (344, 403), }
NpyHeader read_npy_header(zip_file_t* member, const std::string& where) {
  char preamble[8];  // magic "\x93NUMPY", major and minor version
  read_exact(member, preamble, sizeof preamble, where);
  if (std::string_view(preamble, 6) != "\x93NUMPY") throw InputError(fmt::format("{}: not a .npy array", where));
  const int major_version = static_cast<unsigned char>(preamble[6]);
  if (major_version < 1 || major_version > 3) {
    throw InputError(fmt::format("{}: unsupported .npy format version {}", where, major_version));
  }
  std::uint32_t header_length = 0;  // little-endian uint16 in version 1, uint32 in versions 2 and 3
  const std::size_t length_bytes = major_version == 1 ? 2 : 4;
  read_exact(member, &header_length, length_bytes, where);
  if (header_length > (1u << 20)) throw InputError(fmt::format("{}: .npy header of {} bytes", where, header_length));

  std::string header(header_length, '\0');
  read_exact(member, header.data(), header.size(), where);
  static const std::regex descr_pattern(R"('descr'\s*:\s*'([^']*)')");
  static const std::regex fortran_pattern(R"('fortran_order'\s*:\s*(True|False))");
  static const std::regex shape_pattern(R"('shape'\s*:\s*\(([^)]*)\))");
  if (header_field(header, fortran_pattern, "fortran_order", where) != "False") {
    throw InputError(fmt::format("{}: Fortran-ordered .npy arrays are not supported", where));
  }
  return {header_field(header, descr_pattern, "descr", where),
          parse_shape(header_field(header, shape_pattern, "shape", where), where),
          6 + 2 + length_bytes + header_length};
}

struct NpyArray {
  std::vector<long long> shape;
  std::vector<double> values;
};

template <class T>
std::vector<double> read_npy_values(zip_file_t* member, std::size_t count, const std::string& where) {
  std::vector<T> raw(count);
  read_exact(member, raw.data(), count * sizeof(T), where);
  return {raw.begin(), raw.end()};
}

std::size_t npy_item_size(const std::string& descr, const std::string& where) {
  if (descr == "<i2") return 2;
  if (descr == "<i4" || descr == "<f4") return 4;
  if (descr == "<f8") return 8;
  throw InputError(fmt::format("{}: unsupported .npy dtype '{}' (supported: <i2 <i4 <f4 <f8)", where, descr));
}

std::vector<double> read_npy_data(zip_file_t* member, const std::string& descr, std::size_t count,
                                  const std::string& where) {
  if (descr == "<i2") return read_npy_values<std::int16_t>(member, count, where);
  if (descr == "<i4") return read_npy_values<std::int32_t>(member, count, where);
  if (descr == "<f4") return read_npy_values<float>(member, count, where);
  return read_npy_values<double>(member, count, where);
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

NpyArray read_npy(zip_t* archive, const std::string& key, const path& file) {
  const std::string name = key + ".npy";
  const std::string where = fmt::format("{} (array '{}')", file.string(), key);
  zip_stat_t stat;
  if (zip_stat(archive, name.c_str(), 0, &stat) != 0) {
    throw InputError(fmt::format("{}: missing array '{}'", file.string(), key));
  }
  ZipMember member(zip_fopen(archive, name.c_str(), 0), zip_fclose);
  if (!member) throw InputError(fmt::format("{}: {}", where, zip_strerror(archive)));

  const NpyHeader header = read_npy_header(member.get(), where);
  const std::size_t item_size = npy_item_size(header.descr, where);
  const std::size_t count = checked_element_count(header.shape, where);
  if (stat.size != header.bytes + count * item_size) {
    throw InputError(fmt::format("{}: member holds {} bytes, its header promises {}", where, stat.size,
                                 header.bytes + count * item_size));
  }
  return {header.shape, read_npy_data(member.get(), header.descr, count, where)};
}

double npy_scalar(zip_t* archive, const std::string& key, const path& file) {
  const NpyArray array = read_npy(archive, key, file);
  if (array.values.size() != 1) {
    throw InputError(fmt::format("{}: array '{}' should hold one number, holds {}", file.string(), key,
                                 array.values.size()));
  }
  return array.values.front();
}

std::vector<double> npy_vector(zip_t* archive, const std::string& key, std::size_t length, const path& file) {
  NpyArray array = read_npy(archive, key, file);
  if (array.shape.size() != 1 || array.values.size() != length) {
    throw InputError(fmt::format("{}: array '{}' should be 1-D of length {}", file.string(), key, length));
  }
  return std::move(array.values);
}

// A 2-D array (rows, columns) as a heightmap; NaN cells become invalid.
Heightmap npy_heightmap(zip_t* archive, const std::string& key, const path& file) {
  const NpyArray array = read_npy(archive, key, file);
  if (array.shape.size() != 2 || array.shape[0] < 2 || array.shape[1] < 2) {
    throw InputError(fmt::format("{}: array '{}' should be 2-D with at least 2 rows and columns", file.string(), key));
  }
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

HeightmapFile read_matplotlib_npz(const path& file) {
  const ZipArchive archive = open_zip(file);
  if (has_member(archive.get(), "elevation.npy")) return read_jacksboro(archive.get(), file);
  if (has_member(archive.get(), "topo.npy")) return read_topobathy(archive.get(), file);
  throw InputError(fmt::format(
      "{}: missing array 'elevation' (jacksboro_fault_dem.npz) or 'topo' (topobathy.npz)", file.string()));
}

}  // namespace gt::detail
