#include "compare/peers/vtk_isosurface.hpp"

#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/subprocess.hpp"
#include "core/io/volume_io.hpp"
#include "core/json_keys.hpp"

#if !defined(GT_PYTHON_WITH_VTK) || !defined(GT_SOURCE_DIR)
#error "compare/peers/vtk_isosurface.cpp needs the compile definitions GT_PYTHON_WITH_VTK and GT_SOURCE_DIR"
#endif

namespace gt {
namespace {

constexpr const char* python = GT_PYTHON_WITH_VTK;
constexpr const char* script = GT_SOURCE_DIR "/compare/peers/vtk_isosurface.py";

}  // namespace

std::vector<IsosurfacePeerRun> run_vtk_isosurface(const Volume<double>& density, double threshold, int reps) {
  if (std::string_view(python).empty()) {
    throw std::runtime_error("no Python with VTK (python3-vtk9) was found when the build was configured");
  }
  const auto folder = temporary_path("gt-vtk", "");
  const TemporaryFiles temporaries{{folder}};
  std::filesystem::create_directories(folder);
  write_volume(density, folder / "density.npy");
  const std::string failure = run_logged({python, script, (folder / "density.npy").string(), fmt::format("{:.17g}", threshold),
                                          std::to_string(reps), (folder / "times.json").string()},
                                         folder / "log.txt");
  if (!failure.empty()) throw std::runtime_error(failure);
  std::ifstream in(folder / "times.json");
  const auto document = parse_json_bounded(in, (folder / "times.json").string());
  std::vector<IsosurfacePeerRun> runs;
  for (const auto& filter : document.at("filters")) {
    runs.push_back({.name = fmt::format("VTK {} {} (float32, 1 thread)", document.at("vtk_version").get<std::string>(),
                                        filter.at("name").get<std::string>()),
                    .ms = filter.at("ms").get<std::vector<double>>(),
                    .triangles = filter.at("triangles").get<std::size_t>()});
  }
  return runs;
}

}  // namespace gt
