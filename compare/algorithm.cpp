#include "compare/algorithm.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"

namespace gt {
namespace {

// What each algorithm's checks read from a case's "expect" (null: any value; an object: its keys;
// [object]: each element's keys). Field twins share the spec vectors of compare/field_twin.cpp.
nlohmann::json expect_shape_of(const Algorithm& algorithm) {
  using json = nlohmann::json;
  json field_spec = {{"cells", nullptr}, {"total", nullptr}, {"tolerance", nullptr}};
  if (algorithm.name == "erosion.thermal") {
    field_spec["talus_eq_4_10"] = {{"angle", nullptr}, {"width", nullptr}, {"vertical_aspect", nullptr}, {"value", nullptr}};
    return field_spec;
  }
  if (algorithm.name == "erosion.thermal_jako") return field_spec;
  if (algorithm.name.rfind("noise.", 0) == 0) {
    field_spec["points"] = nullptr;
    field_spec["lattice_nonnegative"] = {{"size", nullptr}, {"count", nullptr}};
    field_spec["walk"] = {{"magnitudes", nullptr}, {"direction", nullptr}};
    return field_spec;
  }
  if (algorithm.name == "cave.marching_tetrahedra") return {{"triangles", nullptr}};
  if (algorithm.name == "mesh.check") {
    return {{"watertight", nullptr}, {"closed", nullptr},       {"genus", nullptr},
            {"euler", nullptr},      {"border_edges", nullptr}, {"self_intersections", nullptr}};
  }
  return json::object();
}

}  // namespace

const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> all = [] {
    std::vector<Algorithm> list = {thermal_algorithm(), thermal_jako_algorithm(), pipe_algorithm()};
    for (auto& algorithm : noise_algorithms()) list.push_back(std::move(algorithm));
    for (auto& algorithm : cave_algorithms()) list.push_back(std::move(algorithm));
    list.push_back(cave_endless_algorithm());
    list.push_back(mesh_check_algorithm());
    list.push_back(render_heightmap_algorithm());
    list.push_back(render_phong_algorithm());
    list.push_back(render_terrain_algorithm());
    for (auto& algorithm : list) {
      if (algorithm.expect_shape.empty()) algorithm.expect_shape = expect_shape_of(algorithm);
    }
    return list;
  }();
  return all;
}

const Algorithm& find_algorithm(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& algorithm : algorithms()) {
    if (algorithm.name == name) return algorithm;
    names.push_back(algorithm.name);
  }
  throw InputError(fmt::format("unknown algorithm '{}'; known: {}", name, fmt::join(names, ", ")));
}

}  // namespace gt
