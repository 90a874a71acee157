// check-mesh: read the file, check it, print, and map the verdict to the exit status.
#include "compare/cli/check_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/checks/mesh.hpp"
#include "compare/checks/vertex_values_ply.hpp"
#include "compare/output_folder.hpp"
#include "core/errors.hpp"
#include "core/io/mesh_io.hpp"

namespace gt {

namespace {

constexpr int exit_watertight = 0;
constexpr int exit_not_watertight = 1;
constexpr int exit_unreadable = 2;

void print_report(const std::filesystem::path& file, const MeshFile& read, const MeshReport& report, bool as_json) {
  if (as_json) {
    const nlohmann::json out = {
        {"file", file.string()}, {"format", read.format},          {"notes", read.notes},
        {"report", to_json(report)}, {"locations", locations_json(report)}};
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("{} ({}): {}\n", file.string(), read.format, describe(report));
  for (const std::string& note : read.notes) fmt::print("  note: {}\n", note);
}

// Each vertex's count of the problems located at it (an edge's two ends, a face pair's six corners).
std::vector<double> problems_at_vertices(const MeshReport& report, std::size_t vertices) {
  std::vector<double> problems(vertices, 0.0);
  for (const auto* edges : {&report.raw.border_edges_at, &report.raw.non_manifold_edges_at, &report.raw.misoriented_edges_at}) {
    for (const EdgeAt& edge : *edges) {
      for (const std::uint32_t vertex : edge.vertices) problems[vertex] += 1.0;
    }
  }
  for (const FacePairAt& pair : report.cgal.self_intersections_at) {
    for (const auto& face : pair.faces) {
      for (const std::size_t vertex : face) problems[vertex] += 1.0;
    }
  }
  return problems;
}

void refuse_annotation_path(const std::filesystem::path& file, const std::filesystem::path& annotate) {
  if (annotate.extension() != ".ply") {
    throw InputError(fmt::format("--annotate {}: the annotated mesh is written as .ply", annotate.string()));
  }
  if (same_file(annotate, file)) {
    throw InputError(fmt::format("--annotate {}: that is the mesh being checked", annotate.string()));
  }
}

}  // namespace

int check_mesh_command(const std::filesystem::path& file, bool as_json, const std::filesystem::path& annotate) {
  try {
    if (!annotate.empty()) refuse_annotation_path(file, annotate);
    const MeshFile read = read_mesh(file);
    const MeshReport report = check_mesh(read.mesh);
    if (!annotate.empty()) {
      const std::vector<double> problems = problems_at_vertices(report, read.mesh.positions.size());
      const double most = *std::max_element(problems.begin(), problems.end());
      const std::size_t left_out = write_vertex_values_ply(read.mesh, problems, "problems", std::max(most, 1.0), annotate);
      if (left_out > 0) {
        fmt::print(stderr, "groundtruth: {}: {} faces left out (a half-edge mesh cannot hold them: a non-manifold or "
                           "misoriented edge, a repeated corner); their vertices keep their colours\n",
                   annotate.string(), left_out);
      }
    }
    print_report(file, read, report, as_json);
    return is_watertight_and_oriented(report) ? exit_watertight : exit_not_watertight;
  } catch (const InputError& error) {
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_unreadable;
  }
}

}  // namespace gt
