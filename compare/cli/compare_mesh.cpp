// compare-mesh: read both files, compare their topology and their surfaces, say where they differ.
#include "compare/cli/compare_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "compare/checks/mesh.hpp"
#include "compare/checks/vertex_values_ply.hpp"
#include "compare/output_folder.hpp"
#include "core/errors.hpp"
#include "core/io/mesh_io.hpp"

namespace gt {
namespace {

constexpr int exit_same = 0;
constexpr int exit_different = 1;
constexpr int exit_bad_input = 2;
constexpr std::size_t farthest_listed = 10;
constexpr double default_grid_fraction = 1.0 / 200.0;  // of the larger bounding-box diagonal

struct Side {
  std::filesystem::path file;
  MeshFile read;
  MeshReport report;
  std::vector<VertexDistance> to_other;  // each vertex's distance to the other mesh
  double sampled = 0.0;                  // CGAL's one-sided distance to the other mesh
};

double diagonal(const Mesh& mesh) {
  const Box3<double> box = bounding_box(mesh);
  return std::hypot(box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2]);
}

nlohmann::json topology_json(const MeshReport& report) {
  return {{"watertight_and_oriented", is_watertight_and_oriented(report)},
          {"closed", report.cgal.closed},
          {"components", report.openmesh.components},
          {"genus", report.openmesh.genus},
          {"euler", report.openmesh.euler_characteristic}};
}

// The topology facts that differ between the two, by name.
std::vector<std::string> topology_differences(const MeshReport& a, const MeshReport& b) {
  std::vector<std::string> differing;
  const nlohmann::json facts_a = topology_json(a), facts_b = topology_json(b);
  for (const auto& [name, value] : facts_a.items()) {
    if (value != facts_b[name]) differing.push_back(fmt::format("{} ({} against {})", name, value.dump(), facts_b[name].dump()));
  }
  return differing;
}

double largest_vertex_distance(const std::vector<VertexDistance>& distances) {
  double largest = 0.0;
  for (const auto& distance : distances) {
    if (!std::isnan(distance.distance)) largest = std::max(largest, distance.distance);
  }
  return largest;
}

nlohmann::json farthest_json(const Side& side) {
  std::vector<std::size_t> order;
  for (std::size_t vertex = 0; vertex < side.to_other.size(); ++vertex) {
    if (!std::isnan(side.to_other[vertex].distance)) order.push_back(vertex);
  }
  const std::size_t listed = std::min(farthest_listed, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(listed), order.end(),
                    [&](std::size_t x, std::size_t y) { return side.to_other[x].distance > side.to_other[y].distance; });
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t k = 0; k < listed; ++k) {
    const std::size_t vertex = order[k];
    const auto& distance = side.to_other[vertex];
    list.push_back({{"vertex", vertex},
                    {"at", side.read.mesh.positions[vertex]},
                    {"distance", std::isfinite(distance.distance) ? nlohmann::json(distance.distance) : nlohmann::json()},
                    {"nearest", std::isfinite(distance.distance) ? nlohmann::json(distance.nearest) : nlohmann::json()}});
  }
  return list;
}

nlohmann::json side_json(const Side& side) {
  return {{"file", side.file.string()},
          {"format", side.read.format},
          {"notes", side.read.notes},
          {"vertices", side.read.mesh.positions.size()},
          {"triangles", side.read.mesh.triangles.size()},
          {"topology", topology_json(side.report)},
          {"area", side.report.cgal.area},
          {"volume", side.report.cgal.volume ? nlohmann::json(*side.report.cgal.volume) : nlohmann::json()},
          {"sampled_distance_to_other", side.sampled},
          {"largest_vertex_distance_to_other", largest_vertex_distance(side.to_other)},
          {"farthest_vertices", farthest_json(side)}};
}

std::string where_text(const Side& side, const char* from, const char* to) {
  const nlohmann::json farthest = farthest_json(side);
  if (farthest.empty() || farthest[0]["distance"].is_null()) return "";
  const auto& first = farthest[0];
  const auto at = first["at"].get<std::array<double, 3>>();
  return fmt::format("  farthest vertex of {} from {}: #{} at ({:.6g}, {:.6g}, {:.6g}), {:.6g} away\n", from, to,
                     first["vertex"].get<std::size_t>(), at[0], at[1], at[2], first["distance"].get<double>());
}

void print_paragraph(const Side& a, const Side& b, double symmetric, double spacing,
                     const std::vector<std::string>& differing, const CompareMeshOptions& options, bool same) {
  fmt::print("{} ({}, {} triangles) against {} ({}, {} triangles): {}\n", a.file.string(), a.read.format,
             a.read.mesh.triangles.size(), b.file.string(), b.read.format, b.read.mesh.triangles.size(),
             same ? "the same within what was asked" : "they differ");
  fmt::print("  topology: {}\n", differing.empty() ? "the same (watertight and oriented, closed, components, genus, "
                                                     "Euler characteristic)"
                                                   : fmt::format("differs in {}", fmt::join(differing, ", ")));
  fmt::print("  Hausdorff distance {:.6g} (A to B {:.6g}, B to A {:.6g}; CGAL's grid sampling every {:.3g}){}\n",
             symmetric, a.sampled, b.sampled, spacing,
             options.tolerance ? fmt::format(", tolerance {:.6g}", *options.tolerance) : ", no tolerance given: shown, not judged");
  fmt::print("{}{}", where_text(a, "A", "B"), where_text(b, "B", "A"));
  for (const auto& note : a.read.notes) fmt::print("  note (A): {}\n", note);
  for (const auto& note : b.read.notes) fmt::print("  note (B): {}\n", note);
}

void write_coloured_meshes(const CompareMeshOptions& options, const Side& a, const Side& b, double scale) {
  write_folder_atomically(options.out, [&](const std::filesystem::path& folder) {
    for (const auto& [side, name] : {std::pair{&a, "a_to_b.ply"}, std::pair{&b, "b_to_a.ply"}}) {
      std::vector<double> distances;
      for (const VertexDistance& distance : side->to_other) distances.push_back(distance.distance);
      const std::size_t left_out = write_vertex_values_ply(side->read.mesh, distances, "distance", scale, folder / name);
      if (left_out > 0) {
        fmt::print(stderr, "groundtruth: {}: {} faces left out (a non-manifold edge or vertex, or unusable)\n", name,
                   left_out);
      }
    }
  });
}

}  // namespace

int compare_mesh_command(const CompareMeshOptions& options) {
  try {
    Side a{.file = options.a, .read = read_mesh(options.a)};
    Side b{.file = options.b, .read = read_mesh(options.b)};
    if (!options.out.empty()) {
      for (const auto& input : {options.a, options.b}) refuse_input_inside_output(options.out, input, "compare-mesh");
      check_output_folder(options.out);
    }
    const double spacing =
        options.spacing.value_or(default_grid_fraction * std::max(diagonal(a.read.mesh), diagonal(b.read.mesh)));
    if (!(spacing > 0.0)) throw InputError("compare-mesh: both meshes lie in one point; give --spacing");
    a.report = check_mesh(a.read.mesh);
    b.report = check_mesh(b.read.mesh);
    a.to_other = vertex_distances(a.read.mesh, b.read.mesh);
    b.to_other = vertex_distances(b.read.mesh, a.read.mesh);
    a.sampled = approximate_one_sided_hausdorff_distance(a.read.mesh, b.read.mesh, spacing);
    b.sampled = approximate_one_sided_hausdorff_distance(b.read.mesh, a.read.mesh, spacing);
    // The sampled distance can miss a vertex the exact query finds: take the larger of the two.
    const double symmetric = std::max({a.sampled, b.sampled, largest_vertex_distance(a.to_other),
                                       largest_vertex_distance(b.to_other)});
    const std::vector<std::string> differing = topology_differences(a.report, b.report);
    const bool same = differing.empty() && (!options.tolerance || symmetric <= *options.tolerance);
    if (!options.out.empty()) write_coloured_meshes(options, a, b, symmetric);
    if (options.as_json) {
      const nlohmann::json out = {{"a", side_json(a)},
                                  {"b", side_json(b)},
                                  {"hausdorff", symmetric},
                                  {"grid_spacing", spacing},
                                  {"topology_differs", differing},
                                  {"tolerance", options.tolerance ? nlohmann::json(*options.tolerance) : nlohmann::json()},
                                  {"same", same},
                                  {"coloured_meshes", options.out.empty() ? nlohmann::json()
                                                                          : nlohmann::json(options.out.string())}};
      fmt::print("{}\n", out.dump(2));
    } else {
      print_paragraph(a, b, symmetric, spacing, differing, options, same);
    }
    return same ? exit_same : exit_different;
  } catch (const InputError& error) {
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_bad_input;
  }
}

}  // namespace gt
