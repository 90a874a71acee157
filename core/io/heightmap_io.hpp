// Reading and writing heightmaps.
//
// read_heightmap picks the reader by file extension:
//   .png .tif .tiff .exr (.jpg .pgm ... anything OpenImageIO reads): channel 0 as height.
//       8/16-bit integer images map to [0,1] (OpenImageIO's normalisation) then times
//       `image_vertical_scale`; float and signed int16 TIFF/GeoTIFF keep their values (int16 read
//       as raw integers, metres for DEMs). GeoTIFF: GDAL_NODATA (tag 42113) cells become invalid,
//       ModelPixelScale (tag 33550) gives the cell size (degrees are converted to metres at the
//       grid's centre latitude from ModelTiepoint, tag 33922). EXR/TIFF float NaN cells become
//       invalid. Multi-channel images: channel 0 is used and a note says so; a colour picture
//       (red, green and blue differ somewhere) is refused unless `red_channel` asks for its red.
//   .json: the vega-datasets volcano format {width, height, values[row-major]} (10 m cells,
//       null values invalid).
//   .npz: matplotlib's sample DEMs: jacksboro_fault_dem.npz (`elevation`, int16, cell size from
//       dx/dy, which are in degrees: 1/1200 = 3 arc-seconds) and topobathy.npz (`topo`, float32,
//       longitude/latitude arrays in degrees; mean latitude step, as the rows are not evenly spaced).
//   .npy: one 2-D NumPy array (rows, columns) of int16/int32/float32/float64; NaN cells invalid,
//       1 m cells assumed.
//   Degrees become metres at the grid's centre latitude: 111320 m x cos(lat) per degree of
//   longitude, 110574 m per degree of latitude (see detail::degrees_to_metres).
//   Invalid (no-data, NaN) cells store the value 0. Notes say what was decided for the file.
// Every reader throws InputError with the path in the message for unreadable or malformed files
// (missing, truncated, wrong shape or type) and checks the size with check_grid_fits before
// allocating.
//
// write_heightmap picks the format by extension: .exr (float32, no-data as NaN), .tif/.tiff
// (float32, no-data as NaN), .npy (NumPy float32, or float64 when asked, shape (height, width),
// no-data as NaN; read back
// by read_heightmap, or numpy.load), .png (16-bit, valid range mapped to 0..65535, no-data 0; lossy
// and without the range, for viewing). The cell size is not stored. The file is written under a
// temporary name in the same folder and renamed, so a failed write leaves nothing behind; any
// other extension, or a write that fails, throws InputError.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/grid.hpp"

namespace gt {

struct HeightmapFile {
  Heightmap heights;
  std::string format;               // "png", "tiff", "geotiff", "exr", "volcano-json", "npz"
  std::vector<std::string> notes;   // what the reader decided (channel used, no-data value, units)
};

struct HeightmapReadOptions {
  double image_vertical_scale = 1.0;  // multiplies [0,1] heights read from 8/16-bit images
  double cell_size = 0.0;             // overrides the file's cell size when > 0
  double cell_size_y = 0.0;           // with cell_size: the rows' spacing when it differs (0: cell_size)
  // 8/16-bit images: the [0,1] value is sRGB-encoded and linearised (seed 000 §4.3.1, Algorithm 2)
  // before the vertical scale, as Hydra makes a heightmap of a non-float image's red channel.
  bool srgb = false;
  // A colour image (three or more channels whose first three differ in some pixel) is not a
  // heightmap and is refused, unless this takes its red channel as height as seed 000 §4.2 does.
  bool red_channel = false;
};

// Seed 000's Algorithm 2, the sRGB decoding curve of one channel value c in [0, 1]:
// c/12.92 up to 0.04045, ((c + 0.055)/1.055)^2.4 above.
double srgb_to_linear(double c);

HeightmapFile read_heightmap(const std::filesystem::path& path, const HeightmapReadOptions& options = {});

// The element type of the .npy files write_heightmap writes (the other formats are float32 or
// 16-bit whatever this says): float32 by default, float64 for values that need it (the double
// reference's fields, compare/field_files.hpp).
enum class NpyPrecision { float32, float64 };

void write_heightmap(const Heightmap& heights, const std::filesystem::path& path,
                     NpyPrecision npy_precision = NpyPrecision::float32);

// Throws InputError when an OpenEXR file's header declares an attribute larger than the bytes that
// follow it (OpenEXR would allocate that size first); other files pass. For every reader that hands
// a file to OpenImageIO (read_heightmap does; diff-image too).
void check_exr_attribute_sizes(const std::filesystem::path& file);

}  // namespace gt
