// End-to-end tests of the `groundtruth` executable, run as a user runs it: posix_spawn with an
// argument vector (no shell), in a fresh temporary folder, stdout and stderr captured, exit status
// checked against DESIGN.md's contract (0 nothing unexpected failed, 1 something did, 2 bad usage
// or bad input; bad input writes nothing).
//
// Inputs the project has never seen are written here: a float32 GeoTIFF with ModelPixelScale,
// ModelTiepoint, GeoKeyDirectory and GDAL_NODATA (libtiff), EXR/TIFF files with an infinite cell
// and an RGB PNG (OpenImageIO), a PNG header claiming 10^6 x 10^6 pixels, and volcano-format JSON.
//
// The no-GPU test makes EGL fail by pointing libglvnd at a vendor file that does not exist
// (__EGL_VENDOR_LIBRARY_FILENAMES): with no vendor library, no EGL display can be made, on
// llvmpipe machines and NVIDIA machines alike.

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiffio.h>

#include "core/io/heightmap_io.hpp"
#include "tests/support/npy_writer.hpp"
#include "tests/support/run_program.hpp"


namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
const fs::path dataset_dir = GT_DATASET_DIR;
const std::string volcano = (dataset_dir / "real" / "volcano.json").string();

// Acceptance bounds of the thermal-erosion issue, the same for every case.
constexpr double cpu_mass_drift_bound = 1e-12;
constexpr double gpu_mass_drift_bound = 1e-6;

// ---- helpers ---------------------------------------------------------------------------------

using TempDir = gt::testing::TemporaryFolder;
using RunResult = gt::testing::ProgramRun;
using gt::testing::EnvChanges;
using gt::testing::read_text;

// Runs groundtruth with `args` (argv[1...]) in the folder `cwd`.
RunResult run_groundtruth(const std::vector<std::string>& args, const fs::path& cwd, const EnvChanges& env = {}) {
  return gt::testing::run_program(groundtruth, args, cwd, env);
}

json read_json(const fs::path& file) {
  std::ifstream stream(file);
  if (!stream) {
    ADD_FAILURE() << "cannot open " << file;
    return nullptr;
  }
  try {
    return json::parse(stream);
  } catch (const json::exception& error) {
    ADD_FAILURE() << file << " is not valid JSON: " << error.what();
    return nullptr;
  }
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream stream(file, std::ios::binary);
  stream << text;
  ASSERT_TRUE(stream.good()) << file;
}

std::vector<std::string> folder_entries(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return {names.begin(), names.end()};
}

const json* find_check(const json& report_case, const std::string& name) {
  for (const auto& check : report_case.at("checks")) {
    if (check.at("name") == name) return &check;
  }
  return nullptr;
}

// The check exists, has a finite value and that value is at most `bound`.
void expect_check_at_most(const json& report_case, const std::string& name, double bound) {
  const json* check = find_check(report_case, name);
  ASSERT_NE(check, nullptr) << "case " << report_case.at("name") << " lacks the check " << name;
  ASSERT_TRUE(check->at("value").is_number()) << name << ": " << check->dump();
  EXPECT_LE(check->at("value").get<double>(), bound) << "case " << report_case.at("name") << ": " << check->dump();
  EXPECT_NE(check->at("status"), "fail") << check->dump();
  EXPECT_NE(check->at("status"), "error") << check->dump();
}

void expect_acceptance_bounds(const json& report_case) {
  SCOPED_TRACE("case " + report_case.at("name").get<std::string>());
  const auto status = report_case.at("status").get<std::string>();
  EXPECT_TRUE(status == "pass" || status == "warn") << "status " << status << ": " << report_case.dump(2);
  expect_check_at_most(report_case, "mass.relative_drift.cpu", cpu_mass_drift_bound);
  expect_check_at_most(report_case, "mass.relative_drift.gpu", gpu_mass_drift_bound);
  expect_check_at_most(report_case, "determinism.gpu", 0.0);
  // The twins' agreement is graded by the shadow step (the GPU loaded with ref<float>'s state),
  // against the error model's bound; the end of the run is shown, not graded.
  const json* shadow = find_check(report_case, "parity.shadow.terrain.gpu_vs_float");
  ASSERT_NE(shadow, nullptr);
  EXPECT_EQ(shadow->at("status"), "pass") << shadow->dump();
}

void expect_artifacts_exist(const json& report_case, const fs::path& report_dir) {
  ASSERT_FALSE(report_case.at("artifacts").empty()) << report_case.at("name");
  for (const auto& artifact : report_case.at("artifacts")) {
    const fs::path file = report_dir / artifact.get<std::string>();
    EXPECT_TRUE(fs::is_regular_file(file)) << file;
    if (fs::is_regular_file(file)) {
      EXPECT_GT(fs::file_size(file), 0u) << file;
    }
  }
}

// A single-channel float32 image read with OpenImageIO.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;
};

FloatImage read_float_image(const fs::path& file) {
  FloatImage image;
  const auto input = OIIO::ImageInput::open(file.string());
  if (!input) {
    ADD_FAILURE() << "cannot open " << file << ": " << OIIO::geterror();
    return image;
  }
  image.width = input->spec().width;
  image.height = input->spec().height;
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height);
  if (!input->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    ADD_FAILURE() << "cannot read " << file << ": " << input->geterror();
  }
  return image;
}

void write_float_image(const fs::path& file, int width, int height, int channels, const std::vector<float>& pixels) {
  const auto output = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(output) << OIIO::geterror();
  ASSERT_TRUE(output->open(file.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::FLOAT)))
      << output->geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << output->geterror();
  ASSERT_TRUE(output->close()) << output->geterror();
}

// ---- a GeoTIFF of our own ----------------------------------------------------------------------

constexpr int geotiff_width = 70;
constexpr int geotiff_height = 50;
constexpr double geotiff_cell_m = 30.0;
constexpr float geotiff_no_data = -9999.0f;
const std::vector<std::pair<int, int>> geotiff_no_data_cells = {{3, 4}, {40, 10}, {41, 10}, {69, 49}, {0, 25}, {35, 30}};

// A north-south ridge (Gaussian, 300 m high, σ = 8 cells: slopes up to about 60°) on a gentle
// east-west tilt with a sine swell, plus deterministic noise of a few metres; heights in metres.
std::vector<float> ridge_terrain() {
  std::vector<float> heights(static_cast<std::size_t>(geotiff_width) * geotiff_height);
  std::uint32_t state = 12345u;
  for (int y = 0; y < geotiff_height; ++y) {
    for (int x = 0; x < geotiff_width; ++x) {
      state = state * 1664525u + 1013904223u;
      const double noise = 4.0 * (static_cast<double>(state >> 8) / static_cast<double>(1u << 24) - 0.5);
      const double across = (x - 35.0 - 5.0 * std::sin(y / 7.0)) / 8.0;
      const double height = 450.0 + 300.0 * std::exp(-across * across) + 1.5 * x + 20.0 * std::sin(y / 5.0) + noise;
      heights[static_cast<std::size_t>(y) * geotiff_width + x] = static_cast<float>(height);
    }
  }
  for (const auto& [x, y] : geotiff_no_data_cells) heights[static_cast<std::size_t>(y) * geotiff_width + x] = geotiff_no_data;
  return heights;
}

int ignore_tiff_message(TIFF*, void*, const char*, const char*, va_list) { return 1; }

// Float32, one sample per pixel, projected CRS (UTM 32N) with 30 m pixels and GDAL_NODATA -9999.
void write_geotiff(const fs::path& file, const std::vector<float>& heights) {
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetWarningHandlerExtR(options, ignore_tiff_message, nullptr);
  TIFF* tiff = TIFFOpenExt(file.c_str(), "w", options);
  TIFFOpenOptionsFree(options);
  ASSERT_NE(tiff, nullptr) << file;
  static const TIFFFieldInfo geotiff_fields[] = {
      {33550, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelPixelScaleTag")},
      {33922, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelTiepointTag")},
      {34735, -1, -1, TIFF_SHORT, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoKeyDirectoryTag")},
      {42113, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GDALNoDataTag")},
  };
  ASSERT_EQ(TIFFMergeFieldInfo(tiff, geotiff_fields, std::size(geotiff_fields)), 0);
  TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, geotiff_width);
  TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, geotiff_height);
  TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, 32);
  TIFFSetField(tiff, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
  TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tiff, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  TIFFSetField(tiff, TIFFTAG_ROWSPERSTRIP, 8);
  const double pixel_scale[3] = {geotiff_cell_m, geotiff_cell_m, 0.0};
  const double tiepoint[6] = {0.0, 0.0, 0.0, 500000.0, 5200000.0, 0.0};
  // Header (version 1, revision 1.0, 4 keys), then GTModelType = projected, GTRasterType =
  // PixelIsArea, ProjectedCSType = EPSG 32632, ProjLinearUnits = metre.
  const std::uint16_t geo_keys[] = {1, 1, 0, 4, 1024, 0, 1, 1, 1025, 0, 1, 1, 3072, 0, 1, 32632, 3076, 0, 1, 9001};
  ASSERT_EQ(TIFFSetField(tiff, 33550, 3, pixel_scale), 1);
  ASSERT_EQ(TIFFSetField(tiff, 33922, 6, tiepoint), 1);
  ASSERT_EQ(TIFFSetField(tiff, 34735, static_cast<int>(std::size(geo_keys)), geo_keys), 1);
  ASSERT_EQ(TIFFSetField(tiff, 42113, "-9999"), 1);
  std::vector<float> row(geotiff_width);
  for (int y = 0; y < geotiff_height; ++y) {
    std::copy_n(heights.begin() + static_cast<std::ptrdiff_t>(y) * geotiff_width, geotiff_width, row.begin());
    ASSERT_EQ(TIFFWriteScanline(tiff, row.data(), static_cast<std::uint32_t>(y), 0), 1) << "row " << y;
  }
  TIFFClose(tiff);
}

// ---- a PNG header that claims a huge image -----------------------------------------------------

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

std::string big_endian(std::uint32_t value) {
  return {static_cast<char>(value >> 24), static_cast<char>(value >> 16), static_cast<char>(value >> 8),
          static_cast<char>(value)};
}

std::string png_chunk(const std::string& type, const std::string& data) {
  return big_endian(static_cast<std::uint32_t>(data.size())) + type + data + big_endian(crc32(type + data));
}

// Signature, IHDR (8-bit grey), an IDAT holding an empty zlib stream and IEND: about 70 bytes
// describing width x height pixels (libpng reads the header up to the first IDAT).
std::string png_header_only(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr = big_endian(width) + big_endian(height) + std::string("\x08\x00\x00\x00\x00", 5);
  const std::string empty_zlib("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
  return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", empty_zlib) +
         png_chunk("IEND", "");
}

// ---- 1. the thermal suite --------------------------------------------------------------------

TEST(CliRun, ThermalSuiteMeetsTheAcceptanceBounds) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult run = run_groundtruth({"run", "erosion.thermal.*", "--require-gpu", "--out", out.string()}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  for (const char* file : {"report.json", "report.md", "junit.xml", "index.html"}) {
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
    if (fs::is_regular_file(out / file)) {
      EXPECT_GT(fs::file_size(out / file), 0u) << file;
    }
  }
  const json report = read_json(out / "report.json");
  ASSERT_TRUE(report.is_object());
  EXPECT_EQ(report.at("schema"), 1);
  EXPECT_FALSE(report.at("environment").at("gl_renderer").get<std::string>().empty());
  EXPECT_NE(report.at("environment").at("gl_platform"), "none") << report.at("environment").dump();
  const auto& cases = report.at("cases");
  ASSERT_GE(cases.size(), 6u);
  std::set<std::string> names;
  for (const auto& report_case : cases) {
    names.insert(report_case.at("name").get<std::string>());
    EXPECT_EQ(report_case.at("algorithm"), "erosion.thermal");
    EXPECT_EQ(report_case.at("name").get<std::string>().rfind("erosion.thermal.", 0), 0u);
    expect_acceptance_bounds(report_case);
    expect_artifacts_exist(report_case, out);
  }
  EXPECT_TRUE(names.contains("erosion.thermal.spec.example_3x3"));
  EXPECT_TRUE(names.contains("erosion.thermal.cardinal.volcano"));
  EXPECT_EQ(names.size(), cases.size()) << "a case name appears twice";
  EXPECT_NE(run.out.find(std::to_string(cases.size()) + " cases"), std::string::npos) << run;
}

// The value of a check that must exist.
double check_value(const json& report_case, const std::string& name) {
  const json* check = find_check(report_case, name);
  if (check == nullptr || !check->at("value").is_number()) {
    ADD_FAILURE() << "case " << report_case.at("name") << " lacks a numeric " << name;
    return std::nan("");
  }
  return check->at("value").get<double>();
}

// ---- 1a. the pipe-erosion suite ------------------------------------------------------------------

// Issue 3's acceptance: at least eight erosion.pipe cases covering both transports and seed 001's
// variant; the water balance within 1e-12 (cpu) and 1e-6 (gpu) of the water handled; flux
// transport's material drift within 1e-6 on the GPU, among them over 500 steps of a 256² grid on a
// 500 m base (where ref<float>'s plain float storage drifts by more: the float trap); only
// semi-Lagrangian cases may warn, and only for their material drift.
// The worst outcome of a case's checks other than fidelity.*, which warn when a terrain is unlike
// Earth's (compare/case_descriptors.hpp): a statement about the algorithm, not about the twins.
std::string status_of_twin_checks(const json& report_case) {
  const std::vector<std::string> order = {"pass", "warn", "inconclusive", "skip", "fail", "error"};
  std::size_t worst = 0;
  for (const auto& check : report_case.at("checks")) {
    if (check.at("name").get<std::string>().starts_with("fidelity.")) continue;
    const auto rank = std::find(order.begin(), order.end(), check.at("status").get<std::string>()) - order.begin();
    worst = std::max(worst, static_cast<std::size_t>(rank));
  }
  return order.at(worst);
}

// The droplet eroders (issue 12): every case passes (fidelity aside); batch ordering is bit-exact against ref<float>
// and closes its ledger exactly in quanta; race ordering reports its distance from the sequential
// truth at every spacing rather than hiding it; the double ledger closes everywhere. One test per
// eroder, so that each suite has ctest's whole time limit on a loaded 2-core machine.
void expect_droplet_suite_meets_the_acceptance_bounds(const std::string& algorithm) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult run =
      run_groundtruth({"run", algorithm + ".*", "--require-gpu", "--out", out.string()}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  int cases = 0;
  int graded_races = 0;
  for (const auto& report_case : report.at("cases")) {
    SCOPED_TRACE(report_case.at("name").get<std::string>());
    EXPECT_EQ(report_case.at("algorithm"), algorithm);
    ++cases;
    // The fidelity table's rows warn where the result is unlike Earth: a statement about the
    // algorithm, not about the twins.
    EXPECT_EQ(status_of_twin_checks(report_case), "pass");
    const json* closure = find_check(report_case, "ledger.closure.cpu");
    ASSERT_NE(closure, nullptr);
    EXPECT_LE(closure->at("value").get<double>(), 1e-12);
    const auto ordering = report_case.at("params").at("ordering").get<std::string>();
    if (ordering == "batch") {
      for (const char* name : {"parity.cells_differing.gpu_vs_float", "ledger.quanta.cpu_float", "determinism.gpu"}) {
        const json* check = find_check(report_case, name);
        ASSERT_NE(check, nullptr) << name;
        EXPECT_EQ(check->at("value").get<double>(), 0.0) << name;
      }
    }
    // The flow map (§4.7): drawn by every twin, bit for bit unless racing, and pictured.
    const bool flow_map = report_case.at("algorithm") == "erosion.particle" &&
                          report_case.at("params").at("flow_map").get<bool>();
    if (flow_map && ordering != "race") {
      const json* flow = find_check(report_case, "parity.flow.cells_differing.gpu_vs_float");
      ASSERT_NE(flow, nullptr);
      EXPECT_EQ(flow->at("value").get<double>(), 0.0);
    }
    if (flow_map) {
      EXPECT_TRUE(fs::exists(out / report_case.at("name").get<std::string>() / "flow_cpu.png"));
    }
    if (ordering == "race") {
      for (const int spacing : {16, 8, 4, 2, 1}) {
        const json* distance = find_check(report_case, fmt::format("race.relative_rms.spacing_{}.gpu_vs_float", spacing));
        ASSERT_NE(distance, nullptr) << spacing;
        EXPECT_GT(distance->at("value").get<double>(), 0.0) << "racing droplets differ from the sequential truth";
      }
      // What of a race is order-independent: the case's droplets in batch, bit for bit (not
      // applicable only where batch cannot count a pass's changes even with the droplets apart).
      const json* kernel = find_check(report_case, "parity.batch_kernel.gpu_vs_float");
      ASSERT_NE(kernel, nullptr);
      EXPECT_EQ(kernel->at("status"), "pass");
      if (kernel->at("value").is_number()) {
        EXPECT_EQ(kernel->at("value").get<double>(), 0.0);
        ++graded_races;
      }
    }
  }
  EXPECT_GE(cases, 10);
  EXPECT_GE(graded_races, 3);
}

// A race case grades what of it is order-independent: one iteration of its droplets in batch
// ordering, GPU against ref<float> bit for bit. Honest, every bit equal; with a GPU-only bug in the
// droplets' motion, the check fails and so does the case, though the race itself has no bound.
TEST(CliRun, ARaceCaseGradesItsDropletsInBatchAndAMotionBugFailsThere) {
  const TempDir work;
  const auto kernel_check = [&](const std::vector<std::string>& extra, int expected_status) {
    const fs::path out = work / fmt::format("report{}", extra.size());
    std::vector<std::string> args = {"run", "erosion.particle.mutant_probe.race", "--require-gpu", "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult run = run_groundtruth(args, work.path());
    EXPECT_EQ(run.status, expected_status) << run;
    const json report = read_json(out / "report.json");
    const json* check = find_check(report.at("cases").at(0), "parity.batch_kernel.gpu_vs_float");
    return check == nullptr ? json() : *check;
  };
  const json honest = kernel_check({}, 0);
  ASSERT_TRUE(honest.is_object());
  EXPECT_EQ(honest.at("status"), "pass");
  EXPECT_EQ(honest.at("value").get<double>(), 0.0);
  const json mutated = kernel_check({"--mutant", "erosion.particle.fall_through_acceleration"}, 1);
  ASSERT_TRUE(mutated.is_object());
  EXPECT_EQ(mutated.at("status"), "fail");
  EXPECT_GT(mutated.at("value").get<double>(), 0.0);
}

TEST(CliRun, ParticleSuiteMeetsTheAcceptanceBounds) {
  expect_droplet_suite_meets_the_acceptance_bounds("erosion.particle");
}

TEST(CliRun, BeyerSuiteMeetsTheAcceptanceBounds) {
  expect_droplet_suite_meets_the_acceptance_bounds("erosion.beyer");
}

// The bundled cases, by name, that `keep` keeps (`groundtruth list --json`).
std::vector<std::string> bundled_cases(const std::function<bool(const std::string&)>& keep) {
  const TempDir work;
  const RunResult run = run_groundtruth({"list", "--json"}, work.path());
  EXPECT_EQ(run.status, 0) << run;
  const json listing = json::parse(run.out);
  std::vector<std::string> names;
  for (const auto& spec : listing.at("cases")) {
    const auto name = spec.at("name").get<std::string>();
    if (keep(name)) names.push_back(name);
  }
  return names;
}

// What the pipe suite's cases showed, summed over the halves it is run in.
struct PipeSuiteSeen {
  std::set<std::string> transports;
  bool seed_variant = false;
  bool float_trap_shown = false;
};

// Runs the named pipe cases and checks each against issue 3's bounds, adding what they show to
// `seen`. The suite runs in two halves (flux.* and the rest), so that each has ctest's whole time
// limit on a loaded 2-core machine.
void expect_pipe_cases_meet_the_acceptance_bounds(const std::vector<std::string>& names, PipeSuiteSeen& seen) {
  ASSERT_FALSE(names.empty());
  const TempDir work;
  const fs::path out = work / "report";
  std::vector<std::string> args = {"run"};
  args.insert(args.end(), names.begin(), names.end());
  args.insert(args.end(), {"--require-gpu", "--out", out.string()});
  const RunResult run = run_groundtruth(args, work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  const auto& cases = report.at("cases");
  EXPECT_EQ(cases.size(), names.size());
  for (const auto& report_case : cases) {
    SCOPED_TRACE(report_case.at("name").get<std::string>());
    const auto& params = report_case.at("params");
    const auto transport = params.at("transport").get<std::string>();
    seen.transports.insert(transport);
    seen.seed_variant = seen.seed_variant || (params.at("regolith_depth").get<double>() > 0.0 &&
                                              params.at("sediment_diffusion").get<double>() > 0.0);
    // Inconclusive where the error model of a shadow step is wider than a tenth of the sediment or
    // the velocity (compare/algorithms/pipes.cpp); the terrain and the water must always be decided.
    const auto status = status_of_twin_checks(report_case);
    EXPECT_TRUE(status == "pass" || status == "inconclusive") << report_case.dump(2);
    for (const char* field : {"terrain", "water"}) {
      const json* shadow = find_check(report_case, fmt::format("parity.shadow.{}.gpu_vs_float", field));
      ASSERT_NE(shadow, nullptr) << field;
      EXPECT_EQ(shadow->at("status"), "pass") << shadow->dump();
    }
    expect_check_at_most(report_case, "mass.water_balance.cpu", 1e-12);
    expect_check_at_most(report_case, "mass.water_balance.gpu", 1e-6);
    expect_check_at_most(report_case, "determinism.gpu", 0.0);
    if (transport == "flux") expect_check_at_most(report_case, "mass.material_drift.gpu", 1e-6);
    const bool long_and_large = params.at("steps").get<int>() >= 500 && report_case.at("width").get<int>() >= 256 &&
                                report_case.at("height").get<int>() >= 256;
    if (transport == "flux" && long_and_large) {
      seen.float_trap_shown = seen.float_trap_shown || check_value(report_case, "mass.material_drift.cpu_float") > 1e-6;
    }
    expect_artifacts_exist(report_case, out);
  }
}

bool is_pipe_flux_case(const std::string& name) { return name.starts_with("erosion.pipe.flux."); }

// Issue 3's acceptance over the flux half: among them a 500-step 256² case on a 500 m base, where
// ref<float>'s plain float storage drifts by more than the GPU's bound (the float trap).
TEST(CliRun, PipeSuiteFluxHalfMeetsTheAcceptanceBounds) {
  PipeSuiteSeen seen;
  expect_pipe_cases_meet_the_acceptance_bounds(bundled_cases(is_pipe_flux_case), seen);
  EXPECT_EQ(seen.transports, (std::set<std::string>{"flux"}));
  EXPECT_TRUE(seen.float_trap_shown) << "no 500-step 256² flux case in which ref<float> shows the float trap";
}

// And over the rest: the other transport, seed 001's variant, the sources and the A/B pair; with
// the flux half at least eight cases.
TEST(CliRun, PipeSuiteOtherHalfMeetsTheAcceptanceBounds) {
  const auto pipe_cases = bundled_cases([](const std::string& name) { return name.starts_with("erosion.pipe."); });
  EXPECT_GE(pipe_cases.size(), 8u);
  std::vector<std::string> other_half;
  std::copy_if(pipe_cases.begin(), pipe_cases.end(), std::back_inserter(other_half),
               [](const std::string& name) { return !is_pipe_flux_case(name); });
  PipeSuiteSeen seen;
  expect_pipe_cases_meet_the_acceptance_bounds(other_half, seen);
  EXPECT_TRUE(seen.transports.contains("semi_lagrangian"));
  EXPECT_TRUE(seen.seed_variant) << "no case runs seed 001's variant (regolith and diffusion)";
}

// ---- 1b. the cave suite and the real meshes ----------------------------------------------------


// Issue 5's acceptance: marching-tetrahedra meshes watertight on both backends with the libraries
// agreeing, seams exact along 20 slabs, GPU and CPU meshes equal, marching cubes an expected
// failure with its holes counted, and the four real meshes classified as data-sources.md and
// datasets/README.md say.
TEST(CliRun, CaveSuiteIsWatertightSeamlessAndCatchesTheHoles) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult run = run_groundtruth({"run", "cave.*", "mesh.*", "--require-gpu", "--out", out.string()}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  ASSERT_TRUE(report.is_object());
  std::map<std::string, json> cases;
  for (const auto& report_case : report.at("cases")) {
    cases[report_case.at("name").get<std::string>()] = report_case;
    expect_artifacts_exist(report_case, out);
  }
  for (const char* name : {"cave.marching_tetrahedra.solid.block12", "cave.marching_tetrahedra.solid.far_corrected"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(cases.contains(name));
    const json& solid = cases[name];
    EXPECT_EQ(solid.at("status"), "pass") << solid.dump(2);
    for (const char* backend : {"cpu", "gpu"}) {
      for (const char* what : {"closed", "manifold", "oriented", "self_intersections", "degenerate", "libraries_agree"}) {
        EXPECT_EQ(check_value(solid, fmt::format("mesh.{}.{}", what, backend)), 0.0) << what << " " << backend;
      }
      EXPECT_EQ(find_check(solid, fmt::format("mesh.bounds_volume.{}", backend))->at("status"), "pass");
    }
    EXPECT_EQ(check_value(solid, "parity.topology.gpu_vs_float"), 0.0);
    // A rendered view of each backend's mesh, side by side in the case's section.
    for (const char* view : {"mesh.cpu.png", "mesh.gpu.png"}) EXPECT_TRUE(fs::exists(out / name / view)) << view;
    EXPECT_LE(check_value(solid, "volume.mesh_vs_field.cpu"), find_check(solid, "volume.mesh_vs_field.cpu")->at("threshold").get<double>());
  }
  const json& open = cases.at("cave.marching_tetrahedra.open.big_cube30");
  EXPECT_EQ(open.at("status"), "pass") << open.dump(2);
  EXPECT_EQ(check_value(open, "spec.triangles.cpu"), 0.0);
  EXPECT_EQ(check_value(open, "mesh.border_off_box.gpu"), 0.0);

  const json& cubes = cases.at("cave.marching_cubes.solid.block12");
  EXPECT_EQ(cubes.at("status"), "fail");
  EXPECT_FALSE(cubes.at("expected_failure").get<std::string>().empty()) << cubes.dump(2);
  EXPECT_GT(check_value(cubes, "mesh.closed.cpu"), 0.0) << "the seed's marching cubes should leave holes";
  EXPECT_GT(check_value(cubes, "mesh.holes.cpu"), 0.0);

  const json& path = cases.at("cave.endless.path20");
  EXPECT_EQ(path.at("status"), "pass") << path.dump(2);
  EXPECT_GE(check_value(path, "ring.slabs"), 20.0);
  for (const char* name : {"seams.unmatched_border_edges.cpu", "seams.unmatched_border_edges.gpu", "seams.vertex_bits.cpu",
                           "seams.vertex_bits.gpu", "parity.chunked_vs_monolithic.cpu", "mesh.border_off_box.union_cpu",
                           "mesh.self_intersections.union_gpu", "parity.topology.gpu_vs_float"}) {
    EXPECT_EQ(check_value(path, name), 0.0) << name;
  }
  const json& budget = cases.at("cave.endless.seed_budget");
  EXPECT_EQ(budget.at("status"), "fail") << "MAX_VERTICES = 200,000 drops window geometry on this path";
  EXPECT_FALSE(budget.at("expected_failure").get<std::string>().empty()) << "listed in datasets/expectations.txt";
  EXPECT_GT(check_value(budget, "ring.window_missing_triangles"), 0.0);

  for (const char* name : {"mesh.check.bunny00", "mesh.check.elephant", "mesh.check.cow", "mesh.check.elephant_with_holes"}) {
    ASSERT_TRUE(cases.contains(name)) << name;
    EXPECT_EQ(cases[name].at("status"), "pass") << cases[name].dump(2);
  }
  EXPECT_EQ(check_value(cases.at("mesh.check.elephant"), "spec.genus"), 0.0);
  EXPECT_EQ(check_value(cases.at("mesh.check.elephant_with_holes"), "spec.border_edges"), 0.0);
}

// A scalar volume from a file, meshed on both backends: two overlapping balls as a signed distance
// (negative inside: rock), some samples exactly at the threshold; then a NaN and a flat volume.
TEST(CliRun, VolumeFileIsMeshedWatertightOnBothBackends) {
  const TempDir work;
  constexpr int nx = 18, ny = 15, nz = 13;
  std::vector<double> distance;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        const double first = std::hypot(x - 7.0, y - 7.0, z - 6.0) - 5.0;  // 5 at integer distances: exact zeros
        const double second = std::hypot(x - 12.5, y - 7.25, z - 6.0) - 3.5;
        distance.push_back(std::min(first, second));
      }
    }
  }
  const std::string header = gt::testing::npy_header("<f8", fmt::format("({}, {}, {})", nz, ny, nx));
  const fs::path volume = work / "balls.npy";
  write_text(volume, header + gt::testing::npy_data(distance));
  const fs::path out = work / "report";
  const RunResult run = run_groundtruth({"run", "--algorithm", "cave.marching_tetrahedra", "--input", volume.string(),
                                         "--set", "solid=true", "--set", "origin_x=-30", "--out", out.string()},
                                        work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  ASSERT_EQ(report.at("cases").size(), 1u);
  const json& report_case = report.at("cases")[0];
  EXPECT_EQ(report_case.at("status"), "pass") << report_case.dump(2);
  EXPECT_NE(report_case.at("input").get<std::string>().find("balls.npy (18x15x13 samples)"), std::string::npos);
  for (const char* name : {"mesh.closed.cpu", "mesh.closed.gpu", "mesh.self_intersections.gpu", "parity.topology.gpu_vs_float"}) {
    EXPECT_EQ(check_value(report_case, name), 0.0) << name;
  }
  EXPECT_EQ(check_value(report_case, "mesh.genus.gpu"), 0.0) << "two overlapping balls are one sphere";
  EXPECT_EQ(find_check(report_case, "normals.angle_max.cpu"), nullptr) << "normals compare the noise's derivatives";
  expect_artifacts_exist(report_case, out);

  distance[5] = std::nan("");
  write_text(work / "nan.npy", header + gt::testing::npy_data(distance));
  write_text(work / "flat.npy", gt::testing::npy_header("<f8", "(1, 2, 2)") + gt::testing::npy_data(std::vector<double>(4, 1.0)));
  for (const auto& [file, needle] : {std::pair{"nan.npy", "is nan"}, std::pair{"flat.npy", "empty volume"}}) {
    const RunResult refused = run_groundtruth(
        {"run", "--algorithm", "cave.marching_tetrahedra", "--input", (work / file).string(), "--out", (work / "bad").string()},
        work.path());
    EXPECT_EQ(refused.status, 2) << refused;
    EXPECT_NE(refused.err.find(needle), std::string::npos) << refused;
    EXPECT_FALSE(fs::exists(work / "bad"));
  }
}

// A mesh with nothing to see from above is bad input for the heightmap render: exit 2, no report.
TEST(CliRun, FlatSideOnMeshIsRefusedByTheHeightmapRender) {
  const TempDir work;
  write_text(work / "edge_on.off", "OFF\n3 1 0\n0 0 0\n0 0 1\n1 0 0\n3 0 1 2\n");  // no extent in y
  const RunResult run = run_groundtruth({"run", "--algorithm", "render.heightmap_from_mesh", "--input",
                                         (work / "edge_on.off").string(), "--out", (work / "report").string()},
                                        work.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_NE(run.err.find("nothing is seen from above"), std::string::npos) << run;
  EXPECT_FALSE(fs::exists(work / "report"));
}

// Real meshes through the command users run: exit 0 for the closed ones, 1 for the others.
TEST(CliCheckMesh, ClassifiesTheFourRealMeshes) {
  const TempDir work;
  const fs::path meshes = dataset_dir / "real" / "meshes";
  ASSERT_TRUE(fs::exists(meshes / "bunny00.off")) << "run datasets/fetch.sh";
  for (const auto& [file, status] : {std::pair{"bunny00.off", 0}, std::pair{"elephant.off", 0}, std::pair{"cow.off", 1},
                                     std::pair{"elephant-with-holes.off", 1}}) {
    const RunResult run = run_groundtruth({"check-mesh", (meshes / file).string()}, work.path());
    EXPECT_EQ(run.status, status) << file << "\n" << run;
  }
}

// ---- 2. ad-hoc runs on a GeoTIFF the project has never seen ------------------------------------

class CliGeoTiff : public ::testing::Test {
 protected:
  void SetUp() override {
    heights_ = ridge_terrain();
    write_geotiff(input_, heights_);
    ASSERT_TRUE(fs::is_regular_file(input_));
  }

  bool is_no_data(int x, int y) const {
    for (const auto& cell : geotiff_no_data_cells) {
      if (cell == std::pair{x, y}) return true;
    }
    return false;
  }

  // Runs one ad-hoc case into a fresh folder and returns that folder's report (null on failure).
  json run_ad_hoc(const std::string& algorithm, const std::vector<std::string>& extra, const std::string& folder) {
    std::vector<std::string> args = {"run", "--algorithm", algorithm, "--input", input_.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--out", (work_ / folder).string()});
    const RunResult run = run_groundtruth(args, work_.path());
    EXPECT_EQ(run.status, 0) << run;
    if (run.status != 0) return nullptr;
    return read_json(work_ / folder / "report.json");
  }

  // The one case of an ad-hoc report: bounds, input, size, and NaN exactly at the no-data cells
  // of both result fields.
  void expect_ad_hoc_case(const json& report, const std::string& algorithm, const std::string& folder) {
    ASSERT_TRUE(report.is_object());
    ASSERT_EQ(report.at("cases").size(), 1u);
    const json& report_case = report.at("cases")[0];
    EXPECT_EQ(report_case.at("algorithm"), algorithm);
    EXPECT_EQ(report_case.at("name"), "adhoc." + algorithm + ".ridge");
    expect_acceptance_bounds(report_case);
    expect_artifacts_exist(report_case, work_ / folder);
    const auto input = report_case.at("input").get<std::string>();
    EXPECT_NE(input.find("ridge.tif"), std::string::npos) << input;
    EXPECT_NE(input.find("30x30 m"), std::string::npos) << "ModelPixelScale not honoured: " << input;
    EXPECT_EQ(report_case.at("width"), geotiff_width);
    EXPECT_EQ(report_case.at("height"), geotiff_height);
    for (const char* field : {"terrain_cpu.exr", "terrain_gpu.exr"}) {
      SCOPED_TRACE(field);
      const FloatImage image = read_float_image(work_ / folder / report_case.at("name").get<std::string>() / field);
      ASSERT_EQ(image.width, geotiff_width);
      ASSERT_EQ(image.height, geotiff_height);
      int nan_cells = 0;
      double total_before = 0.0, total_after = 0.0;
      for (int y = 0; y < geotiff_height; ++y) {
        for (int x = 0; x < geotiff_width; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * geotiff_width + x;
          const float value = image.pixels[i];
          nan_cells += std::isnan(value);
          if (is_no_data(x, y)) {
            EXPECT_TRUE(std::isnan(value)) << "no-data cell (" << x << ", " << y << ") holds " << value;
          } else {
            EXPECT_TRUE(std::isfinite(value)) << "cell (" << x << ", " << y << ") holds " << value;
            total_before += heights_[i];
            total_after += value;
          }
        }
      }
      EXPECT_EQ(nan_cells, static_cast<int>(geotiff_no_data_cells.size()));
      // The field is the eroded terrain, not something else of the same shape: the volume of
      // the valid cells is kept (to float precision of the EXR) ...
      EXPECT_NEAR(total_after / total_before, 1.0, 1e-6);
    }
  }

  // ... and erosion moved material somewhere.
  void expect_terrain_changed(const std::string& folder, const std::string& name) {
    const FloatImage image = read_float_image(work_ / folder / name / "terrain_cpu.exr");
    ASSERT_EQ(image.pixels.size(), heights_.size());
    double largest_change = 0.0;
    for (std::size_t i = 0; i < heights_.size(); ++i) {
      if (std::isfinite(image.pixels[i])) largest_change = std::max(largest_change, std::abs(double{image.pixels[i]} - heights_[i]));
    }
    EXPECT_GT(largest_change, 1.0) << "erosion did not move anything (m)";
  }

  TempDir work_;
  fs::path input_ = work_ / "ridge.tif";
  std::vector<float> heights_;
};

TEST_F(CliGeoTiff, ThermalOnEglAndOsmesaHonoursNoData) {
  const std::vector<std::string> params = {"--set", "iterations=51", "--set", "talus_angle=25",
                                           "--set", "neighbourhood=alternating"};
  for (const std::string gl : {"egl", "osmesa"}) {
    SCOPED_TRACE("--gl " + gl);
    std::vector<std::string> extra = params;
    extra.insert(extra.end(), {"--gl", gl});
    const std::string folder = "report-" + gl;
    const json report = run_ad_hoc("erosion.thermal", extra, folder);
    ASSERT_TRUE(report.is_object());
    const auto platform = report.at("environment").at("gl_platform").get<std::string>();
    if (gl == "egl") {
      EXPECT_TRUE(platform == "egl-surfaceless" || platform == "egl-device") << platform;
    } else {
      EXPECT_EQ(platform, "osmesa");
    }
    EXPECT_FALSE(report.at("environment").at("gl_renderer").get<std::string>().empty());
    expect_ad_hoc_case(report, "erosion.thermal", folder);
    const json& params_used = report.at("cases")[0].at("params");
    EXPECT_EQ(params_used.at("iterations"), 51);
    EXPECT_DOUBLE_EQ(params_used.at("talus_angle").get<double>(), 25.0);
    EXPECT_EQ(params_used.at("neighbourhood"), "alternating");
    expect_terrain_changed(folder, "adhoc.erosion.thermal.ridge");
  }
}

TEST_F(CliGeoTiff, JakoThermalOnEgl) {
  const json report = run_ad_hoc("erosion.thermal_jako", {"--gl", "egl"}, "report-jako");
  ASSERT_TRUE(report.is_object());
  expect_ad_hoc_case(report, "erosion.thermal_jako", "report-jako");
  expect_terrain_changed("report-jako", "adhoc.erosion.thermal_jako.ridge");
}

// An RGB image is accepted and its channel 0 is the height: one iteration with an 85° talus moves
// nothing on these gentle slopes (at most 0.05 per 1 m cell), so the result is the input, red / 255.
// (ZeroIterationsIsTheIdentity says so more directly.)
// Fields as data (issue 19): the pipe model's every state field (the outflow one field per pipe),
// before and after, for each backend, as EXR and .npy with the same values, each described in
// fields.json with its unit; the .npy reads back through the heightmap reader (NumPy's format) at
// the case's grid size, float64 for ref<double>'s fields (the EXR holds their float32 rounding),
// float32 for the others. The cells are rectangular (--cell-size-y), as the sidecar's grid says.
TEST(CliRun, EveryPipeFieldIsWrittenAsExrAndNpyWithItsSidecar) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult run = run_groundtruth({"run", "--algorithm", "erosion.pipe", "--input", volcano, "--cell-size", "10",
                                         "--cell-size-y", "12", "--set", "steps=5", "--require-gpu", "--out",
                                         out.string()},
                                        work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  const json& report_case = report.at("cases")[0];
  expect_artifacts_exist(report_case, out);
  const fs::path folder = out / report_case.at("name").get<std::string>();
  const json sidecar = read_json(folder / "fields.json");
  EXPECT_EQ(sidecar.at("algorithm"), "erosion.pipe");
  EXPECT_EQ(sidecar.at("params").at("steps"), 5);
  EXPECT_EQ(sidecar.at("grid").at("cell_size_x"), 10.0);
  EXPECT_EQ(sidecar.at("grid").at("cell_size_y"), 12.0);
  std::set<std::string> described;
  for (const json& file : sidecar.at("files")) {
    const auto stem = file.at("stem").get<std::string>();
    SCOPED_TRACE(stem);
    described.insert(stem);
    EXPECT_FALSE(file.at("unit").get<std::string>().empty());
    const bool double_reference = file.at("backend") == "cpu";
    EXPECT_EQ(file.at("npy_dtype"), double_reference ? "float64" : "float32");
    const gt::HeightmapFile npy = gt::read_heightmap(folder / (stem + ".npy"));
    const FloatImage exr = read_float_image(folder / (stem + ".exr"));
    ASSERT_EQ(npy.heights.width, report_case.at("width").get<int>());
    ASSERT_EQ(npy.heights.height, report_case.at("height").get<int>());
    ASSERT_EQ(exr.pixels.size(), npy.heights.size());
    for (std::size_t i = 0; i < exr.pixels.size(); ++i) {
      if (std::isnan(exr.pixels[i])) {
        ASSERT_FALSE(npy.heights.is_valid(i)) << i;
      } else {
        ASSERT_EQ(double_reference ? static_cast<float>(npy.heights.values[i]) : npy.heights.values[i],
                  exr.pixels[i]) << i;
      }
    }
  }
  for (const char* field : {"terrain", "water", "sediment", "velocity_x", "velocity_y", "regolith", "outflow_L",
                            "outflow_R", "outflow_T", "outflow_B"}) {
    for (const char* backend : {"input", "cpu", "gpu"}) {
      EXPECT_TRUE(described.contains(fmt::format("{}_{}", field, backend))) << field << " " << backend;
    }
  }
  // The water after 5 steps is what the model made, not the dry input again.
  const gt::HeightmapFile water = gt::read_heightmap(folder / "water_cpu.npy");
  EXPECT_GT(*std::max_element(water.heights.values.begin(), water.heights.values.end()), 0.0);
}

// A colour picture is not a heightmap: refused with exit 2, nothing written, unless --red-channel
// takes its red channel (channel 0) as height.
TEST(CliRun, RgbPngIsRefusedUnlessItsRedChannelIsAskedFor) {
  const TempDir work;
  constexpr int width = 24, height = 16;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
      rgb[i] = static_cast<std::uint8_t>(10 * x + y);
      rgb[i + 1] = static_cast<std::uint8_t>(255 - 10 * x);
      rgb[i + 2] = 77;
    }
  }
  const fs::path input = work / "colour.png";
  {
    const auto output = OIIO::ImageOutput::create(input.string());
    ASSERT_TRUE(output) << OIIO::geterror();
    ASSERT_TRUE(output->open(input.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::UINT8, rgb.data())) << output->geterror();
    ASSERT_TRUE(output->close());
  }
  const fs::path out = work / "report";
  const std::vector<std::string> args = {"run", "--algorithm", "erosion.thermal", "--input", input.string(), "--set",
                                         "iterations=1", "--set", "talus_angle=85", "--out", out.string()};
  const RunResult refused = run_groundtruth(args, work.path());
  EXPECT_EQ(refused.status, 2) << refused;
  EXPECT_THAT(refused.err, ::testing::HasSubstr("not a heightmap")) << refused;
  EXPECT_FALSE(fs::exists(out));
  std::vector<std::string> red_channel = args;
  red_channel.push_back("--red-channel");
  const RunResult run = run_groundtruth(red_channel, work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  ASSERT_TRUE(report.is_object());
  ASSERT_EQ(report.at("cases").size(), 1u);
  const json& report_case = report.at("cases")[0];
  EXPECT_EQ(report_case.at("status"), "pass") << report_case.dump(2);
  EXPECT_EQ(report_case.at("width"), width);
  EXPECT_EQ(report_case.at("height"), height);
  const FloatImage result = read_float_image(out / "adhoc.erosion.thermal.colour" / "terrain_cpu.exr");
  ASSERT_EQ(result.pixels.size(), static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < result.pixels.size(); ++i) {
    ASSERT_NEAR(result.pixels[i], rgb[3 * i] / 255.0, 1e-6) << "cell " << i;
  }
}

// iterations = 0 is inside the declared range [0, 100000]: the float-side bounds must still allow
// for the one rounding of the input to float (field_twin.cpp's float_roundings).
TEST(CliRun, ZeroIterationsIsTheIdentity) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult run = run_groundtruth(
      {"run", "--algorithm", "erosion.thermal", "--input", volcano, "--set", "iterations=0", "--out", out.string()},
      work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  ASSERT_TRUE(report.is_object());
  ASSERT_EQ(report.at("cases").size(), 1u);
  EXPECT_EQ(report.at("cases")[0].at("status"), "pass") << report.at("cases")[0].dump(2);
}

// An ad-hoc noise run needs no input: it samples a grid and writes float images other tools open.
TEST(CliRun, AdHocNoiseWritesFloatImages) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult run = run_groundtruth({"run", "--algorithm", "noise.simplex3", "--size", "96x64", "--set", "step=0.07",
                                         "--set", "kernel=0.5", "--out", out.string()},
                                        work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json report = read_json(out / "report.json");
  ASSERT_EQ(report.at("cases").size(), 1u);
  const json& only = report.at("cases")[0];
  EXPECT_EQ(only.at("name"), "adhoc.noise.simplex3.96x64");
  EXPECT_EQ(only.at("status"), "pass") << only.dump(2);
  for (const char* file : {"cpu.exr", "gpu.exr"}) {
    auto image = OIIO::ImageInput::open((out / "adhoc.noise.simplex3.96x64" / file).string());
    ASSERT_TRUE(image) << file;
    EXPECT_EQ(image->spec().width, 96);
    EXPECT_EQ(image->spec().height, 64);
    EXPECT_EQ(image->spec().format, OIIO::TypeDesc::FLOAT);
  }
}

// ---- 3. bad input: exit 2, a message naming the problem, nothing written -----------------------

class CliRefuses : public ::testing::Test {
 protected:
  // Runs groundtruth with `args` followed by --out <work>/out; expects exit 2, every needle on
  // stderr, and the work folder exactly as before (no report, no staging folder).
  void expect_refused(std::vector<std::string> args, const std::vector<std::string>& needles) {
    const fs::path out = work_ / "out";
    args.insert(args.end(), {"--out", out.string()});
    const auto before = folder_entries(work_.path());
    const RunResult run = run_groundtruth(args, cwd_);
    EXPECT_EQ(run.status, 2) << run;
    for (const auto& needle : needles) EXPECT_NE(run.err.find(needle), std::string::npos) << needle << "\n" << run;
    EXPECT_EQ(run.err.find("internal error"), std::string::npos) << run;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(folder_entries(work_.path()), before) << "something was written beside --out";
    EXPECT_TRUE(fs::is_empty(cwd_)) << "something was written in the working folder";
  }

  void SetUp() override { fs::create_directory(cwd_); }

  std::vector<std::string> ad_hoc(const fs::path& input, std::vector<std::string> more = {}) {
    std::vector<std::string> args = {"run", "--algorithm", "erosion.thermal", "--input", input.string()};
    args.insert(args.end(), more.begin(), more.end());
    return args;
  }

  TempDir work_;
  fs::path cwd_ = work_ / "cwd";
};

TEST_F(CliRefuses, InfiniteCellInExr) {
  constexpr int width = 8, height = 6;
  std::vector<float> pixels(width * height, 12.5f);
  pixels[3 * width + 5] = std::numeric_limits<float>::infinity();
  const fs::path input = work_ / "spike.exr";
  write_float_image(input, width, height, 1, pixels);
  expect_refused(ad_hoc(input), {"spike.exr", "x=5, y=3", "inf"});
}

TEST_F(CliRefuses, InfiniteCellInFloatTiff) {
  constexpr int width = 8, height = 6;
  std::vector<float> pixels(width * height, 12.5f);
  pixels[1 * width + 2] = -std::numeric_limits<float>::infinity();
  const fs::path input = work_ / "pit.tif";
  write_float_image(input, width, height, 1, pixels);
  expect_refused(ad_hoc(input), {"pit.tif", "x=2, y=1", "-inf"});
}

TEST_F(CliRefuses, NonNumberInVolcanoJson) {
  const fs::path input = work_ / "nan.json";
  write_text(input, R"({"width": 2, "height": 2, "values": [1, 2, "NaN", 4]})");
  expect_refused(ad_hoc(input), {"nan.json", "values[2]", "not a number"});
}

// nlohmann throws out_of_range (406), not parse_error, for a number beyond double's range; the
// reader must turn that into bad input too (exit 2), not an internal error.
TEST_F(CliRefuses, OverflowingNumberInVolcanoJson) {
  const fs::path input = work_ / "overflow.json";
  write_text(input, R"({"width": 2, "height": 2, "values": [1, 2, 1e999, 4]})");
  expect_refused(ad_hoc(input), {"overflow.json"});
}

TEST_F(CliRefuses, PipeErosionWithoutTime) {
  expect_refused({"run", "--algorithm", "erosion.pipe", "--input", volcano, "--set", "time_step=0"},
                 {"time_step", "[1e-06, 3600]"});
}

TEST_F(CliRefuses, PipeErosionWithNegativeRain) {
  expect_refused({"run", "--algorithm", "erosion.pipe", "--input", volcano, "--set", "rain_rate=-0.001"},
                 {"rain_rate", "-0.001"});
}

TEST_F(CliRefuses, PipeErosionEvaporatingMoreThanTheWater) {
  expect_refused({"run", "--algorithm", "erosion.pipe", "--input", volcano, "--set", "evaporation_rate=100"},
                 {"evaporation_rate", "exceeds 1"});
}

TEST_F(CliRefuses, PipeErosionOnNaNHeights) {
  const fs::path input = work_ / "nan.json";
  write_text(input, R"({"width": 2, "height": 2, "values": [1, 2, "NaN", 4]})");
  expect_refused({"run", "--algorithm", "erosion.pipe", "--input", input.string()}, {"nan.json", "not a number"});
}

TEST_F(CliRefuses, PipeErosionOnAMaskCoveringEverything) {
  const fs::path input = work_ / "masked.json";
  write_text(input, R"({"width": 3, "height": 2, "values": [null, null, null, null, null, null]})");
  expect_refused({"run", "--algorithm", "erosion.pipe", "--input", input.string()}, {"erosion.pipe", "mask", "every cell"});
}

TEST_F(CliRefuses, UnknownParameterListsTheKnownNames) {
  expect_refused(ad_hoc(volcano, {"--set", "talos=3"}),
                 {"talos", "iterations", "talus_angle", "strength", "neighbourhood", "normalised"});
}

TEST_F(CliRefuses, OutOfRangeParameterNamesTheRange) {
  expect_refused(ad_hoc(volcano, {"--set", "talus_angle=95"}), {"talus_angle", "95", "[0, 85]"});
}

TEST_F(CliRefuses, NonIntegerIterations) {
  expect_refused(ad_hoc(volcano, {"--set", "iterations=2.5"}), {"iterations", "2.5", "integer"});
}

TEST_F(CliRefuses, MalformedAssignment) {
  expect_refused(ad_hoc(volcano, {"--set", "talus_angle"}), {"talus_angle", "name=value"});
}

TEST_F(CliRefuses, UnreadableImage) {
  const fs::path input = work_ / "garbage.png";
  std::string bytes(300, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 7919u + 13u) % 251u);
  write_text(input, bytes);
  expect_refused(ad_hoc(input), {"garbage.png"});
}

TEST_F(CliRefuses, MissingInputFile) {
  expect_refused(ad_hoc(work_ / "nowhere.tif"), {"nowhere.tif", "no such file"});
}

TEST_F(CliRefuses, VolcanoJsonBeyondTheLargestSide) {
  const fs::path input = work_ / "huge.json";
  write_text(input, R"({"width": 2000000, "height": 2000000, "values": []})");
  expect_refused(ad_hoc(input), {"huge.json", "2000000x2000000", "largest supported side"});
}

TEST_F(CliRefuses, VolcanoJsonLargerThanMemory) {
  const fs::path input = work_ / "big.json";
  write_text(input, R"({"width": 1000000, "height": 1000000, "values": []})");
  expect_refused(ad_hoc(input), {"big.json", "1000000x1000000", "GiB"});
}

TEST_F(CliRefuses, PngHeaderLargerThanMemory) {
  const fs::path input = work_ / "claims.png";
  write_text(input, png_header_only(1000000, 1000000));
  ASSERT_LT(fs::file_size(input), 100u);
  expect_refused(ad_hoc(input), {"claims.png", "1000000x1000000", "GiB"});
}

TEST_F(CliRefuses, OutputParentMissing) {
  const fs::path out = work_ / "no" / "such" / "report";
  const RunResult run = run_groundtruth({"run", "erosion.thermal.spec.*", "--out", out.string()}, cwd_);
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_NE(run.err.find("does not exist"), std::string::npos) << run;
  EXPECT_FALSE(fs::exists(work_ / "no"));
  EXPECT_TRUE(fs::is_empty(cwd_));
}

TEST_F(CliRefuses, OutputFolderHoldingUserFiles) {
  const fs::path out = work_ / "thesis";
  fs::create_directory(out);
  const std::string text = "my notes, not a report\n";
  write_text(out / "chapter1.txt", text);
  const auto stamp = fs::last_write_time(out / "chapter1.txt");
  const auto before = folder_entries(work_.path());
  const RunResult run = run_groundtruth({"run", "erosion.thermal.spec.*", "--out", out.string()}, cwd_);
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_NE(run.err.find("not a groundtruth report"), std::string::npos) << run;
  EXPECT_EQ(folder_entries(out), std::vector<std::string>{"chapter1.txt"});
  EXPECT_EQ(read_text(out / "chapter1.txt"), text);
  EXPECT_EQ(fs::last_write_time(out / "chapter1.txt"), stamp);
  EXPECT_EQ(folder_entries(work_.path()), before);
  EXPECT_TRUE(fs::is_empty(cwd_));
}

TEST_F(CliRefuses, OutputIsAFile) {
  const fs::path out = work_ / "results.csv";
  write_text(out, "a,b\n1,2\n");
  const RunResult run = run_groundtruth({"run", "erosion.thermal.spec.*", "--out", out.string()}, cwd_);
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_NE(run.err.find("not a folder"), std::string::npos) << run;
  EXPECT_EQ(read_text(out), "a,b\n1,2\n");
}

TEST_F(CliRefuses, UnknownAlgorithm) {
  expect_refused({"run", "--algorithm", "erosion.nope", "--input", volcano},
                 {"erosion.nope", "erosion.thermal", "erosion.thermal_jako"});
}

TEST_F(CliRefuses, PatternMatchingNoCase) { expect_refused({"run", "nothing.*"}, {"nothing.*"}); }

TEST_F(CliRefuses, NothingToRun) { expect_refused({"run"}, {"nothing to run"}); }

TEST_F(CliRefuses, AlgorithmWithoutInput) {
  expect_refused({"run", "--algorithm", "erosion.thermal"}, {"erosion.thermal", "--input"});
}

TEST_F(CliRefuses, FractalOctavesOutOfRange) {
  expect_refused({"run", "--algorithm", "noise.fbm", "--set", "octaves=0"}, {"octaves", "[1, 32]"});
}

TEST_F(CliRefuses, NonPositiveLacunarity) {
  expect_refused({"run", "--algorithm", "noise.fbm", "--set", "lacunarity=-2"}, {"lacunarity", "out of range"});
}

TEST_F(CliRefuses, OriginReductionWithNonIntegerLacunarity) {
  expect_refused({"run", "--algorithm", "noise.fbm", "--set", "lacunarity=2.5", "--set", "reduce_origin=true"},
                 {"reduce_origin", "integer lacunarity"});
}

TEST_F(CliRefuses, MalformedNoiseGridSize) {
  expect_refused({"run", "--algorithm", "noise.simplex3", "--size", "100000x0"}, {"--size", "WxH"});
}

TEST_F(CliRefuses, NoiseGridLargerThanMemory) {
  expect_refused({"run", "--algorithm", "noise.simplex3", "--size", "60000x60000"}, {"60000x60000", "GiB"});
}

TEST_F(CliRefuses, InputWithoutAlgorithm) { expect_refused({"run", "--input", volcano}, {"--algorithm", "--input"}); }

TEST_F(CliRefuses, UnknownGlBackend) {
  expect_refused({"run", "erosion.thermal.spec.*", "--gl", "vulkan"}, {"--gl", "vulkan", "egl", "osmesa"});
}

TEST_F(CliRefuses, UnknownBackend) {
  expect_refused({"run", "erosion.thermal.spec.*", "--backend", "fpga"}, {"--backend", "fpga"});
}

// ---- 4. list ---------------------------------------------------------------------------------

TEST(CliList, JsonListsParametersAndCases) {
  const TempDir work;
  const RunResult run = run_groundtruth({"list", "--json"}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  json listing;
  ASSERT_NO_THROW(listing = json::parse(run.out)) << run;
  ASSERT_TRUE(listing.at("algorithms").is_array());

  const json* thermal = nullptr;
  for (const auto& algorithm : listing.at("algorithms")) {
    if (algorithm.at("name") == "erosion.thermal") thermal = &algorithm;
  }
  ASSERT_NE(thermal, nullptr) << listing.dump(2);
  std::set<std::string> names;
  for (const auto& param : thermal->at("params")) {
    SCOPED_TRACE(param.dump());
    ASSERT_TRUE(param.contains("name") && param.contains("kind") && param.contains("default") && param.contains("unit"));
    names.insert(param.at("name").get<std::string>());
    const auto kind = param.at("kind").get<std::string>();
    const json& fallback = param.at("default");
    if (kind == "real" || kind == "integer") {
      ASSERT_TRUE(param.contains("min") && param.contains("max"));
      EXPECT_LE(param.at("min").get<double>(), fallback.get<double>());
      EXPECT_LE(fallback.get<double>(), param.at("max").get<double>());
      if (kind == "integer") {
        EXPECT_TRUE(fallback.is_number_integer());
      }
    } else if (kind == "choice") {
      ASSERT_TRUE(param.at("choices").is_array());
      EXPECT_NE(std::find(param.at("choices").begin(), param.at("choices").end(), fallback), param.at("choices").end());
    } else {
      EXPECT_EQ(kind, "boolean");
      EXPECT_TRUE(fallback.is_boolean());
    }
  }
  for (const char* name : {"iterations", "talus_angle", "strength", "neighbourhood"}) {
    EXPECT_TRUE(names.contains(name)) << name;
  }
  for (const auto& param : thermal->at("params")) {
    if (param.at("name") == "talus_angle") {
      EXPECT_EQ(param.at("unit"), "degree");
      EXPECT_EQ(param.at("min").get<double>(), 0.0);
      EXPECT_EQ(param.at("max").get<double>(), 85.0);
    }
  }

  // The cases are exactly those of datasets/cases/*.json, an entry with an A/B pair listed as its
  // two sides.
  std::set<std::string> expected_cases;
  for (const auto& entry : fs::directory_iterator(dataset_dir / "cases")) {
    if (entry.path().extension() != ".json") continue;
    for (const auto& spec : read_json(entry.path())) {
      const std::string name = spec.at("name").get<std::string>();
      if (spec.contains("ab")) {
        expected_cases.insert({name + ".a", name + ".b"});
      } else {
        expected_cases.insert(name);
      }
    }
  }
  ASSERT_FALSE(expected_cases.empty());
  std::set<std::string> listed_cases;
  for (const auto& spec : listing.at("cases")) listed_cases.insert(spec.at("name").get<std::string>());
  EXPECT_EQ(listed_cases, expected_cases);
  EXPECT_EQ(listing.at("cases").size(), expected_cases.size());
}

TEST(CliList, TextNamesAlgorithmsAndCases) {
  const TempDir work;
  const RunResult run = run_groundtruth({"list"}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  for (const char* needle : {"erosion.thermal", "erosion.thermal_jako", "talus_angle", "erosion.thermal.spec.example_3x3"}) {
    EXPECT_NE(run.out.find(needle), std::string::npos) << needle << "\n" << run;
  }
}

// A pattern names algorithms by name and cases by their own name or their algorithm's; --algorithms
// leaves the cases out; a pattern that names nothing is bad input. Ranges of whole numbers read as
// whole numbers.
TEST(CliList, PatternsAndAlgorithmsAloneFilterTheListing) {
  const TempDir work;
  const RunResult pipes = run_groundtruth({"list", "--json", "erosion.pipe*"}, work.path());
  ASSERT_EQ(pipes.status, 0) << pipes;
  const json listing = json::parse(pipes.out);
  ASSERT_EQ(listing.at("algorithms").size(), 1u);
  EXPECT_EQ(listing["algorithms"][0].at("name"), "erosion.pipe");
  ASSERT_FALSE(listing.at("cases").empty());
  for (const auto& spec : listing.at("cases")) EXPECT_EQ(spec.at("algorithm"), "erosion.pipe") << spec.dump();
  // A case pattern also names its algorithm's cases only, and the algorithm itself not.
  const json one = json::parse(run_groundtruth({"list", "--json", "erosion.thermal.spec.example_3x3"}, work.path()).out);
  EXPECT_TRUE(one.at("algorithms").empty());
  ASSERT_EQ(one.at("cases").size(), 1u);

  const RunResult alone = run_groundtruth({"list", "--algorithms", "noise.*"}, work.path());
  ASSERT_EQ(alone.status, 0) << alone;
  EXPECT_THAT(alone.out, ::testing::HasSubstr("noise.simplex3"));
  EXPECT_THAT(alone.out, ::testing::Not(::testing::HasSubstr("Cases")));
  EXPECT_THAT(alone.out, ::testing::Not(::testing::HasSubstr("erosion.")));

  const RunResult thermal = run_groundtruth({"list", "--algorithms", "erosion.thermal"}, work.path());
  EXPECT_THAT(thermal.out, ::testing::HasSubstr("[0, 100000]")) << thermal;  // iterations: an integer
  EXPECT_THAT(thermal.out, ::testing::HasSubstr("[0.0, 85.0]")) << thermal;  // talus_angle: a real

  const RunResult none = run_groundtruth({"list", "nothing*"}, work.path());
  EXPECT_EQ(none.status, 2) << none;
  EXPECT_THAT(none.err, ::testing::HasSubstr("no algorithm or case matches nothing*")) << none;
}

// --image-vertical-scale gives an ad-hoc 16-bit PNG its height range, as a case file's
// "vertical_scale" does, in the process and through a worker (-j 2 passes it on).
TEST(CliRun, ImageVerticalScaleSetsAnAdHocPngsHeightRange) {
  const TempDir work;
  {
    std::vector<std::uint16_t> ramp(16 * 16);
    for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = static_cast<std::uint16_t>(i % 16 == 15 ? 65535 : i % 16 * 4000);
    auto out = OIIO::ImageOutput::create((work.path() / "ramp.png").string());
    ASSERT_TRUE(out && out->open((work.path() / "ramp.png").string(), OIIO::ImageSpec(16, 16, 1, OIIO::TypeDesc::UINT16)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, ramp.data()) && out->close());
  }
  for (const char* parallel : {"1", "2"}) {
    const fs::path out = work.path() / (std::string("scaled_j") + parallel);
    const RunResult run = run_groundtruth({"run", "--algorithm", "erosion.thermal", "--input", "ramp.png",
                                           "--image-vertical-scale", "250", "--set", "iterations=0", "--backend", "cpu",
                                           "-j", parallel, "--out", out.string()},
                                          work.path());
    ASSERT_EQ(run.status, 0) << run;
    const auto terrain = gt::read_heightmap(out / "adhoc.erosion.thermal.ramp" / "terrain_cpu.npy").heights;
    EXPECT_DOUBLE_EQ(*std::max_element(terrain.values.begin(), terrain.values.end()), 250.0) << parallel;
  }
  const RunResult refused = run_groundtruth(
      {"run", "--algorithm", "erosion.thermal", "--input", "ramp.png", "--image-vertical-scale", "0", "--out", "x"},
      work.path());
  EXPECT_EQ(refused.status, 2) << refused;
}

// --version names the source tree's revision (git describe) and the build, and exits 0.
TEST(CliVersion, NamesTheRevisionAndTheBuild) {
  const TempDir work;
  const RunResult run = run_groundtruth({"--version"}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  EXPECT_THAT(run.out, ::testing::MatchesRegex("groundtruth [^ ]+ \\([A-Za-z]+ build, configured at [^ )]+\\)\n")) << run;
}

// ---- 5. atomic replacement of a report folder ------------------------------------------------

TEST(CliRun, ReportFolderIsReplacedWhole) {
  const TempDir work;
  const fs::path out = work / "report";
  const RunResult first = run_groundtruth({"run", "erosion.thermal.spec.*", "--out", out.string()}, work.path());
  ASSERT_EQ(first.status, 0) << first;
  ASSERT_TRUE(fs::is_regular_file(out / "report.json"));
  EXPECT_NE(read_json(out / "report.json").at("environment").at("gl_platform"), "none");

  const RunResult second = run_groundtruth(
      {"run", "erosion.thermal.spec.*", "--backend", "cpu", "--out", out.string()}, work.path());
  ASSERT_EQ(second.status, 0) << second;
  const json report = read_json(out / "report.json");
  ASSERT_TRUE(report.is_object());
  EXPECT_EQ(report.at("environment").at("gl_platform"), "none") << "report.json is not the second run's";
  EXPECT_EQ(folder_entries(work.path()), std::vector<std::string>{"report"})
      << "staging, previous or lock (.report.groundtruth-*) left beside the report";

  // A file the user put into the report folder since is theirs: the folder is no longer replaced.
  write_text(out / "my-notes.txt", "from the user\n");
  const RunResult third = run_groundtruth({"run", "erosion.thermal.spec.*", "--backend", "cpu", "--out", out.string()},
                                          work.path());
  EXPECT_EQ(third.status, 2) << third;
  EXPECT_NE(third.err.find("my-notes.txt was added"), std::string::npos) << third;
  EXPECT_EQ(read_text(out / "my-notes.txt"), "from the user\n");
}

// ---- 6. no GPU context -----------------------------------------------------------------------

TEST(CliRun, MissingGlContextSkipsGpuChecks) {
  const TempDir work;
  const fs::path out = work / "report";
  // libglvnd loads no EGL vendor, so no EGL display exists.
  const RunResult run = run_groundtruth({"run", "erosion.thermal.spec.*", "--gl", "egl", "--out", out.string()},
                                        work.path(), {{"__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json"}});
  ASSERT_EQ(run.status, 0) << run;
  EXPECT_NE(run.err.find("EGL"), std::string::npos) << run;
  EXPECT_NE(run.err.find("GPU checks are skipped"), std::string::npos) << run;
  const json report = read_json(out / "report.json");
  ASSERT_TRUE(report.is_object());
  EXPECT_EQ(report.at("environment").at("gl_platform"), "none");
  EXPECT_EQ(report.at("environment").at("gl_renderer").get<std::string>().rfind("none", 0), 0u)
      << report.at("environment").dump();
  ASSERT_EQ(report.at("cases").size(), 1u);
  const json& report_case = report.at("cases")[0];
  EXPECT_EQ(report_case.at("status"), "skip") << "a skipped GPU half is never a pass: " << report_case.dump(2);
  int gpu_checks = 0;
  for (const auto& check : report_case.at("checks")) {
    const auto name = check.at("name").get<std::string>();
    const bool gpu = name.ends_with(".gpu") || name.find("gpu_vs") != std::string::npos;
    if (!gpu) continue;
    ++gpu_checks;
    EXPECT_EQ(check.at("status"), "skip") << check.dump();
    ASSERT_TRUE(check.contains("detail")) << check.dump();
    EXPECT_NE(check.at("detail").get<std::string>().find("no GL context"), std::string::npos) << check.dump();
  }
  EXPECT_GE(gpu_checks, 6);  // mass, 4 parity, determinism (and the spec vectors)
  const json* cpu_drift = find_check(report_case, "mass.relative_drift.cpu");
  ASSERT_NE(cpu_drift, nullptr);
  EXPECT_EQ(cpu_drift->at("status"), "pass");
  EXPECT_LE(cpu_drift->at("value").get<double>(), cpu_mass_drift_bound);
  const json* spec_cells = find_check(report_case, "spec.cells.cpu");
  ASSERT_NE(spec_cells, nullptr);
  EXPECT_EQ(spec_cells->at("status"), "pass");
  for (const auto& artifact : report_case.at("artifacts")) {
    EXPECT_EQ(artifact.get<std::string>().find("gpu"), std::string::npos) << "GPU artifact without a GPU: " << artifact;
  }
  expect_artifacts_exist(report_case, out);
}

// ---- 7. check-mesh --------------------------------------------------------------------------

// The exit status says watertight (0), not (1) or unreadable (2); --json is one parseable object
// whose verdict matches the status; a file the readers reject is refused with its name.
TEST(CliCheckMesh, ExitStatusFollowsTheVerdict) {
  const TempDir work;
  const fs::path tetrahedron = work / "tetrahedron.off";
  write_text(tetrahedron, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const RunResult closed = run_groundtruth({"check-mesh", tetrahedron.string()}, work.path());
  EXPECT_EQ(closed.status, 0) << closed;
  EXPECT_NE(closed.out.find("watertight and consistently oriented"), std::string::npos) << closed;

  const fs::path open = work / "open.obj";
  write_text(open, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  const RunResult holed = run_groundtruth({"check-mesh", open.string(), "--json"}, work.path());
  EXPECT_EQ(holed.status, 1) << holed;
  const json verdict = json::parse(holed.out, nullptr, false);
  ASSERT_FALSE(verdict.is_discarded()) << holed;
  EXPECT_EQ(verdict.at("format"), "obj");
  EXPECT_EQ(verdict.at("report").at("raw").at("border_edges"), 3) << verdict.dump(2);
  // Where: the hole's three edges by their input vertices (0-based) and midpoints.
  const json& border = verdict.at("locations").at("border_edges");
  ASSERT_EQ(border.size(), 3u) << verdict.dump(2);
  EXPECT_EQ(border[0].at("vertices"), json({1, 2}));
  EXPECT_EQ(border[0].at("at"), json({0.5, 0.5, 0.0}));
  EXPECT_EQ(border[2].at("vertices"), json({2, 3}));
  EXPECT_EQ(border[2].at("at"), json({0.0, 0.5, 0.5}));

  // A flipped face: its three edges are each used twice in one direction, and are listed.
  const fs::path flipped = work / "flipped.off";
  write_text(flipped, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 3 2\n");
  const RunResult turned = run_groundtruth({"check-mesh", flipped.string(), "--json"}, work.path());
  EXPECT_EQ(turned.status, 1) << turned;
  const json misoriented = json::parse(turned.out).at("locations").at("misoriented_edges");
  EXPECT_EQ(misoriented, json::parse(R"([{"vertices": [1, 2], "at": [0.5, 0.5, 0.0]},
                                         {"vertices": [1, 3], "at": [0.5, 0.0, 0.5]},
                                         {"vertices": [2, 3], "at": [0.0, 0.5, 0.5]}])"));

  // Two triangles through each other: the pair, by each face's vertices, where they cross.
  const fs::path crossing = work / "crossing.obj";
  write_text(crossing, "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0.5 0.5 -1\nv 0.5 0.5 1\nv 1.5 0.5 0\nf 1 2 3\nf 4 5 6\n");
  const RunResult crossed = run_groundtruth({"check-mesh", crossing.string(), "--json"}, work.path());
  EXPECT_EQ(crossed.status, 1) << crossed;
  const json pairs = json::parse(crossed.out).at("locations").at("self_intersections");
  ASSERT_EQ(pairs.size(), 1u) << crossed.out;
  std::set<std::set<int>> faces;
  for (const auto& face : pairs[0].at("faces")) faces.insert(face.get<std::set<int>>());
  EXPECT_EQ(faces, (std::set<std::set<int>>{{0, 1, 2}, {3, 4, 5}}));

  const fs::path truncated = work / "truncated.off";
  write_text(truncated, "OFF\n4 4 0\n0 0 0\n1 0 0\n");
  for (const fs::path& bad : {truncated, work / "missing.ply", work / "mesh.xyz"}) {
    const RunResult refused = run_groundtruth({"check-mesh", bad.string()}, work.path());
    EXPECT_EQ(refused.status, 2) << refused;
    EXPECT_NE(refused.err.find(bad.filename().string()), std::string::npos) << refused;
    EXPECT_EQ(refused.err.find("internal error"), std::string::npos) << refused;
  }
}

}  // namespace
