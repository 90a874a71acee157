// `cave.endless`: seed 004's endless cave (digest §2.7) along a scripted camera path. A big cube
// of size_x × size_y × size_z cells at origin_* (the seed's BIG_CUBE_SIZE = 30), then `slabs`
// slabs of one cell appended on the `direction` face, one per lattice unit the camera flies: the
// path of a camera that keeps to the centre of its window (the seed's dead band, TOLERANCE). Every
// piece is an open chunk meshed on its own by marching tetrahedra, on the CPU (ref<double>, and
// ref<float> for the GPU's parity) and on the GPU (one mesher moved from slab to slab).
//
// Decisions where the seed is vague: the camera flies straight, so every slab covers the window's
// face exactly (BIG_CUBE_SIZE × BIG_CUBE_SIZE × 1); chunks are never regenerated, so no region is
// generated twice; the ring buffer is the seed's MAX_VERTICES soup vertices (rounded down to a
// multiple of 3 so no triangle is torn) overwritten oldest first, with each soup vertex holding a
// position and a normal (2 × 3 floats = 24 bytes), as the seed's two std::vector<glm::vec3>.
//
// Checks (backend cpu = ref<double>, gpu = the GPU twin):
//   seams.unmatched_border_edges.{cpu,gpu}   on the plane between consecutive chunks, border
//                          edges of one chunk without the reversed edge in the other (must be 0:
//                          the union is seamless)
//   seams.vertex_bits.{cpu,gpu}    vertices of one edge key whose positions differ in any bit
//                          between two chunks (must be 0)
//   mesh.*.union_{cpu,gpu}        the chunks welded by edge key, checked as one open surface
//                          (compare/checks/mesh.hpp), with mesh.border_off_box: border edges only
//                          on the faces of the union's box
//   parity.chunked_vs_monolithic.cpu   triangles (by edge key) or vertex bits that differ from one
//                          marching-tetrahedra run over the union's box (must be 0)
//   parity.topology.gpu_vs_float, parity.max_abs.gpu_vs_float   chunk by chunk, as the block cases
//   ring.window_missing_triangles   the largest number, over the path, of triangles inside the
//                          camera's window that the ring buffer has already overwritten (the
//                          seed's "places with visibly missing data"): `warn` above 0, not a
//                          failure: it is the seed's budget, not a meshing error
//   ring.high_water_bytes, ring.triangles_held   informative; plot of the path.
#include "compare/algorithms/cave.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <unordered_map>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/checks/cave_mesh.hpp"
#include "compare/checks/mesh.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/plots.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/params/cave.hpp"
#include "gpu/cave/marching_tetrahedra.hpp"
#include "gpu/timing.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_tetrahedra.hpp"

namespace gt {
namespace {

constexpr std::size_t bytes_per_soup_vertex = 2 * 3 * sizeof(float);  // position and normal

// The path of a case (CaveEndlessParams), its direction as an axis and a sign.
struct Path {
  CaveParams big_cube;
  int slabs;
  int axis;  // the direction of flight
  int sign;
  std::size_t max_vertices;  // a multiple of 3
};

const ParamSpecs& endless_specs() {
  static const ParamSpecs specs = param_specs(cave_endless_param_table());
  return specs;
}

Path path_from_json(const nlohmann::json& resolved) {
  const auto given = params_from_json(cave_endless_param_table(), resolved);
  Path path;
  path.big_cube = given.big_cube;
  require_noise_range(path.big_cube);
  if (path.big_cube.solid) throw InputError("cave.endless is made of open chunks: set solid=false");
  path.slabs = given.slabs;
  path.sign = given.direction[0] == '+' ? 1 : -1;
  path.axis = given.direction[1] - 'x';
  path.max_vertices = given.max_vertices / 3 * 3;
  return path;
}

// Chunk 0 is the big cube, chunk k the k-th slab.
CaveParams chunk_params(const Path& path, int chunk) {
  CaveParams params = path.big_cube;
  if (chunk == 0) return params;
  const int axis = path.axis;
  params.size[axis] = 1;
  params.origin[axis] = path.sign > 0 ? path.big_cube.origin[axis] + path.big_cube.size[axis] + chunk - 1
                                      : path.big_cube.origin[axis] - chunk;
  return params;
}

// The camera's window after `slabs` slabs: the big cube moved along the path.
LatticeBox window_after(const Path& path, int slabs) {
  LatticeBox box = lattice_box(path.big_cube);
  box.low[path.axis] += path.sign * slabs;
  box.high[path.axis] += path.sign * slabs;
  return box;
}

CaveParams union_params(const Path& path) {
  CaveParams params = path.big_cube;
  params.size[path.axis] += path.slabs;
  if (path.sign < 0) params.origin[path.axis] -= path.slabs;
  return params;
}

void check_path_fits(const Path& path) {
  const CaveParams whole = union_params(path);
  const std::array<std::int64_t, 3> origin{whole.origin[0], whole.origin[1], whole.origin[2]};
  const std::array<std::int64_t, 3> samples{whole.size[0] + 1, whole.size[1] + 1, whole.size[2] + 1};
  if (!lattice_range_fits(origin, samples, false)) {
    throw InputError("the path leaves the lattice range of the edge keys, ±2^19 per axis");
  }
  require_checkable_block(whole);
}

template <class Real>
TriangleMesh<Real> reference_chunk(const CaveParams& params) {
  return reference::marching_tetrahedra(reference::cave_density<Real>(params), static_cast<Real>(params.threshold),
                                        false, {params.origin[0], params.origin[1], params.origin[2]});
}

template <class Real>
std::vector<TriangleMesh<Real>> reference_path(const Path& path) {
  std::vector<TriangleMesh<Real>> chunks;
  for (int chunk = 0; chunk <= path.slabs; ++chunk) chunks.push_back(reference_chunk<Real>(chunk_params(path, chunk)));
  return chunks;
}

// The GPU path: one mesher for the big cube, one moved from slab to slab. run() leaves the meshes
// on the GPU (the caller brackets it with glFinish); meshes() downloads them.
class GpuPath {
 public:
  explicit GpuPath(const Path& path) : path_(path), big_cube_(path.big_cube), slab_(chunk_params(path, 1)) {}

  std::vector<TriangleMesh<float>> run(bool download) {
    std::vector<TriangleMesh<float>> chunks;
    big_cube_.run();
    if (download) chunks.push_back(big_cube_.result());
    for (int chunk = 1; chunk <= path_.slabs; ++chunk) {
      slab_.move_to(chunk_params(path_, chunk).origin);
      slab_.run();
      if (download) chunks.push_back(slab_.result());
    }
    return chunks;
  }

 private:
  Path path_;
  gpu::MarchingTetrahedra big_cube_;
  gpu::MarchingTetrahedra slab_;
};

// ---- seams ---------------------------------------------------------------------------------

struct SeamFacts {
  std::size_t unmatched_border_edges = 0;
  std::size_t vertex_bit_differences = 0;
  std::size_t seam_edges = 0;
};

using KeyEdge = std::pair<std::uint64_t, std::uint64_t>;

template <class Real>
std::set<KeyEdge> border_edges_on_plane(const TriangleMesh<Real>& mesh, int axis, std::int64_t plane) {
  std::set<KeyEdge> on_plane;
  for (const auto& edge : border_edges(mesh)) {
    const std::uint64_t from = mesh.edge_keys[edge[0]];
    const std::uint64_t to = mesh.edge_keys[edge[1]];
    if (key_on_plane(from, axis, plane) && key_on_plane(to, axis, plane)) on_plane.insert({from, to});
  }
  return on_plane;
}

template <class Real>
SeamFacts seam_facts(const Path& path, const std::vector<TriangleMesh<Real>>& chunks) {
  SeamFacts facts;
  for (int chunk = 0; chunk + 1 < static_cast<int>(chunks.size()); ++chunk) {
    const LatticeBox older = lattice_box(chunk_params(path, chunk));
    const std::int64_t plane = path.sign > 0 ? older.high[path.axis] : older.low[path.axis];
    const auto behind = border_edges_on_plane(chunks[chunk], path.axis, plane);
    const auto ahead = border_edges_on_plane(chunks[chunk + 1], path.axis, plane);
    facts.seam_edges += behind.size();
    for (const auto& [from, to] : behind) facts.unmatched_border_edges += ahead.contains({to, from}) ? 0 : 1;
    for (const auto& [from, to] : ahead) facts.unmatched_border_edges += behind.contains({to, from}) ? 0 : 1;
    facts.vertex_bit_differences += compare_vertices(chunks[chunk], chunks[chunk + 1]).bit_differences;
  }
  return facts;
}

// The chunks as one mesh, vertices shared by edge key (positions of the first chunk that has them).
template <class Real>
TriangleMesh<Real> weld(const std::vector<TriangleMesh<Real>>& chunks) {
  TriangleMesh<Real> welded;
  std::unordered_map<std::uint64_t, std::uint32_t> index_of_key;
  for (const auto& chunk : chunks) {
    std::vector<std::uint32_t> index(chunk.positions.size());
    for (std::size_t vertex = 0; vertex < chunk.positions.size(); ++vertex) {
      const auto [found, inserted] =
          index_of_key.try_emplace(chunk.edge_keys[vertex], static_cast<std::uint32_t>(welded.positions.size()));
      if (inserted) {
        welded.positions.push_back(chunk.positions[vertex]);
        welded.edge_keys.push_back(chunk.edge_keys[vertex]);
      }
      index[vertex] = found->second;
    }
    for (const auto& triangle : chunk.triangles) welded.triangles.push_back({index[triangle[0]], index[triangle[1]], index[triangle[2]]});
  }
  return welded;
}

template <class Real>
void add_seam_checks(const Path& path, const std::vector<TriangleMesh<Real>>& chunks, const std::string& backend,
                     const RunOptions& options, CaseResult& result) {
  const SeamFacts seams = seam_facts(path, chunks);
  result.checks.push_back(bounded_check(
      "seams.unmatched_border_edges." + backend, double(seams.unmatched_border_edges), 0.0, std::nullopt,
      fmt::format("border edges on the {} planes between consecutive chunks without their reverse in the neighbour "
                  "({} seam edges)",
                  path.slabs, seams.seam_edges)));
  result.checks.push_back(bounded_check("seams.vertex_bits." + backend, double(seams.vertex_bit_differences), 0.0,
                                        std::nullopt, "vertices of one edge key placed differently by two chunks"));
  if (options.progress) options.progress->stage("CGAL and OpenMesh (" + backend + " union)");
  const Mesh welded = to_double_mesh(weld(chunks));
  const auto checks = mesh_checks(check_mesh(welded), "union_" + backend, false);
  result.checks.insert(result.checks.end(), checks.begin(), checks.end());
  result.checks.push_back(bounded_check("mesh.border_off_box.union_" + backend,
                                        double(border_edges_off_box(welded, lattice_box(union_params(path)))), 0.0,
                                        std::nullopt, "border edges of the welded path not on a face of its box"));
  write_mesh_artifact(welded, "path." + backend + ".ply",
                      fmt::format("{} path welded, {} triangles", backend, welded.triangles.size()), options, result);
}

void add_monolithic_check(const Path& path, const std::vector<Mesh>& chunks, CaseResult& result) {
  const Mesh welded = weld(chunks);
  const Mesh whole = reference_chunk<double>(union_params(path));
  const std::size_t triangles = triangle_difference(key_triangles(welded), key_triangles(whole));
  const VertexComparison vertices = compare_vertices(welded, whole);
  result.checks.push_back(bounded_check(
      "parity.chunked_vs_monolithic.cpu",
      double(triangles + vertices.bit_differences + vertices.only_in_a + vertices.only_in_b), 0.0, std::nullopt,
      fmt::format("triangles ({}) and vertices ({} moved, {} missing) differing from one block over the path's box",
                  triangles, vertices.bit_differences, vertices.only_in_a + vertices.only_in_b)));
}

// ---- the ring buffer ---------------------------------------------------------------------

struct RingStep {
  std::size_t generated = 0;  // triangles generated so far
  std::size_t held = 0;       // triangles the ring buffer still holds
  std::size_t window_missing = 0;
};

std::array<double, 3> centroid(const Mesh& mesh, const std::array<std::uint32_t, 3>& triangle) {
  std::array<double, 3> sum{};
  for (const std::uint32_t vertex : triangle) {
    for (int axis = 0; axis < 3; ++axis) sum[axis] += mesh.positions[vertex][axis] / 3.0;
  }
  return sum;
}

bool inside(const LatticeBox& box, const std::array<double, 3>& point) {
  for (int axis = 0; axis < 3; ++axis) {
    if (point[axis] < double(box.low[axis]) || point[axis] > double(box.high[axis])) return false;
  }
  return true;
}

// After each chunk: how many triangles the seed's FIFO of soup vertices still holds, and how many
// triangles inside the camera's window it has already overwritten.
std::vector<RingStep> simulate_ring(const Path& path, const std::vector<Mesh>& chunks) {
  std::vector<RingStep> steps;
  std::vector<std::size_t> first_triangle;  // stream index of each chunk's first triangle
  std::size_t generated = 0;
  const std::size_t capacity = path.max_vertices / 3;  // triangles
  for (std::size_t chunk = 0; chunk < chunks.size(); ++chunk) {
    first_triangle.push_back(generated);
    generated += chunks[chunk].triangles.size();
    const std::size_t overwritten = generated > capacity ? generated - capacity : 0;
    const LatticeBox window = window_after(path, static_cast<int>(chunk));
    RingStep step{generated, generated - overwritten, 0};
    for (std::size_t older = 0; older <= chunk && first_triangle[older] < overwritten; ++older) {
      const auto& triangles = chunks[older].triangles;
      for (std::size_t triangle = 0; triangle < triangles.size() && first_triangle[older] + triangle < overwritten; ++triangle) {
        step.window_missing += inside(window, centroid(chunks[older], triangles[triangle])) ? 1 : 0;
      }
    }
    steps.push_back(step);
  }
  return steps;
}

void add_ring_checks(const Path& path, const std::vector<Mesh>& chunks, const RunOptions& options, CaseResult& result) {
  const auto steps = simulate_ring(path, chunks);
  std::size_t worst = 0, worst_step = 0, high_water = 0;
  for (std::size_t step = 0; step < steps.size(); ++step) {
    if (steps[step].window_missing > worst) {
      worst = steps[step].window_missing;
      worst_step = step;
    }
    high_water = std::max(high_water, steps[step].held);
  }
  result.checks.push_back(bounded_check(
      "ring.window_missing_triangles", double(worst), 0.0, std::nullopt,
      worst == 0 ? fmt::format("the ring buffer of {} soup vertices kept every triangle of the camera's window",
                               path.max_vertices)
                 : fmt::format("the ring buffer of {} soup vertices had overwritten {} triangles inside the camera's "
                               "window after slab {}: the seed's FIFO drops by age, not by distance",
                               path.max_vertices, worst, worst_step)));
  result.checks.push_back(informative_check("ring.high_water_bytes", double(high_water * 3 * bytes_per_soup_vertex),
                                            fmt::format("{} triangles held at most, 3 soup vertices of {} bytes each",
                                                        high_water, bytes_per_soup_vertex)));
  result.checks.push_back(informative_check("ring.triangles_held", double(steps.back().held),
                                            fmt::format("at the end of the path; {} generated", steps.back().generated)));
  result.checks.push_back(informative_check("ring.slabs", double(path.slabs), "slabs appended after the big cube"));
  if (options.report_dir.empty()) return;
  SeriesPlot plot{fmt::format("{}: geometry along the path", result.name), "slabs appended", "triangles", false, false, {}};
  Series generated{"generated", {}, {}, true}, held{"held in the ring buffer", {}, {}, false},
      missing{"inside the window but overwritten", {}, {}, false};
  for (std::size_t step = 0; step < steps.size(); ++step) {
    for (Series* series : {&generated, &held, &missing}) series->x.push_back(double(step));
    generated.y.push_back(double(steps[step].generated));
    held.y.push_back(double(steps[step].held));
    missing.y.push_back(double(steps[step].window_missing));
  }
  plot.series = {generated, held, missing};
  attach_plot({plot}, options, "ring.png",
              "triangles generated, held by the ring buffer and missing from the window", result);
}

// ---- GPU -----------------------------------------------------------------------------------

void add_gpu_checks(const Path& path, const std::vector<TriangleMesh<float>>& singles, const RunOptions& options,
                    CaseResult& result) {
  if (options.progress) options.progress->stage("GPU");
  GpuPath gpu_path(path);
  const auto chunks = gpu_path.run(true);
  time_gpu(options.gpu_reps, [&] { gpu_path.run(false); }, result.timings);
  std::size_t differing_chunks = 0;
  double largest_distance = 0.0;
  for (std::size_t chunk = 0; chunk < chunks.size(); ++chunk) {
    const bool same = chunks[chunk].triangles == singles[chunk].triangles && chunks[chunk].edge_keys == singles[chunk].edge_keys;
    differing_chunks += same ? 0 : 1;
    largest_distance = std::max(largest_distance, compare_vertices(chunks[chunk], singles[chunk]).max_distance);
  }
  result.checks.push_back(bounded_check("parity.topology.gpu_vs_float", double(differing_chunks), 0.0, std::nullopt,
                                        "chunks whose index buffer or edge keys differ from ref<float>'s"));
  const LatticeBox box = lattice_box(union_params(path));
  double magnitude = 0.0;
  for (int axis = 0; axis < 3; ++axis) magnitude = std::max({magnitude, std::abs(double(box.low[axis])), std::abs(double(box.high[axis]))});
  result.checks.push_back(bounded_check(
      "parity.max_abs.gpu_vs_float", largest_distance, gpu_vertex_bound(magnitude),
      std::nullopt, "largest vertex distance over all chunks; GLSL's division within 2.5 ulp (see cave.marching_tetrahedra)"));
  add_seam_checks(path, chunks, "gpu", options, result);
}

void run_path(const Path& path, const RunOptions& options, CaseResult& result) {
  result.input = fmt::format("seed 004 density: a {}x{}x{} big cube at ({}, {}, {}) and {} slabs along {}{}",
                             path.big_cube.size[0], path.big_cube.size[1], path.big_cube.size[2],
                             path.big_cube.origin[0], path.big_cube.origin[1], path.big_cube.origin[2], path.slabs,
                             path.sign > 0 ? '+' : '-', char('x' + path.axis));
  if (options.progress) options.progress->stage("CPU reference (double)");
  std::vector<Mesh> chunks;
  time_cpu(std::max(options.cpu_reps, 1), [&] { chunks = reference_path<double>(path); }, result.timings);
  add_seam_checks(path, chunks, "cpu", options, result);
  add_monolithic_check(path, chunks, result);
  // Fields as data (compare/field_files.hpp): the density over the path's whole box, sampled as
  // one block; the chunks read it piece by piece.
  write_volume_field_file(reference::cave_density<double>(union_params(path)),
                          {"density_cpu", "density", "cpu", "1",
                           "seed 004 density over the path's box (big cube and slabs), ref<double>; rock below the "
                           "threshold"},
                          options, result);
  add_ring_checks(path, chunks, options, result);
  if (!options.gpu_available) {
    skip_as_other_backend(result, "mesh.", ".union_cpu", ".union_gpu", options.gpu_unavailable_reason);
    skip_as_other_backend(result, "seams.", ".cpu", ".gpu", options.gpu_unavailable_reason);
    for (const char* name : {"parity.topology.gpu_vs_float", "parity.max_abs.gpu_vs_float"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
    return;
  }
  add_gpu_checks(path, reference_path<float>(path), options, result);
}

PreparedTwin prepare_path(const nlohmann::json& resolved, const LoadedInput& input) {
  if (input.heights.size() != 0 || input.mesh) {
    throw InputError("the cave makes its own density from its parameters: give the case no input");
  }
  Path path = path_from_json(resolved);
  check_path_fits(path);
  PreparedTwin prepared;
  prepared.kind = CaseRun([path](const nlohmann::json&, const RunOptions& options, CaseResult& result) {
    run_path(path, options, result);
  });
  return prepared;
}

// Measured 1530 B a sample of the big cube (61³ vs 31³) and 1240 B a sample of a slab (200 vs 20
// slabs of 31²), both backends; the ring buffer is simulated by counts and costs nothing. Slabs
// are sized by the block's largest face, whichever the direction.
MemoryEstimate path_memory(const nlohmann::json& resolved, const LoadedInput&) {
  const auto given = params_from_json(cave_endless_param_table(), resolved);
  const double x = given.big_cube.size[0] + 1.0;
  const double y = given.big_cube.size[1] + 1.0;
  const double z = given.big_cube.size[2] + 1.0;
  const double slab_samples = given.slabs * std::max({x * y, y * z, x * z});
  return memory_for(x * y * z, "samples of the big cube", 2000) + memory_for(slab_samples, "slab samples", 1500);
}

}  // namespace

const ParamTable<CaveEndlessParams>& cave_endless_param_table() {
  using C = CaveEndlessParams;
  static const ParamTable<C> table = [] {
    ParamTable<C> rows = nested(&C::big_cube, cave_param_table());
    rows.push_back(integer_param("slabs", &C::slabs, 1, 2000, "count",
                                 "slabs appended along the path, one per lattice unit of flight"));
    rows.push_back(choice_param("direction", &C::direction, {"+x", "-x", "+y", "-y", "+z", "-z"}, "",
                                "the camera's straight flight: the face slabs are added on"));
    rows.push_back(integer_param("max_vertices", &C::max_vertices, 3, 1e9, "soup vertex",
                                 "ring-buffer capacity (the seed's MAX_VERTICES; rounded down to a multiple of 3)"));
    return rows;
  }();
  return table;
}

Algorithm cave_endless_algorithm() {
  return {.name = "cave.endless",
          .summary = "seed 004's endless cave: a big cube, then slabs along a camera path, seams and ring buffer checked",
          .source = "seed 004 digest §2.7",
          .params = &endless_specs(),
          .prepare = prepare_path,
          .kind = CaseKind::custom,
          .ad_hoc_input = AdHocInput::none,
          .memory = path_memory};
}

}  // namespace gt
