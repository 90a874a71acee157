#include "compare/field_files.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/report/report_common.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/io/volume_io.hpp"
#include "core/json_keys.hpp"

namespace gt {
namespace {

nlohmann::json grid_of(const Grid<double>& values) {
  return {{"width", values.width}, {"height", values.height}, {"cell_size_x", values.cell_size_x},
          {"cell_size_y", values.cell_size_y}, {"horizontal_unit", values.horizontal_unit}};
}

nlohmann::json grid_of(const Volume<double>& volume) {
  return {{"nx", volume.nx}, {"ny", volume.ny}, {"nz", volume.nz}, {"spacing", volume.spacing},
          {"origin", volume.origin}};
}

// Adds the file's entry to the case's fields.json, made with the case's provenance and `grid` (the
// first field's) on the case's first call.
void describe_field_file(const std::filesystem::path& folder, const nlohmann::json& grid, const FieldFile& file,
                         const nlohmann::json& formats, const char* npy_dtype, CaseResult& result) {
  const auto sidecar = folder / "fields.json";
  const bool first = !std::filesystem::exists(sidecar);
  nlohmann::json described;
  if (first) {
    described = {{"case", result.name}, {"algorithm", result.algorithm}, {"params", result.params},
                 {"input", result.input}, {"grid", grid},                {"files", nlohmann::json::array()}};
  } else {
    std::ifstream in(sidecar);
    described = parse_json_bounded(in, sidecar.string());
  }
  nlohmann::json entry = {{"stem", file.stem},       {"formats", formats}, {"field", file.field},
                          {"backend", file.backend}, {"unit", file.unit},  {"meaning", file.meaning},
                          {"npy_dtype", npy_dtype}};
  if (grid != described["grid"]) entry["grid"] = grid;  // a field on another grid than the first's
  described["files"].push_back(entry);
  write_file_atomically(sidecar, described.dump(2) + '\n');
  if (first) {
    result.artifacts.push_back({result.name + "/fields.json", "field",
                                "what each field file holds: field, backend, unit, meaning; the case's parameters, "
                                "input and grid"});
  }
}

std::filesystem::path case_folder(const RunOptions& options, const CaseResult& result) {
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace

void write_field_files(const Grid<double>& values, const FieldFile& file, const RunOptions& options,
                       CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = case_folder(options, result);
  // ref<double>'s fields keep their precision in the .npy: a float32 copy would round away the
  // differences from ref<float> that the parity checks measure.
  const bool double_reference = file.backend == "cpu";
  write_heightmap(values, folder / (file.stem + ".exr"));
  write_heightmap(values, folder / (file.stem + ".npy"), double_reference ? NpyPrecision::float64 : NpyPrecision::float32);
  const std::string what = fmt::format("{} ({}, {})", file.meaning, file.field, file.unit);
  const char* npy_dtype = double_reference ? "float64" : "float32";
  result.artifacts.push_back({result.name + "/" + file.stem + ".exr", "field", what + ", float32 EXR"});
  result.artifacts.push_back({result.name + "/" + file.stem + ".npy", "field",
                              fmt::format("{}, {} NumPy array (height, width), NaN no-data", what, npy_dtype)});
  describe_field_file(folder, grid_of(values), file, {"exr", "npy"}, npy_dtype, result);
}

void write_volume_field_file(const Volume<double>& values, const FieldFile& file, const RunOptions& options,
                             CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = case_folder(options, result);
  write_volume(values, folder / (file.stem + ".npy"));
  // For image tools, the z slices one under the other: the volume's own order, x fastest, then y,
  // then z, is that of an nx x (ny·nz) image.
  Grid<double> slices(values.nx, values.ny * values.nz);
  slices.values = values.values;
  slices.horizontal_unit = "sample";
  write_heightmap(slices, folder / (file.stem + ".exr"));
  const std::string what = fmt::format("{} ({}, {})", file.meaning, file.field, file.unit);
  result.artifacts.push_back({result.name + "/" + file.stem + ".npy", "field", what + ", float32 NumPy array (nz, ny, nx)"});
  result.artifacts.push_back({result.name + "/" + file.stem + ".exr", "field",
                              what + ", float32 EXR of the z slices one under the other (row z·ny + y)"});
  describe_field_file(folder, grid_of(values), file, {"exr", "npy"}, "float32", result);
}

}  // namespace gt
