// Tests of read_heightmap / write_heightmap: round trips through EXR, TIFF and PNG16, the [0,1]
// normalisation of 8/16-bit images, multi-channel notes, InputErrors that name the file, the
// small malformed inputs of tests/data/io (made by its generate.py), and the four real DEMs that
// datasets/fetch.sh puts in datasets/real (a missing file fails with a hint to run the script).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tiffio.h>

#include "core/errors.hpp"
#include "core/grid.hpp"
#include "core/io/heightmap_io.hpp"
#include "tests/support/npy_writer.hpp"
#include "tests/support/temporary_folder.hpp"

namespace gt {
namespace {

namespace fs = std::filesystem;

const fs::path io_data_dir = fs::path(GT_TEST_DATA_DIR) / "io";
const fs::path real_data_dir = fs::path(GT_DATASET_DIR) / "real";

using testing::TemporaryFolder;

// 7 x 5 heights exact in float32, cells (1, 1) and (4, 3) marked invalid.
Heightmap masked_sample() {
  Heightmap heights(7, 5);
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) heights.at(x, y) = 100.125 + 1.25 * x - 3.5 * y;
  }
  heights.valid.assign(heights.size(), 1);
  for (const auto& [x, y] : {std::pair{1, 1}, std::pair{4, 3}}) {
    heights.valid[heights.index(x, y)] = 0;
    heights.at(x, y) = 0.0;
  }
  return heights;
}

template <class T>
void write_test_image(const fs::path& file, int width, int height, int channels, const std::vector<T>& pixels) {
  const OIIO::TypeDesc type(OIIO::BaseTypeFromC<T>::value);
  const auto output = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(output) << OIIO::geterror();
  ASSERT_TRUE(output->open(file.string(), OIIO::ImageSpec(width, height, channels, type))) << output->geterror();
  ASSERT_TRUE(output->write_image(type, pixels.data())) << output->geterror();
  ASSERT_TRUE(output->close()) << output->geterror();
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

bool has_note_containing(const HeightmapFile& file, const std::string& text) {
  return std::any_of(file.notes.begin(), file.notes.end(),
                     [&](const std::string& note) { return note.find(text) != std::string::npos; });
}

// Runs `action`, expecting an InputError whose message contains `path` and `detail`.
template <class Action>
void expect_input_error(Action action, const fs::path& path, const std::string& detail) {
  try {
    action();
    ADD_FAILURE() << "no InputError for " << path;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << "expected '" << detail << "' in: " << message;
  }
}

struct ValidRange {
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -std::numeric_limits<double>::infinity();
};

ValidRange valid_range(const Heightmap& heights) {
  ValidRange range;
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if (!heights.is_valid(i)) continue;
    range.lowest = std::min(range.lowest, heights.values[i]);
    range.highest = std::max(range.highest, heights.values[i]);
  }
  return range;
}

// ---- round trips ---------------------------------------------------------------------------------

class FloatRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(FloatRoundTrip, KeepsValuesAndMask) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / ("heights" + GetParam());
  const Heightmap written = masked_sample();
  write_heightmap(written, file);
  EXPECT_EQ(folder.entries(), std::vector<fs::path>{file}) << "the temporary file should be renamed";

  const HeightmapFile read = read_heightmap(file);
  ASSERT_EQ(read.heights.width, written.width);
  ASSERT_EQ(read.heights.height, written.height);
  EXPECT_EQ(read.heights.values, written.values);
  EXPECT_EQ(read.heights.valid, written.valid);
  // The masked cells are written as NaN and read back as no-data: a decision the user is told of.
  const std::size_t masked = written.size() - gt::count_valid(written);
  ASSERT_GT(masked, 0u);
  EXPECT_TRUE(has_note_containing(read, fmt::format("{} NaN cells of {} taken as no-data", masked, written.size())));
}

INSTANTIATE_TEST_SUITE_P(Formats, FloatRoundTrip, ::testing::Values(".exr", ".tif", ".tiff"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(HeightmapIo, Png16RoundTripWithinOneStep) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "heights.png";
  const Heightmap written = masked_sample();
  write_heightmap(written, file);

  const ValidRange range = valid_range(written);
  const double span = range.highest - range.lowest;
  HeightmapReadOptions options;
  options.image_vertical_scale = span;
  const HeightmapFile read = read_heightmap(file, options);
  EXPECT_EQ(read.format, "png");
  EXPECT_FALSE(read.heights.has_mask()) << "PNG keeps no mask; no-data cells read as the lowest level";
  for (std::size_t i = 0; i < written.size(); ++i) {
    const double expected = written.is_valid(i) ? written.values[i] - range.lowest : 0.0;
    EXPECT_NEAR(read.heights.values[i], expected, span / 65535.0) << "cell " << i;
  }
}

// ---- reading images --------------------------------------------------------------------------------

TEST(HeightmapIo, Png8BitIsNormalisedThenScaled) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "gray8.png";
  write_test_image<std::uint8_t>(file, 3, 1, 1, {0, 51, 255});
  HeightmapReadOptions options;
  options.image_vertical_scale = 10.0;
  const HeightmapFile read = read_heightmap(file, options);
  EXPECT_EQ(read.format, "png");
  EXPECT_EQ(read.heights.values, (std::vector<double>{0.0, 2.0, 10.0}));
  EXPECT_TRUE(has_note_containing(read, "8-bit"));
}

// Seed 000's Algorithm 2 against the digest's test values (§4.2): 0.04045 -> 0.0031308 (the end
// of the linear segment), 0.5 -> 0.2140411, 1 -> 1; the values are quoted to 7 decimals.
TEST(HeightmapIo, SrgbCurveMeetsTheSeedsValues) {
  EXPECT_NEAR(gt::srgb_to_linear(0.04045), 0.0031308, 5e-8);
  EXPECT_NEAR(gt::srgb_to_linear(0.5), 0.2140411, 5e-8);
  EXPECT_DOUBLE_EQ(gt::srgb_to_linear(1.0), 1.0);
  EXPECT_DOUBLE_EQ(gt::srgb_to_linear(0.0), 0.0);
}

// An 8-bit image read as Hydra does with a non-float image: value/255 decoded from sRGB, then scaled.
TEST(HeightmapIo, Png8BitSrgbIsDecodedBeforeScaling) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "gray8.png";
  write_test_image<std::uint8_t>(file, 3, 1, 1, {0, 51, 255});
  HeightmapReadOptions options;
  options.image_vertical_scale = 10.0;
  options.srgb = true;
  const HeightmapFile read = read_heightmap(file, options);
  EXPECT_DOUBLE_EQ(read.heights.values[0], 0.0);
  EXPECT_NEAR(read.heights.values[1], 10.0 * gt::srgb_to_linear(0.2), 1e-12);
  EXPECT_NEAR(read.heights.values[1], 0.3310, 1e-4) << "0.2 decodes to 0.0331";
  EXPECT_DOUBLE_EQ(read.heights.values[2], 10.0);
  EXPECT_TRUE(has_note_containing(read, "sRGB-decoded"));
}

TEST(HeightmapIo, Png16BitIsNormalisedThenScaled) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "gray16.png";
  write_test_image<std::uint16_t>(file, 3, 1, 1, {0, 13107, 65535});
  HeightmapReadOptions options;
  options.image_vertical_scale = 10.0;
  const HeightmapFile read = read_heightmap(file, options);
  EXPECT_EQ(read.heights.values, (std::vector<double>{0.0, 2.0, 10.0}));
  EXPECT_TRUE(has_note_containing(read, "16-bit"));
}

TEST(HeightmapIo, MultiChannelUsesChannelZeroUnaffectedByAlpha) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "rgba.png";
  // Two RGBA pixels: the first fully transparent, so a premultiplying reader would return 0.
  write_test_image<std::uint8_t>(file, 2, 1, 4, {255, 7, 7, 0, 51, 9, 9, 255});
  HeightmapReadOptions options;
  options.red_channel = true;
  const HeightmapFile read = read_heightmap(file, options);
  EXPECT_EQ(read.heights.values, (std::vector<double>{1.0, 0.2}));
  EXPECT_TRUE(has_note_containing(read, "channel 0")) << fmt::format("{}", fmt::join(read.notes, "; "));
  EXPECT_TRUE(has_note_containing(read, "red channel"));
}

// A colour picture is not a heightmap: refused with the number of coloured pixels, unless the red
// channel is asked for (above).
TEST(HeightmapIo, AColourImageIsRefusedAsAHeightmap) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "photo.png";
  write_test_image<std::uint8_t>(file, 3, 1, 3, {10, 10, 10, 200, 30, 40, 90, 90, 90});
  try {
    (void)read_heightmap(file);
    FAIL() << "a colour image was read as a heightmap";
  } catch (const gt::InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("not a heightmap"));
    EXPECT_THAT(error.what(), ::testing::HasSubstr("1 of 3 pixels"));
    EXPECT_THAT(error.what(), ::testing::HasSubstr("red_channel"));
  }
}

// A grey picture stored as RGB is a heightmap.
TEST(HeightmapIo, AGreyImageStoredAsRgbIsAHeightmap) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "grey.png";
  write_test_image<std::uint8_t>(file, 2, 1, 3, {0, 0, 0, 255, 255, 255});
  EXPECT_EQ(read_heightmap(file).heights.values, (std::vector<double>{0.0, 1.0}));
}

// .npy: float32 (height, width), NaN no-data, read back with the same values and mask; the data
// starts at a multiple of 64 bytes as NumPy's format 1.0 asks.
TEST(HeightmapIo, NpyRoundTripsValuesAndNoData) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "heights.npy";
  const Heightmap written = masked_sample();
  write_heightmap(written, file);
  const HeightmapFile read = read_heightmap(file);
  EXPECT_EQ(read.format, "npy");
  EXPECT_EQ(read.heights.width, written.width);
  EXPECT_EQ(read.heights.height, written.height);
  EXPECT_EQ(read.heights.valid, written.valid);
  for (std::size_t i = 0; i < written.size(); ++i) {
    if (written.is_valid(i)) {
      EXPECT_EQ(read.heights.values[i], written.values[i]) << i;
    }
  }
  EXPECT_EQ(fs::file_size(file) % 64, written.size() * sizeof(float) % 64);
  std::ifstream in(file, std::ios::binary);
  std::string lead(10, '\0');
  in.read(lead.data(), 10);
  EXPECT_EQ(lead.substr(1, 5), "NUMPY");
  const std::size_t header = static_cast<unsigned char>(lead[8]) + 256u * static_cast<unsigned char>(lead[9]);
  EXPECT_EQ((10 + header) % 64, 0u);
  EXPECT_EQ(fs::file_size(file), 10 + header + written.size() * sizeof(float));
}

// .npy asked as float64 keeps every double (values float32 cannot hold: square roots), '<f8' in
// its header, 8 bytes a cell; the default float32 file of the same heights rounds them.
TEST(HeightmapIo, NpyFloat64KeepsEveryDouble) {
  const TemporaryFolder folder;
  Heightmap written = masked_sample();
  for (std::size_t i = 0; i < written.size(); ++i) written.values[i] = written.is_valid(i) ? std::sqrt(i + 2.0) : 0.0;
  const fs::path wide = folder.path() / "wide.npy";
  const fs::path narrow = folder.path() / "narrow.npy";
  write_heightmap(written, wide, NpyPrecision::float64);
  write_heightmap(written, narrow);
  const HeightmapFile read = read_heightmap(wide);
  EXPECT_EQ(read.heights.valid, written.valid);
  EXPECT_EQ(read.heights.values, written.values);
  EXPECT_NE(read_heightmap(narrow).heights.values, written.values);
  std::ifstream in(wide, std::ios::binary);
  std::string lead(10, '\0');
  in.read(lead.data(), 10);
  const std::size_t header = static_cast<unsigned char>(lead[8]) + 256u * static_cast<unsigned char>(lead[9]);
  std::string dictionary(header, '\0');
  in.read(dictionary.data(), static_cast<std::streamsize>(header));
  EXPECT_THAT(dictionary, ::testing::HasSubstr("'descr': '<f8'"));
  EXPECT_EQ(fs::file_size(wide), 10 + header + written.size() * sizeof(double));
}

// A 3-D .npy is a volume, not a heightmap.
TEST(HeightmapIo, NpyOfAnotherShapeIsRefused) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "volume.npy";
  const char header[] = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 2, 2), }";
  std::string padded = header;
  padded.append(63 - (10 + padded.size()) % 64, ' ');
  padded.push_back('\n');
  std::ofstream out(file, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  out.put(static_cast<char>(padded.size() & 0xff));
  out.put(static_cast<char>(padded.size() >> 8));
  out << padded;
  const std::vector<float> values(8, 1.0f);
  out.write(reinterpret_cast<const char*>(values.data()), 32);
  out.close();
  try {
    (void)read_heightmap(file);
    FAIL() << "a 3-D array was read as a heightmap";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("2-D array"));
  }
}

TEST(HeightmapIo, CellSizeOptionOverridesTheFile) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "heights.exr";
  write_heightmap(masked_sample(), file);
  HeightmapReadOptions options;
  options.cell_size = 2.5;
  const HeightmapFile read = read_heightmap(file, options);
  EXPECT_EQ(read.heights.cell_size_x, 2.5);
  EXPECT_EQ(read.heights.cell_size_y, 2.5);
  options.cell_size_y = 4.0;
  const HeightmapFile rectangular = read_heightmap(file, options);
  EXPECT_EQ(rectangular.heights.cell_size_x, 2.5);
  EXPECT_EQ(rectangular.heights.cell_size_y, 4.0);
  EXPECT_THAT(rectangular.notes, ::testing::Contains("cell size set to 2.5 m (x, columns) by 4 m (y, rows) by the caller"));
}

TEST(HeightmapIo, NpzNanCellsBecomeInvalidZeros) {
  const HeightmapFile read = read_heightmap(io_data_dir / "topobathy_nan.npz");
  EXPECT_EQ(read.heights.values, (std::vector<double>{-10, 0, 5, 0, 20, 30}));
  EXPECT_EQ(read.heights.valid, (std::vector<std::uint8_t>{1, 1, 1, 0, 1, 1}));
}

// ---- errors ------------------------------------------------------------------------------------------

TEST(HeightmapIoErrors, MissingAndEmptyPaths) {
  const TemporaryFolder folder;
  const fs::path missing = folder.path() / "missing.png";
  expect_input_error([&] { read_heightmap(missing); }, missing, "cannot open");
  expect_input_error([&] { read_heightmap(""); }, "", "cannot open");
}

TEST(HeightmapIoErrors, GarbageBytesWithPngExtension) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "garbage.png";
  write_bytes(file, "this is not an image, only some text pretending to be one");
  expect_input_error([&] { read_heightmap(file); }, file, "cannot open");
}

TEST(HeightmapIoErrors, TruncatedImages) {
  const TemporaryFolder folder;
  for (const std::string extension : {".png", ".tif", ".exr"}) {
    const fs::path file = folder.path() / ("truncated" + extension);
    write_heightmap(masked_sample(), file);
    fs::resize_file(file, fs::file_size(file) / 2);
    expect_input_error([&] { read_heightmap(file); }, file, "");
  }
}

TEST(HeightmapIoErrors, TiffWithTruncatedStrip) {
  const fs::path file = io_data_dir / "truncated_strip.tif";
  // Refused before OpenImageIO reads: the strip's byte count runs past the end of the file.
  expect_input_error([&] { read_heightmap(file); }, file,
                     "TIFF strip 0 of 1 (32 bytes at offset 134) is empty or runs past the end of the 144-byte file");
}

TEST(HeightmapIoErrors, VolcanoJsonWithWrongCount) {
  const fs::path file = io_data_dir / "volcano_wrong_count.json";
  expect_input_error([&] { read_heightmap(file); }, file, "'values' holds 5 numbers");
}

TEST(HeightmapIoErrors, AbsurdJsonSizeIsRefusedBeforeAllocating) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "huge.json";
  write_bytes(file, R"({"width": 1000000, "height": 1000000, "values": []})");
  expect_input_error([&] { read_heightmap(file); }, file, "1000000x1000000");
}

// A .npy of format `version` whose header is `dictionary` as given (no padding added), then `data`.
std::string npy_with_header(int version, const std::string& dictionary, const std::string& data) {
  std::string bytes("\x93NUMPY", 6);
  bytes.push_back(static_cast<char>(version));
  bytes.push_back('\0');
  const auto length = static_cast<std::uint32_t>(dictionary.size());
  bytes.append(reinterpret_cast<const char*>(&length), version == 1 ? 2 : 4);
  return bytes + dictionary + data;
}

const std::string six_floats = gt::testing::npy_data(std::vector<float>{1, 2, 3, 4, 5, 6});

// Headers beyond numpy.load's own 10,000-byte default are refused before they are read: a 100 KB
// one overflowed the stack of the regular expressions that parsed headers. Within it, any padding
// and spacing numpy's grammar allows is read, in one pass.
TEST(HeightmapIoErrors, NpyHeaderOverNumpysLimitIsRefusedUnread) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "long_header.npy";
  const std::string padded = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }" + std::string(100000, ' ');
  write_bytes(file, npy_with_header(2, padded + "\n", six_floats));
  expect_input_error([&] { read_heightmap(file); }, file, "over the 10000 numpy.load reads by default");
  write_bytes(file, npy_with_header(2, "{'descr': '" + std::string(100000, '<') + "', }\n", six_floats));
  expect_input_error([&] { read_heightmap(file); }, file, "over the 10000");
}

TEST(HeightmapIo, NpyHeaderOfAnySpacingWithinTheLimitIsRead) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "spaced.npy";
  for (const std::string& dictionary :
       {"{'shape':(2,3),'fortran_order':False,'descr':'<f4'}" + std::string(9000, ' ') + "\n",
        std::string("{ 'descr' :  '<f4' , 'fortran_order' : False , 'shape' : ( 2 , 3 , ) , }\n")}) {
    SCOPED_TRACE(dictionary.substr(0, 80));
    write_bytes(file, npy_with_header(3, dictionary, six_floats));
    const HeightmapFile read = read_heightmap(file);
    EXPECT_EQ(read.heights.width, 3);
    EXPECT_EQ(read.heights.height, 2);
    EXPECT_EQ(read.heights.values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  }
}

TEST(HeightmapIoErrors, NpyHeaderFieldsThatAreNotNumpysAreRefused) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "bad.npy";
  const auto refused = [&](const std::string& dictionary, const std::string& message) {
    write_bytes(file, npy_with_header(1, dictionary + "\n", six_floats));
    expect_input_error([&] { read_heightmap(file); }, file, message);
  };
  refused("{'descr': '<f4', 'fortran_order': False, 'shape': (2,,3), }", "bad .npy shape");
  refused("{'descr': '<f4', 'fortran_order': False, 'shape': (2, -3), }", "bad .npy shape");
  refused("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3", "no valid 'shape'");
  refused("{'descr': <f4, 'fortran_order': False, 'shape': (2, 3), }", "no valid 'descr'");
  refused("{'descr': '<f4', 'fortran_order': Maybe, 'shape': (2, 3), }", "no valid 'fortran_order'");
  refused("{'descr': '" + std::string(5000, 'x') + "', 'fortran_order': False, 'shape': (2, 3), }",
          "... (5000 bytes)' (supported: <i2 <i4 <f4 <f8)");
}

TEST(HeightmapIoErrors, NpzMissingKey) {
  const fs::path file = io_data_dir / "jacksboro_missing_dx.npz";
  expect_input_error([&] { read_heightmap(file); }, file, "missing array 'dx'");
}

TEST(HeightmapIoErrors, NpzUnsupportedLayouts) {
  expect_input_error([&] { read_heightmap(io_data_dir / "elevation_uint8.npz"); }, io_data_dir / "elevation_uint8.npz",
                     "unsupported .npy dtype '|u1'");
  expect_input_error([&] { read_heightmap(io_data_dir / "elevation_fortran.npz"); },
                     io_data_dir / "elevation_fortran.npz", "Fortran-ordered");
}

TEST(HeightmapIoErrors, TruncatedNpz) {
  const TemporaryFolder folder;
  const fs::path file = folder.path() / "truncated.npz";
  fs::copy_file(io_data_dir / "topobathy_nan.npz", file);
  fs::resize_file(file, fs::file_size(file) - 40);
  expect_input_error([&] { read_heightmap(file); }, file, "npz");
}

TEST(HeightmapIoErrors, WriteUnknownExtensionOrFolder) {
  const TemporaryFolder folder;
  const fs::path unknown = folder.path() / "heights.bmp";
  expect_input_error([&] { write_heightmap(masked_sample(), unknown); }, unknown, "unknown heightmap extension");
  const fs::path no_folder = folder.path() / "absent" / "heights.exr";
  expect_input_error([&] { write_heightmap(masked_sample(), no_folder); }, no_folder, "cannot write");
  EXPECT_TRUE(folder.entries().empty()) << "a failed write must leave nothing behind";
}

// ---- real DEMs (datasets/fetch.sh) -------------------------------------------------------------------

struct RealDem {
  const char* file;
  int width;
  int height;
  std::size_t valid_cells;
  double lowest;
  double highest;
  double cell_size_x;  // metres, after the documented conversions
  double cell_size_y;
};

void PrintTo(const RealDem& dem, std::ostream* out) { *out << dem.file; }

class RealDems : public ::testing::TestWithParam<RealDem> {};

TEST_P(RealDems, HaveTheDocumentedGridAndRange) {
  const RealDem& dem = GetParam();
  const fs::path file = real_data_dir / dem.file;
  ASSERT_TRUE(fs::exists(file)) << file << " is missing: run datasets/fetch.sh";
  const HeightmapFile read = read_heightmap(file);
  const Heightmap& heights = read.heights;
  EXPECT_EQ(heights.width, dem.width);
  EXPECT_EQ(heights.height, dem.height);
  EXPECT_EQ(count_valid(heights), dem.valid_cells);
  const ValidRange range = valid_range(heights);
  EXPECT_EQ(range.lowest, dem.lowest);
  EXPECT_EQ(range.highest, dem.highest);
  EXPECT_NEAR(heights.cell_size_x, dem.cell_size_x, 0.05);
  EXPECT_NEAR(heights.cell_size_y, dem.cell_size_y, 0.05);
  EXPECT_EQ(heights.horizontal_unit, "m");
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if (!heights.is_valid(i)) {
      ASSERT_EQ(heights.values[i], 0.0) << "invalid cells store 0";
    }
  }
}

// Cell sizes: 3" (jacksboro) at 36.59 N, 2' x 0.02187 deg (topobathy) at 49.00 N, 30" (Luxembourg)
// at 49.82 N, each as d_lon * 111320 * cos(latitude) by d_lat * 110574.
INSTANTIATE_TEST_SUITE_P(
    Datasets, RealDems,
    ::testing::Values(RealDem{"volcano.json", 87, 61, 87 * 61, 94, 195, 10.0, 10.0},
                      RealDem{"jacksboro_fault_dem.npz", 403, 344, 403 * 344, 236, 1076, 74.48, 92.15},
                      RealDem{"topobathy.npz", 120, 91, 120 * 91, -1437, 2205, 2434.4, 2417.7},
                      RealDem{"elev.tif", 95, 90, 4608, 141, 547, 598.6, 921.45}),
    [](const auto& info) { return fs::path(info.param.file).stem().string(); });

TEST(RealDems, LuxembourgIsAGeoTiffWithNoData) {
  const fs::path file = real_data_dir / "elev.tif";
  ASSERT_TRUE(fs::exists(file)) << file << " is missing: run datasets/fetch.sh";
  const HeightmapFile read = read_heightmap(file);
  EXPECT_EQ(read.format, "geotiff");
  EXPECT_TRUE(has_note_containing(read, "GDAL_NODATA -32768: 3942 cells invalid"))
      << fmt::format("{}", fmt::join(read.notes, "; "));
  EXPECT_TRUE(has_note_containing(read, "geographic CRS"));
}

// libgeotiff and GDAL register the GeoTIFF tags with libtiff in a process that loads them (rasterio
// beside the Python module): the array tags then pass a 16-bit count and GDAL_NODATA comes as a C
// string, where an unregistered tag passes a 32-bit count. Registered here as they do (xtiff.c,
// GDAL's GTiffTagExtender), the file must read as it does without them.
TIFFExtendProc extender_before = nullptr;

void register_geotiff_tags_as_gdal_does(TIFF* tiff) {
  static const TIFFFieldInfo fields[] = {
      {33550, TIFF_VARIABLE, TIFF_VARIABLE, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoPixelScale")},
      {33922, TIFF_VARIABLE, TIFF_VARIABLE, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoTiePoints")},
      {34735, TIFF_VARIABLE, TIFF_VARIABLE, TIFF_SHORT, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoKeyDirectory")},
      {42113, TIFF_VARIABLE, TIFF_VARIABLE, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GDALNoDataValue")}};
  TIFFMergeFieldInfo(tiff, fields, sizeof fields / sizeof fields[0]);
  if (extender_before != nullptr) extender_before(tiff);
}

TEST(RealDems, LuxembourgReadsTheSameWhereGdalRegisteredTheGeoTiffTags) {
  const fs::path file = real_data_dir / "elev.tif";
  ASSERT_TRUE(fs::exists(file)) << file << " is missing: run datasets/fetch.sh";
  const HeightmapFile plain = read_heightmap(file);
  extender_before = TIFFSetTagExtender(register_geotiff_tags_as_gdal_does);
  HeightmapFile registered;
  try {
    registered = read_heightmap(file);
  } catch (...) {
    TIFFSetTagExtender(extender_before);
    throw;
  }
  TIFFSetTagExtender(extender_before);
  EXPECT_EQ(registered.format, "geotiff");
  EXPECT_EQ(registered.notes, plain.notes);
  EXPECT_TRUE(has_note_containing(registered, "GDAL_NODATA -32768: 3942 cells invalid"));
  EXPECT_EQ(registered.heights.cell_size_x, plain.heights.cell_size_x);
  EXPECT_EQ(registered.heights.cell_size_y, plain.heights.cell_size_y);
  EXPECT_EQ(registered.heights.values, plain.heights.values);
  EXPECT_EQ(registered.heights.valid, plain.heights.valid);
}

}  // namespace
}  // namespace gt
