#include "compare/field_files.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/io/heightmap_io.hpp"

namespace gt {
namespace {

nlohmann::json provenance(const Grid<double>& values, const CaseResult& result) {
  return {{"case", result.name},
          {"algorithm", result.algorithm},
          {"params", result.params},
          {"input", result.input},
          {"grid", {{"width", values.width}, {"height", values.height}, {"cell_size_x", values.cell_size_x},
                    {"cell_size_y", values.cell_size_y}, {"horizontal_unit", values.horizontal_unit}}},
          {"files", nlohmann::json::array()}};
}

// The sidecar as the case's earlier calls left it, or a new one.
nlohmann::json read_sidecar(const std::filesystem::path& sidecar, const Grid<double>& values, const CaseResult& result) {
  if (!std::filesystem::exists(sidecar)) return provenance(values, result);
  std::ifstream in(sidecar);
  return nlohmann::json::parse(in);
}

}  // namespace

void write_field_files(const Grid<double>& values, const FieldFile& file, const RunOptions& options,
                       CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  write_heightmap(values, folder / (file.stem + ".exr"));
  write_heightmap(values, folder / (file.stem + ".npy"));
  const std::string what = fmt::format("{} ({}, {})", file.meaning, file.field, file.unit);
  result.artifacts.push_back({result.name + "/" + file.stem + ".exr", "field", what + ", float32 EXR"});
  result.artifacts.push_back(
      {result.name + "/" + file.stem + ".npy", "field", what + ", float32 NumPy array (height, width), NaN no-data"});
  const auto sidecar = folder / "fields.json";
  const bool first = !std::filesystem::exists(sidecar);
  nlohmann::json described = read_sidecar(sidecar, values, result);
  described["files"].push_back({{"stem", file.stem},
                                {"formats", {"exr", "npy"}},
                                {"field", file.field},
                                {"backend", file.backend},
                                {"unit", file.unit},
                                {"meaning", file.meaning}});
  std::ofstream out(sidecar);
  out << described.dump(2) << '\n';
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", sidecar.string()));
  if (first) {
    result.artifacts.push_back({result.name + "/fields.json", "field",
                                "what each field file holds: field, backend, unit, meaning; the case's parameters, "
                                "input and grid"});
  }
}

}  // namespace gt
