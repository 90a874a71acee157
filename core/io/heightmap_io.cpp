// read_heightmap / write_heightmap (contract in heightmap_io.hpp): dispatch by extension, image
// pixels through OpenImageIO, GeoTIFF georeferencing through libtiff, writes through a temporary
// file in the target's folder renamed into place.
//
// Conventions
//   - Pixels are read in their stored type, channel 0 only. uint8/uint16 are divided by 255/65535
//     (OpenImageIO's normalisation) and multiplied by image_vertical_scale; every other type
//     (int8/16/32, uint32, half, float, double) keeps its values.
//   - OpenImageIO 2.4 does not expose the GeoTIFF tags, so they are read with libtiff, which
//     registers unknown tags as anonymous fields (count passed as uint32): ModelPixelScale 33550,
//     ModelTiepoint 33922, GeoKeyDirectory 34735, GDAL_NODATA 42113 (ASCII).
//   - Geographic CRS (GTModelTypeGeoKey 1024 == 2, or, without a key directory, a pixel scale
//     under 0.1): the scale is in degrees, converted to metres at the latitude of the grid's
//     centre row (detail::degrees_to_metres). Projected CRS: the scale is taken as metres.
//   - No-data: NaN cells and cells equal to GDAL_NODATA become invalid with value 0.
#include "core/io/heightmap_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <tiffio.h>

#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/dem_formats.hpp"
#include "core/io/npy.hpp"
#include "core/io/text_file.hpp"

namespace gt {
namespace {

// The note of a reader that found no cell size.
const std::string cell_size_assumed = fmt::format("1 m assumed (set it with {})", cell_size_settings);

using std::filesystem::path;

std::string lower_extension(const path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// ---- GeoTIFF tags (libtiff) --------------------------------------------------------------------

constexpr std::uint32_t model_pixel_scale_tag = 33550;
constexpr std::uint32_t model_tiepoint_tag = 33922;
constexpr std::uint32_t geo_key_directory_tag = 34735;
constexpr std::uint32_t gdal_nodata_tag = 42113;
constexpr std::uint16_t model_type_geo_key = 1024;
constexpr std::uint16_t projected_linear_units_geo_key = 3076;
constexpr int model_type_geographic = 2;
constexpr int linear_unit_metre = 9001;

struct GeoTiffTags {
  std::vector<double> pixel_scale;        // (x, y, z) in CRS units per pixel
  std::vector<double> tiepoint;           // (i, j, k, x, y, z): raster (i, j) lies at CRS (x, y)
  std::vector<std::uint16_t> geo_keys;    // header (version, revision, minor, count), then keys
  std::optional<std::string> no_data;     // GDAL's decimal text of the no-data value

  bool georeferenced() const { return !pixel_scale.empty() || no_data.has_value(); }
};

// Appends libtiff's error message to the std::string at `messages`.
int collect_tiff_error(TIFF*, void* messages, const char* module, const char* format, va_list args) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, args);
  std::string& collected = *static_cast<std::string*>(messages);
  collected += fmt::format("{}{}: {}", collected.empty() ? "" : "; ", module ? module : "libtiff", text);
  return 1;
}

// Unknown-tag warnings are expected: every GeoTIFF tag is unknown to libtiff.
int ignore_tiff_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

// Values of an array tag stored as `type`; empty when the file lacks the tag. libtiff passes the
// count of a tag it does not know as 32 bits; where libgeotiff registered the GeoTIFF tags in this
// process (GDAL loaded beside us, e.g. by rasterio in a Python session) as 16 bits.
template <class T>
std::vector<T> tiff_array_tag(TIFF* tiff, std::uint32_t tag, TIFFDataType type, const path& file) {
  const TIFFField* field = TIFFFindField(tiff, tag, TIFF_ANY);
  if (field == nullptr) return {};
  const int count_size = TIFFFieldSetGetCountSize(field);
  if (TIFFFieldDataType(field) != type || !TIFFFieldPassCount(field) || (count_size != 2 && count_size != 4)) {
    throw InputError(fmt::format("{}: TIFF tag {} has an unexpected type or layout", file.string(), tag));
  }
  T* data = nullptr;
  std::uint32_t count = 0;
  if (count_size == 2) {
    std::uint16_t short_count = 0;
    if (!TIFFGetField(tiff, tag, &short_count, &data)) return {};
    count = short_count;
  } else if (!TIFFGetField(tiff, tag, &count, &data)) {
    return {};
  }
  if (data == nullptr) return {};
  return {data, data + count};
}

// The text of an ASCII tag, nullopt when the file lacks it. libtiff passes a tag it does not know
// with its count; one GDAL registered in this process (its GDAL_NODATA) as a C string, which
// libtiff ends with a NUL on reading.
std::optional<std::string> tiff_text_tag(TIFF* tiff, std::uint32_t tag, const path& file) {
  const TIFFField* field = TIFFFindField(tiff, tag, TIFF_ANY);
  if (field == nullptr) return std::nullopt;
  if (TIFFFieldPassCount(field)) {
    const std::vector<char> text = tiff_array_tag<char>(tiff, tag, TIFF_ASCII, file);
    if (text.empty()) return std::nullopt;
    return std::string(text.begin(), std::find(text.begin(), text.end(), '\0'));
  }
  if (TIFFFieldDataType(field) != TIFF_ASCII) {
    throw InputError(fmt::format("{}: TIFF tag {} has an unexpected type or layout", file.string(), tag));
  }
  const char* text = nullptr;
  if (!TIFFGetField(tiff, tag, &text) || text == nullptr || *text == '\0') return std::nullopt;
  return std::string(text);
}

// A TIFF names where its pixel data lie (strip or tile offsets and byte counts); OpenImageIO reads
// whatever the header declares and prints an error per missing strip (4 MB of stderr for a 200-byte
// file declaring 37000² pixels). Refused here: a strip or tile that is empty or runs past the end of
// the file, and uncompressed data shorter than the pixels it must hold.
void check_tiff_data_in_file(TIFF* tiff, const path& file) {
  const std::uintmax_t file_size = std::filesystem::file_size(file);
  const bool tiled = TIFFIsTiled(tiff) != 0;
  const std::uint32_t chunks = tiled ? TIFFNumberOfTiles(tiff) : TIFFNumberOfStrips(tiff);
  std::uint64_t* offsets = nullptr;
  std::uint64_t* byte_counts = nullptr;
  if (!TIFFGetField(tiff, tiled ? TIFFTAG_TILEOFFSETS : TIFFTAG_STRIPOFFSETS, &offsets) ||
      !TIFFGetField(tiff, tiled ? TIFFTAG_TILEBYTECOUNTS : TIFFTAG_STRIPBYTECOUNTS, &byte_counts) || offsets == nullptr ||
      byte_counts == nullptr) {
    throw InputError(fmt::format("{}: the TIFF names no {} offsets or byte counts", file.string(), tiled ? "tile" : "strip"));
  }
  std::uint64_t stored = 0;
  for (std::uint32_t chunk = 0; chunk < chunks; ++chunk) {
    if (byte_counts[chunk] == 0 || offsets[chunk] > file_size || byte_counts[chunk] > file_size - offsets[chunk]) {
      throw InputError(fmt::format("{}: TIFF {} {} of {} ({} bytes at offset {}) is empty or runs past the end of "
                                   "the {}-byte file: the header declares more data than the file holds",
                                   file.string(), tiled ? "tile" : "strip", chunk, chunks, byte_counts[chunk],
                                   offsets[chunk], file_size));
    }
    stored += byte_counts[chunk];
  }
  std::uint16_t compression = COMPRESSION_NONE;
  TIFFGetFieldDefaulted(tiff, TIFFTAG_COMPRESSION, &compression);
  // Tiles are stored whole, edge tiles included; strips hold the image's rows, the last one short.
  std::uint32_t rows = 0;
  std::uint16_t planar = PLANARCONFIG_CONTIG, samples = 1;
  TIFFGetField(tiff, TIFFTAG_IMAGELENGTH, &rows);
  TIFFGetFieldDefaulted(tiff, TIFFTAG_PLANARCONFIG, &planar);
  TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLESPERPIXEL, &samples);
  const double planes = planar == PLANARCONFIG_SEPARATE ? samples : 1.0;
  const double pixel_bytes = tiled ? static_cast<double>(TIFFTileSize64(tiff)) * chunks
                                   : static_cast<double>(TIFFVStripSize64(tiff, rows)) * planes;
  if (compression == COMPRESSION_NONE && static_cast<double>(stored) < pixel_bytes) {
    throw InputError(fmt::format("{}: uncompressed TIFF stores {} bytes of pixels, fewer than the {:.0f} its size "
                                 "declares",
                                 file.string(), stored, pixel_bytes));
  }
}

GeoTiffTags read_geotiff_tags(const path& file) {
  std::string errors;
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, collect_tiff_error, &errors);
  TIFFOpenOptionsSetWarningHandlerExtR(options, ignore_tiff_warning, nullptr);
  const std::unique_ptr<TIFF, decltype(&TIFFClose)> tiff(TIFFOpenExt(file.c_str(), "r", options), TIFFClose);
  TIFFOpenOptionsFree(options);
  if (!tiff) throw InputError(fmt::format("cannot open {} as TIFF: {}", file.string(), errors));

  check_tiff_data_in_file(tiff.get(), file);
  GeoTiffTags tags;
  tags.pixel_scale = tiff_array_tag<double>(tiff.get(), model_pixel_scale_tag, TIFF_DOUBLE, file);
  tags.tiepoint = tiff_array_tag<double>(tiff.get(), model_tiepoint_tag, TIFF_DOUBLE, file);
  tags.geo_keys = tiff_array_tag<std::uint16_t>(tiff.get(), geo_key_directory_tag, TIFF_SHORT, file);
  tags.no_data = tiff_text_tag(tiff.get(), gdal_nodata_tag, file);
  if (!tags.pixel_scale.empty() && tags.pixel_scale.size() < 2) {
    throw InputError(fmt::format("{}: ModelPixelScale holds {} values, expected 3", file.string(),
                                 tags.pixel_scale.size()));
  }
  return tags;
}

// Value of a GeoKey stored inline in the key directory.
std::optional<int> geo_key(const std::vector<std::uint16_t>& directory, std::uint16_t key) {
  if (directory.size() < 4) return std::nullopt;
  const std::size_t key_count = std::min<std::size_t>(directory[3], (directory.size() - 4) / 4);
  for (std::size_t k = 0; k < key_count; ++k) {
    const std::uint16_t* entry = &directory[4 + 4 * k];  // id, tag location, count, value
    if (entry[0] == key && entry[1] == 0) return entry[3];
  }
  return std::nullopt;
}

std::optional<double> parse_no_data(const GeoTiffTags& tags, std::vector<std::string>& notes) {
  if (!tags.no_data) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(tags.no_data->c_str(), &end);
  if (end == tags.no_data->c_str()) {
    notes.push_back(fmt::format("GDAL_NODATA '{}' is not a number; ignored", *tags.no_data));
    return std::nullopt;
  }
  return value;
}

bool is_geographic(const GeoTiffTags& tags, std::vector<std::string>& notes) {
  if (const auto model_type = geo_key(tags.geo_keys, model_type_geo_key)) return *model_type == model_type_geographic;
  const bool small_scale = tags.pixel_scale[0] < 0.1 && tags.pixel_scale[1] < 0.1;
  notes.push_back(fmt::format("no GTModelTypeGeoKey: pixel scale {} taken as {}", tags.pixel_scale[0],
                              small_scale ? "degrees (under 0.1)" : "metres"));
  return small_scale;
}

void apply_geographic_cell_size(HeightmapFile& file, const GeoTiffTags& tags) {
  Heightmap& heights = file.heights;
  const double scale_x = tags.pixel_scale[0];
  const double scale_y = tags.pixel_scale[1];
  if (tags.tiepoint.size() < 6) {
    heights.cell_size_x = scale_x;
    heights.cell_size_y = scale_y;
    heights.horizontal_unit = "deg";
    file.notes.push_back("geographic GeoTIFF without ModelTiepoint: cell size left in degrees");
    return;
  }
  const double centre_latitude = tags.tiepoint[4] - (0.5 * heights.height - tags.tiepoint[1]) * scale_y;
  const detail::CellSizeMetres cell = detail::degrees_to_metres(scale_x, scale_y, centre_latitude);
  heights.cell_size_x = cell.x;
  heights.cell_size_y = cell.y;
  file.notes.push_back(fmt::format(
      "geographic CRS: pixel {:.4g}\" x {:.4g}\" converted to metres at centre latitude {:.4f}: {:.2f} m x {:.2f} m",
      scale_x * 3600.0, scale_y * 3600.0, centre_latitude, cell.x, cell.y));
}

void apply_georeferencing(HeightmapFile& file, const GeoTiffTags& tags) {
  if (tags.pixel_scale.empty()) {
    file.notes.push_back("no ModelPixelScale: " + cell_size_assumed);
    return;
  }
  if (is_geographic(tags, file.notes)) {
    apply_geographic_cell_size(file, tags);
    return;
  }
  file.heights.cell_size_x = tags.pixel_scale[0];
  file.heights.cell_size_y = tags.pixel_scale[1];
  const auto linear_unit = geo_key(tags.geo_keys, projected_linear_units_geo_key);
  file.notes.push_back(linear_unit && *linear_unit != linear_unit_metre
                           ? fmt::format("projected CRS with linear unit code {}: pixel scale not converted", *linear_unit)
                           : "projected CRS: pixel scale taken as metres");
}

}  // namespace

// ---- EXR header (before OpenEXR) ---------------------------------------------------------------
// OpenEXR 3.1 allocates each header attribute at the size the file declares before reading it (a
// 600-byte file asked for 1.9 GB: found by fuzzing). The header is a list of attributes, each a
// name and a type (null-terminated) and an int32 size, ended by an empty name; every size must
// fit in the bytes that follow.
void check_exr_attribute_sizes(const path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char magic[4] = {};
  in.read(reinterpret_cast<char*>(magic), 4);
  if (!in || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01) return;  // not EXR
  const std::uintmax_t file_size = std::filesystem::file_size(file);
  in.seekg(8);  // magic and version
  std::string name, type;
  while (std::getline(in, name, '\0') && !name.empty() && std::getline(in, type, '\0')) {
    unsigned char size_bytes[4] = {};
    in.read(reinterpret_cast<char*>(size_bytes), 4);
    const std::uint32_t size = std::uint32_t{size_bytes[0]} | (std::uint32_t{size_bytes[1]} << 8) |
                               (std::uint32_t{size_bytes[2]} << 16) | (std::uint32_t{size_bytes[3]} << 24);
    const std::streamoff position = in.tellg();
    if (!in || position < 0 || size > file_size - static_cast<std::uintmax_t>(position)) {
      throw InputError(fmt::format("{}: EXR header attribute '{}' declares {} bytes, more than the file holds",
                                   file.string(), name.substr(0, 64), size));
    }
    in.seekg(size, std::ios::cur);
  }
}

namespace {

// ---- pixels (OpenImageIO) ----------------------------------------------------------------------

template <class T>
bool is_no_data(T value, const std::optional<double>& no_data) {
  if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(value)) return true;
  }
  return no_data && static_cast<double>(value) == *no_data;
}

// Channel 0 read as `type` into T, times `scale`; NaN and no-data cells become invalid.
template <class T>
Heightmap read_channel0(OIIO::ImageInput& input, OIIO::TypeDesc type, double scale,
                        const std::optional<double>& no_data, const path& file) {
  const OIIO::ImageSpec& spec = input.spec();
  std::vector<T> raw(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height));
  const bool read = input.read_image(0, 0, 0, 1, type, raw.data());
  // The TIFF reader reports a truncated strip through geterror() but still returns true.
  const std::string error = input.geterror();
  if (!read || !error.empty()) throw InputError(fmt::format("{}: cannot read pixels: {}", file.string(), error));
  Heightmap heights(spec.width, spec.height);
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (is_no_data(raw[i], no_data)) {
      detail::mark_invalid(heights, i);
    } else {
      heights.values[i] = static_cast<double>(raw[i]) * scale;
    }
  }
  return heights;
}

// An 8/16-bit image's channel 0 as [0, 1] values (value / largest), sRGB-decoded when asked, times
// the vertical scale.
template <class T>
Heightmap read_unsigned_image(OIIO::ImageInput& input, const HeightmapReadOptions& options,
                              const std::optional<double>& no_data, std::vector<std::string>& notes, const path& file) {
  const double largest = static_cast<double>(std::numeric_limits<T>::max());
  notes.push_back(fmt::format("{}-bit image: value / {}{} x image_vertical_scale ({})", 8 * sizeof(T), largest,
                              options.srgb ? ", sRGB-decoded (seed 000 Algorithm 2)," : "",
                              options.image_vertical_scale));
  if (!options.srgb) {
    return read_channel0<T>(input, input.spec().format, options.image_vertical_scale / largest, no_data, file);
  }
  Heightmap heights = read_channel0<T>(input, input.spec().format, 1.0 / largest, no_data, file);
  for (double& value : heights.values) value = srgb_to_linear(value) * options.image_vertical_scale;
  return heights;
}

Heightmap read_pixels(OIIO::ImageInput& input, const HeightmapReadOptions& options,
                      const std::optional<double>& no_data, std::vector<std::string>& notes, const path& file) {
  using OIIO::TypeDesc;
  const TypeDesc stored = input.spec().format;
  switch (stored.basetype) {
    case TypeDesc::UINT8:
      return read_unsigned_image<std::uint8_t>(input, options, no_data, notes, file);
    case TypeDesc::UINT16:
      return read_unsigned_image<std::uint16_t>(input, options, no_data, notes, file);
    case TypeDesc::INT8:
      return read_channel0<std::int8_t>(input, stored, 1.0, no_data, file);
    case TypeDesc::INT16:
      notes.push_back("int16 samples kept as they are (metres)");
      return read_channel0<std::int16_t>(input, stored, 1.0, no_data, file);
    case TypeDesc::INT32:
      return read_channel0<std::int32_t>(input, stored, 1.0, no_data, file);
    case TypeDesc::UINT32:
      return read_channel0<std::uint32_t>(input, stored, 1.0, no_data, file);
    case TypeDesc::HALF:
    case TypeDesc::FLOAT:
      return read_channel0<float>(input, TypeDesc::FLOAT, 1.0, no_data, file);
    case TypeDesc::DOUBLE:
      return read_channel0<double>(input, TypeDesc::DOUBLE, 1.0, no_data, file);
    default:
      throw InputError(fmt::format("{}: unsupported pixel type {}", file.string(), stored.c_str()));
  }
}

std::string format_label(const std::string& oiio_format, const GeoTiffTags& tags) {
  if (oiio_format == "openexr") return "exr";
  if (oiio_format == "tiff" && tags.georeferenced()) return "geotiff";
  return oiio_format;
}

// Refuses a colour image as a heightmap unless its red channel is asked for: reads the first three
// channels as float (12 bytes a pixel, counted by the caller's size check) and counts the pixels
// whose channels differ. A grey picture stored as RGB passes.
void check_grey(OIIO::ImageInput& input, const HeightmapReadOptions& options, std::vector<std::string>& notes,
                const path& file) {
  const OIIO::ImageSpec& spec = input.spec();
  if (spec.nchannels < 3) return;
  if (options.red_channel) {
    notes.push_back("colour image: its red channel taken as height (seed 000 §4.2, `red_channel`)");
    return;
  }
  std::vector<float> rgb(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) * 3);
  if (!input.read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data())) {
    throw InputError(fmt::format("{}: cannot read pixels: {}", file.string(), input.geterror()));
  }
  std::size_t coloured = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3) coloured += rgb[i] != rgb[i + 1] || rgb[i + 1] != rgb[i + 2] ? 1 : 0;
  if (coloured == 0) return;
  throw InputError(fmt::format(
      "{} is a colour image, not a heightmap: its red, green and blue differ in {} of {} pixels; to take its red "
      "channel as height, as seed 000 §4.2 does with a picture, set \"red_channel\": true on the case's input (ad-hoc "
      "runs: --red-channel)",
      file.string(), coloured, rgb.size() / 3));
}

HeightmapFile read_image(const path& file, const HeightmapReadOptions& options) {
  check_exr_attribute_sizes(file);
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // channel 0 as stored, not multiplied by alpha
  const auto input = OIIO::ImageInput::open(file.string(), &config);
  if (!input) throw InputError(fmt::format("cannot open {}: {}", file.string(), OIIO::geterror()));
  const OIIO::ImageSpec& spec = input->spec();

  HeightmapFile result;
  const bool is_tiff = std::string(input->format_name()) == "tiff";
  const GeoTiffTags tags = is_tiff ? read_geotiff_tags(file) : GeoTiffTags{};
  // While reading: OpenImageIO's decoded image (PNG keeps it whole; every channel in its stored
  // type), channel 0 converted (at most 8 bytes), the heights (8) and the no-data mask (1); before,
  // a colour image's three channels as float (12) for check_grey.
  check_grid_fits(spec.width, spec.height, 17 + static_cast<long long>(spec.nchannels) * spec.format.size(),
                  file.string());
  result.format = format_label(input->format_name(), tags);
  check_grey(*input, options, result.notes, file);
  if (spec.nchannels > 1) {
    result.notes.push_back(fmt::format("{} channels: channel 0 ({}) used as height", spec.nchannels,
                                       spec.channel_name(0)));
  }
  const std::optional<double> no_data = parse_no_data(tags, result.notes);
  result.heights = read_pixels(*input, options, no_data, result.notes, file);
  const std::size_t masked = result.heights.size() - count_valid(result.heights);
  if (no_data) {
    result.notes.push_back(fmt::format("GDAL_NODATA {}: {} cells invalid (NaN cells included), masked: no algorithm "
                                       "reads or changes them",
                                       *no_data, masked));
  } else if (masked > 0) {
    result.notes.push_back(fmt::format("{} NaN cells of {} taken as no-data (GDAL's convention) and masked: no "
                                       "algorithm reads or changes them",
                                       masked, result.heights.size()));
  }
  if (is_tiff && tags.georeferenced()) {
    apply_georeferencing(result, tags);
  } else {
    result.notes.push_back("no cell size in the file: " + cell_size_assumed);
  }
  return result;
}

void apply_cell_size_override(HeightmapFile& file, double cell_size, double cell_size_y) {
  if (!(cell_size > 0.0)) return;
  file.heights.cell_size_x = cell_size;
  file.heights.cell_size_y = cell_size_y > 0.0 ? cell_size_y : cell_size;
  file.heights.horizontal_unit = "m";
  // The caller's size replaces what a reader assumed for want of one in the file.
  std::erase_if(file.notes, [](const std::string& note) { return note.find("1 m assumed") != std::string::npos; });
  file.notes.push_back(file.heights.cell_size_y == cell_size
                           ? fmt::format("cell size set to {} m by the caller", cell_size)
                           : fmt::format("cell size set to {} m (x, columns) by {} m (y, rows) by the caller",
                                         cell_size, file.heights.cell_size_y));
}

// ---- writing -----------------------------------------------------------------------------------

// The heights as `Value`s, invalid cells NaN.
template <typename Value>
std::vector<Value> pixels_of(const Heightmap& heights) {
  std::vector<Value> pixels(heights.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    pixels[i] = heights.is_valid(i) ? static_cast<Value>(heights.values[i]) : std::numeric_limits<Value>::quiet_NaN();
  }
  return pixels;
}

// Valid heights mapped linearly from [min, max] to 0..65535; invalid cells 0.
std::vector<std::uint16_t> png16_levels(const Heightmap& heights) {
  const auto [lowest, highest] = valid_range(heights);
  const double step = highest > lowest ? (highest - lowest) / 65535.0 : 1.0;
  std::vector<std::uint16_t> levels(heights.size(), 0);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (heights.is_valid(i)) levels[i] = static_cast<std::uint16_t>(std::lround((heights.values[i] - lowest) / step));
  }
  return levels;
}

void write_single_channel(const path& file, OIIO::TypeDesc type, int width, int height, const void* pixels) {
  OIIO::ImageSpec spec(width, height, 1, type);
  spec.channelnames = {"Y"};
  write_image_atomically(file, spec, type, pixels);
}

void write_pixels(const Heightmap& heights, const path& file, const std::string& extension, NpyPrecision npy_precision) {
  if (extension == ".npy") {
    write_file_atomically(file, [&](const path& temporary) {
      if (npy_precision == NpyPrecision::float64) {
        detail::write_npy({heights.height, heights.width}, pixels_of<double>(heights), temporary, file);
      } else {
        detail::write_npy({heights.height, heights.width}, pixels_of<float>(heights), temporary, file);
      }
    });
  } else if (extension == ".png") {
    const std::vector<std::uint16_t> levels = png16_levels(heights);
    write_single_channel(file, OIIO::TypeDesc::UINT16, heights.width, heights.height, levels.data());
  } else {
    const std::vector<float> pixels = pixels_of<float>(heights);
    write_single_channel(file, OIIO::TypeDesc::FLOAT, heights.width, heights.height, pixels.data());
  }
}

void check_writable_shape(const Heightmap& heights, const path& target) {
  const std::size_t cells = static_cast<std::size_t>(std::max(heights.width, 0)) * std::max(heights.height, 0);
  if (cells == 0 || heights.values.size() != cells || (heights.has_mask() && heights.valid.size() != cells)) {
    throw InputError(fmt::format("cannot write {}: heightmap {}x{} holds {} values and {} mask bytes",
                                 target.string(), heights.width, heights.height, heights.values.size(),
                                 heights.valid.size()));
  }
}

}  // namespace

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

HeightmapFile read_heightmap(const path& file, const HeightmapReadOptions& options) {
  if (file.empty()) throw InputError("cannot open heightmap: empty path");
  require_regular_file(file, "cannot open");
  const std::string extension = lower_extension(file);
  HeightmapFile result = extension == ".json"  ? detail::read_volcano_json(file)
                         : extension == ".npz" ? detail::read_matplotlib_npz(file)
                         : extension == ".npy" ? detail::read_npy_heightmap(file)
                                               : read_image(file, options);
  apply_cell_size_override(result, options.cell_size, options.cell_size_y);
  return result;
}

void write_heightmap(const Heightmap& heights, const path& file, NpyPrecision npy_precision) {
  const std::string extension = lower_extension(file);
  if (extension != ".exr" && extension != ".tif" && extension != ".tiff" && extension != ".png" && extension != ".npy") {
    throw InputError(fmt::format(
        "cannot write {}: unknown heightmap extension '{}' (use .exr, .tif, .tiff, .png or .npy)", file.string(),
        extension));
  }
  check_writable_shape(heights, file);
  write_pixels(heights, file, extension, npy_precision);
}

}  // namespace gt
