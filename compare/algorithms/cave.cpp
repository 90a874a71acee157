// The driver's view of seed 004's cave block (digest §2.2–2.8, issue 5): one block of the seed's
// density meshed by marching tetrahedra (CPU in double and float, GPU) or by the seed's marching
// cubes (CPU only, the variant that fails), with the watertightness, parity, volume and normal
// checks; and the performance rows of the mesher (voxels and triangles per second).
//
// Checks of a block case (backend cpu = ref<double>, the truth; gpu = the GPU twin):
//   mesh.*.{cpu,gpu}                 compare/checks/mesh.hpp (closed only for a solid block)
//   mesh.border_off_box.{cpu,gpu}    open chunk: border edges not on the block's faces (must be 0)
//   mesh.holes.cpu                   boundary loops of a solid block (marching cubes' holes)
//   spec.triangles.cpu               the case's expected triangle count (of ref<double>: the float
//                                    twins may differ where samples change side, see below)
//   volume.mesh_vs_field.cpu         solid: |CGAL volume - rock samples| against the cut-cube
//                                    bound of compare/checks/cave_mesh.hpp
//   volume.mesh_vs_pl.cpu            solid, tetrahedra: |volume the mesh encloses - the field's
//                                    piecewise-linear rock under the mesher's placement rule|, per
//                                    Kuhn tetrahedron from the samples (cave_mesh.hpp), against the
//                                    rounding of both (fixed before the mesh is read)
//   spec.vertex_crossing.cpu         ref<double>'s vertices against the field (cave_mesh.hpp): on an
//                                    edge whose endpoints differ in rock, within δ + 8u·(m + 2) of the
//                                    linear interpolant's crossing (the midpoint at the pad or with
//                                    midpoint placement); the count of vertices that are not (must be 0)
//   normals.angle_*.cpu              seed's central differences vs the analytic gradient (degrees)
//   parity.normals.gpu_vs_float      the GPU's central differences (gpu/cave/normals.hpp) vs
//                                    ref<float>'s at the GPU mesh's vertices: largest angle / its
//                                    per-vertex bound (<= 1), fixed from ref<float>'s differences
//                                    and the noise module's GPU-vs-float model (add_gpu_normals_check)
//   parity.density.float_vs_double   max |density_float − density| against ε, the a-priori bound
//                                    of the float density (density_precision: the noise module's
//                                    float model, or one rounding of a volume's values), fixed
//                                    before the float density is read; the two checks below use ε
//   parity.topology.{float,gpu}_vs_double   triangles (by edge keys) in one mesh only that no
//                                    possible side change explains (must be 0): a sample that is
//                                    rock in one precision and air in the other changes the cases
//                                    of the cubes it is a corner of and nothing else, and only a
//                                    sample within ε of the threshold can, so every differing
//                                    triangle must lie in a cube with such a sample
//   parity.vertex_model.{float,gpu}_vs_double   largest vertex distance / per-vertex bound (<= 1)
//                                    against ref<double>'s mesher run on the float density's samples
//                                    and threshold (exact in double): no density error enters, only the float
//                                    roundings of t (4u, GLSL's division included) and of the
//                                    position (u·(|a| + 1)); √3 for the three axes
//   parity.hausdorff.{float,gpu}_vs_double   symmetric Hausdorff distance (informative;
//                                    compare/checks/keyed_hausdorff.hpp): the corner distances
//                                    bound triangles both meshes have, CGAL samples the others
//                                    against the triangles near them
//   parity.topology.gpu_vs_float, parity.max_abs.gpu_vs_float   the same float operations: equal
//                                    index buffers and keys; positions within GLSL's division
//                                    error (3u of t plus one rounding of the position), 0 on llvmpipe
//   determinism.gpu                  vertices or triangles differing between two GPU runs
// Meshes are written beside the report as mesh.cpu.<format> and mesh.gpu.<format>, and ref<double>'s
// (and a candidate's) drawn as mesh.cpu.png by the reference Phong rasterizer.
//
// A user's mesh (`run --candidate FILE`, compare/external/candidate.hpp) stands where the GPU's
// does and is held to ref<double> (run_candidate_half): its vertices keyed by the Kuhn edges they
// lie on (cave_mesh.hpp key_by_lattice_edges; mesh.on_lattice_edges.candidate), its mesh.* checks,
// spec.vertex_crossing.candidate with the float density's a-priori error ε, parity.crossing_edges
// (edges with no endpoint within ε of the threshold must carry a vertex in both meshes or in
// neither), parity.hausdorff with the bound keyed_hausdorff_bound derives from the truth before
// the file is read; its triangles' keys are shown, not graded (a quad may be split either way).
//
// The density is the seed's noise, or a volume read from a file ({"volume": "f.npy"}, `--input
// f.npy`): then the block's size is the volume's, origin_* places its first sample on the lattice,
// threshold and solid apply, the noise parameters do not, ref<float> and the GPU mesh the samples
// rounded to float, and there are no normal checks (they compare two ways of differentiating the
// noise).
#include "compare/algorithms/cave.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <future>
#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/algorithm.hpp"
#include "compare/checks/cave_mesh.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/keyed_hausdorff.hpp"
#include "compare/checks/mesh.hpp"
#include "compare/checks/noise_error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/peers/vtk_isosurface.hpp"
#include "compare/report/images.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/params/cave.hpp"
#include "core/params/noise.hpp"
#include "gpu/cave/marching_tetrahedra.hpp"
#include "gpu/cave/normals.hpp"
#include "gpu/timing.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_cubes.hpp"
#include "reference/cave/marching_tetrahedra.hpp"
#include "reference/cave/normals.hpp"
#include "reference/render/phong.hpp"

namespace gt {
namespace {

using reference::EdgePlacement;

enum class Mesher { tetrahedra, cubes };

struct Block {
  CaveParams params;  // with a volume: origin and solid apply, size is the volume's, the noise fields do not
  std::shared_ptr<const Volume<double>> volume;  // a density read from a file; null: the seed's noise
  Mesher mesher = Mesher::tetrahedra;
  EdgePlacement placement;  // the case's (CaveMeshParams)
  std::string mesh_format;
};

constexpr Choice<EdgePlacement> placement_choices[] = {{"linear", EdgePlacement::linear},
                                                       {"midpoint", EdgePlacement::midpoint}};

const ParamSpecs& block_specs(Mesher mesher) {
  static const ParamSpecs tetrahedra = param_specs(cave_mesh_param_table());
  static const ParamSpecs cubes = param_specs(cave_mesh_param_table(), cave_mesh_defaults_for_cubes());
  return mesher == Mesher::tetrahedra ? tetrahedra : cubes;
}

std::array<std::int64_t, 3> lattice_origin(const CaveParams& params) {
  return {params.origin[0], params.origin[1], params.origin[2]};
}

template <class Real>
TriangleMesh<Real> mesh_block(const Block& block, const Volume<Real>& density) {
  const auto threshold = static_cast<Real>(block.params.threshold);
  const auto origin = lattice_origin(block.params);
  return block.mesher == Mesher::tetrahedra
             ? reference::marching_tetrahedra(density, threshold, block.params.solid, origin, block.placement)
             : reference::marching_cubes(density, threshold, block.params.solid, origin, block.placement);
}

double max_abs_difference(const Volume<float>& single, const Volume<double>& truth) {
  double largest = 0.0;
  for (std::size_t sample = 0; sample < truth.values.size(); ++sample) {
    largest = std::max(largest, std::abs(double(single.values[sample]) - truth.values[sample]));
  }
  return largest;
}

// The a-priori bound ε of |density_float − density| at every sample, fixed before the float density
// is read: for the seed's noise, the noise module's float model (compare/checks/
// noise_error_model.hpp: simplex3 with the block's kernel, coordinates up to the block's largest
// |lattice coordinate| / scale, each formed as float(c)·float(1/scale), two roundings); for a volume
// read from a file, one rounding to float of its largest |value|.
double density_precision(const Block& block, const Volume<double>& density) {
  if (block.volume) {
    double largest = 0.0;
    for (const double value : density.values) largest = std::max(largest, std::abs(value));
    return unit_roundoff_float * largest;
  }
  NoiseParams noise = noise_defaults(NoiseBasis::simplex3, Fractal::none);
  noise.kernel_radius_squared = block.params.kernel_radius_squared;
  double extent = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double first = block.params.origin[axis], last = first + block.params.size[axis];
    extent = std::max({extent, std::abs(first), std::abs(last)});
  }
  return noise_precision_bound(noise, extent / block.params.scale);
}

// Global lattice points of the samples whose a-priori interval [density − ε, density + ε] holds
// the threshold (or its float rounding): the only ones that may be rock in one precision and air
// in the other.
std::vector<std::array<std::int64_t, 3>> possible_side_changes(const Volume<double>& truth, double density_error,
                                                               const CaveParams& params) {
  std::vector<std::array<std::int64_t, 3>> changes;
  const double reach = density_error + unit_roundoff_float * std::abs(params.threshold);
  for (int z = 0; z < truth.nz; ++z) {
    for (int y = 0; y < truth.ny; ++y) {
      for (int x = 0; x < truth.nx; ++x) {
        if (std::abs(truth.at(x, y, z) - params.threshold) <= reach) {
          changes.push_back({std::int64_t{params.origin[0]} + x, std::int64_t{params.origin[1]} + y,
                             std::int64_t{params.origin[2]} + z});
        }
      }
    }
  }
  return changes;
}

// The per-vertex bound of parity.vertex_model (see the file comment): the float mesher's rounding
// of t and of the position, for a vertex on the lattice edge `key`.
double vertex_rounding_bound(std::uint64_t key) {
  const LatticeEdge edge = lattice_edge_from_key(key);
  double magnitude = 0.0;
  for (int axis = 0; axis < 3; ++axis) magnitude = std::max(magnitude, std::abs(double(edge.lower_point[axis])) + 1.0);
  return std::sqrt(3.0) * unit_roundoff_float * (4.0 + magnitude);
}

struct BlockMeshes {
  Volume<double> density;
  Mesh truth;                  // ref<double>
  Mesh float_density_meshed;   // ref<double>'s mesher on ref<float>'s samples and threshold (exact
                               // in double): the float meshers' rounding-only truth
  Volume<float> density_float;
  TriangleMesh<float> single;  // ref<float>, what the GPU must reproduce
  std::vector<std::array<std::int64_t, 3>> possible_side_changes;  // samples within ε of the threshold
  double density_error = 0.0;  // ε: the a-priori bound of |density_float - density| (density_precision)
};

void add_expected_triangles(const nlohmann::json& expect, std::size_t triangles, const std::string& backend,
                            CaseResult& result) {
  if (!expect.is_object() || !expect.contains("triangles")) return;
  const double expected = expect["triangles"];
  result.checks.push_back(bounded_check("spec.triangles." + backend, std::abs(double(triangles) - expected), 0.0,
                                        std::nullopt, fmt::format("{} triangles, {} expected", triangles, expected)));
}

// The checks every mesh of a block gets, on either backend, from its CGAL and OpenMesh report.
std::vector<Check> block_mesh_checks(const Block& block, const Mesh& mesh, const MeshReport& report,
                                     const std::string& backend) {
  std::vector<Check> checks = mesh_checks(report, backend, block.params.solid);
  if (block.params.solid) {
    checks.push_back(informative_check("mesh.holes." + backend, double(report.openmesh.boundary_loops),
                                       "boundary loops of a block that should be closed (OpenMesh)"));
  } else {
    checks.push_back(bounded_check("mesh.border_off_box." + backend,
                                   double(border_edges_off_box(mesh, lattice_box(block.params))), 0.0, std::nullopt,
                                   "border edges not lying on a face of the block's box"));
  }
  return checks;
}

// A picture of a mesh for the reader, who cannot open a mesh file in a browser: the reference
// rasterizer's plain Phong look from render.phong's default orbit (azimuth 30°, elevation 20°,
// field of view 40°, 0.6 of the default light so that near faces keep their shading), 320 × 320
// pixels, beside the mesh file. None for a mesh the rasterizer cannot take (an index out of range,
// a non-finite corner: mesh.invalid says so), or in a run without pictures.
void write_mesh_picture(const Mesh& mesh, const std::string& backend, const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty() || !options.pictures || mesh.triangles.empty()) return;
  const bool drawable = std::ranges::all_of(mesh.triangles, [&](const auto& triangle) {
    return std::ranges::all_of(triangle, [&](std::uint32_t vertex) {
      return vertex < mesh.positions.size() && std::ranges::all_of(mesh.positions[vertex], [](double c) { return std::isfinite(c); });
    });
  });
  if (!drawable) return;
  constexpr int side = 320;
  const reference::Camera camera = reference::orbit_camera(mesh, 30.0, 20.0, 40.0, side, side);
  reference::PhongScene scene = reference::phong_scene(mesh, camera);
  scene.light_power *= 0.6;  // the faces nearest the eye would clamp to white at the default power
  const reference::Rgb8Image image = reference::render_phong(scene);
  std::vector<std::array<float, 3>> colours;
  colours.reserve(static_cast<std::size_t>(side) * side);
  for (std::size_t pixel = 0; pixel + 2 < image.rgb.size(); pixel += 3) {
    colours.push_back({image.rgb[pixel] / 255.0f, image.rgb[pixel + 1] / 255.0f, image.rgb[pixel + 2] / 255.0f});
  }
  const std::string file = "mesh." + backend + ".png";
  std::filesystem::create_directories(options.report_dir / result.name);
  write_colour_image(side, side, colours, options.report_dir / result.name / file);
  add_picture(result, file,
              fmt::format("{} mesh, {} triangles: the reference rasterizer's Phong view from azimuth 30°, elevation "
                          "20° (y up)",
                          backend, mesh.triangles.size()));
}

std::optional<Check> volume_check(const Block& block, const BlockMeshes& meshes, const MeshReport& report) {
  if (!block.params.solid) return std::nullopt;
  if (!report.cgal.volume) {
    return not_applicable_check("volume.mesh_vs_field.cpu", "CGAL gives no volume for an open mesh");
  }
  const FieldVolume field = volume_bound_from_field(meshes.density, block.params.threshold);
  return bounded_check(
      "volume.mesh_vs_field.cpu", std::abs(*report.cgal.volume - field.rock_samples), field.bound, std::nullopt,
      fmt::format("mesh volume {:.6g} vs {} rock samples (lattice units³); bound: Σ max(k, 8 - k)/8 over the {} cubes "
                  "the surface cuts (k rock corners)",
                  *report.cgal.volume, field.rock_samples, field.cut_cubes));
}

// The volume ref<double>'s mesh encloses against the piecewise-linear volume the field and the
// mesher's placement rule give (cave_mesh.hpp piecewise_linear_volume), both from the field alone.
// Bound, fixed before the mesh is read, for N cut tetrahedra: each vertex within ε = 8u·(m + 2) of
// its crossing moves the volume by at most ε times the area around it, each triangle's area at
// most 1 (a plane section of a Kuhn tetrahedron) and at most 2N triangles, counted at 3 corners:
// 6N·ε; the mesh's determinants on coordinates up to e (the block's extent) 4u·e³ a triangle,
// 2N triangles; the field's polytopes 32u a tetrahedron.
Check piecewise_linear_volume_check(const Block& block, const BlockMeshes& meshes) {
  const auto origin = lattice_origin(block.params);
  const PiecewiseLinearVolume field = piecewise_linear_volume(meshes.density, block.params.threshold, origin,
                                                              block.placement == EdgePlacement::linear);
  double magnitude = 0.0, extent = 0.0;
  const std::array<int, 3> sizes{meshes.density.nx, meshes.density.ny, meshes.density.nz};
  for (int axis = 0; axis < 3; ++axis) {
    magnitude = std::max({magnitude, std::abs(double(origin[axis]) - 1.0), std::abs(double(origin[axis]) + sizes[axis])});
    extent = std::max(extent, double(sizes[axis]) + 1.0);
  }
  constexpr double u = 0x1p-53;
  const double cut = double(field.cut_tetrahedra);
  const double bound = 6.0 * cut * vertex_crossing_bound(0.0, magnitude, u) + 2.0 * cut * 4.0 * u * extent * extent * extent +
                       32.0 * u * cut;
  const double enclosed = enclosed_volume(meshes.truth, origin);
  return bounded_check(
      "volume.mesh_vs_pl.cpu", std::abs(enclosed - field.volume), bound, std::nullopt,
      fmt::format("ref<double>'s mesh encloses {:.12g} lattice units³ where the field's piecewise-linear rock under the "
                  "mesher's placement rule holds {:.12g} ({} cut Kuhn tetrahedra, computed from the samples); bound: the "
                  "vertices' rounding 6N·8u(m + 2), the mesh's determinants 8N·u·e³, the polytopes 32N·u",
                  enclosed, field.volume, field.cut_tetrahedra));
}

void add_crossing_check(const Block& block, const BlockMeshes& meshes, CaseResult& result) {
  const VertexCrossings crossings =
      vertex_crossings(meshes.truth, meshes.density, block.params.threshold, lattice_origin(block.params),
                       block.placement == EdgePlacement::linear);
  result.checks.push_back(bounded_check(
      "spec.vertex_crossing.cpu", double(crossings.not_crossing + crossings.off_crossing), 0.0, std::nullopt,
      fmt::format("vertices of {} on an edge the surface does not cross ({}) or off the crossing by more than "
                  "δ + 8u·(m + 2) ({}); largest distance {:.3g} lattice units, {:.3g} of its bound",
                  crossings.vertices, crossings.not_crossing, crossings.off_crossing, crossings.max_distance,
                  crossings.max_bound_ratio)));
}

void add_normal_checks(const Block& block, const Mesh& mesh, CaseResult& result) {
  if (mesh.positions.empty()) return;
  auto angles = reference::normal_angles(reference::central_difference_normals(mesh, block.params),
                                         reference::gradient_normals(mesh, block.params));
  for (double& angle : angles) angle *= 180.0 / M_PI;
  const double largest = *std::max_element(angles.begin(), angles.end());
  const std::string model = fmt::format(
      "central differences (step 1, the seed's) vs the analytic gradient, degrees; error h²/6·f''' for h = {:g} noise "
      "units{}",
      1.0 / block.params.scale,
      block.params.kernel_radius_squared > 0.5 ? ", plus the jumps of kernel 0.6 across simplex faces" : "");
  result.checks.push_back(informative_check("normals.angle_median.cpu", median(angles), model));
  result.checks.push_back(informative_check("normals.angle_max.cpu", largest, model));
}

// The GPU's central-difference normals (gpu/cave/normals.hpp) against ref<float>'s at the GPU mesh's
// vertices, angle by angle against a bound per vertex fixed from ref<float>'s differences before
// the GPU's are read. Both evaluate the density at the same float points (p ± step and the product
// by float(1/scale) are correctly rounded on both sides), so each of the six samples differs by at
// most a, the noise module's GPU-vs-float bound (noise_arithmetic_bound: the same float operations
// in the same order), and each difference d_c by 2a plus the rounding of the subtraction on both
// sides (u·|d_c| each): the unnormalised vectors differ by δ <= 2√3·a + 2u·|d|, so their directions
// by at most asin(δ/|d|) with d ref<float>'s; the normalisation adds at most 6u (GLSL's division
// within 2.5 ulp and the reference's 0.5, on three components), a common scale (the square root)
// none. A vertex with |d| <= δ (a flat spot of the density) is not graded.
void add_gpu_normals_check(const Block& block, const TriangleMesh<float>& gpu_mesh, CaseResult& result) {
  const CaveParams& params = block.params;
  constexpr double step = 1.0;  // the seed's ND
  NoiseParams noise = noise_defaults(NoiseBasis::simplex3, Fractal::none);
  noise.kernel_radius_squared = params.kernel_radius_squared;
  const double per_sample = noise_arithmetic_bound(noise);
  const double u = unit_roundoff_float;
  const auto differences = reference::central_differences<float>(gpu_mesh, params, step);
  std::vector<double> bounds;
  bounds.reserve(differences.size());
  for (const auto& difference : differences) {
    double squared = 0.0;
    for (const float component : difference) squared += double(component) * double(component);
    const double length = std::sqrt(squared);
    const double gap = 2.0 * std::sqrt(3.0) * per_sample + 2.0 * u * length;
    bounds.push_back(length > gap ? std::asin(gap / length) + 6.0 * u : std::numeric_limits<double>::infinity());
  }
  const auto gpu_normals = gpu::central_difference_normals(gpu_mesh.positions, params, step);
  const auto float_normals = reference::unit_normals(differences);
  const std::vector<double> angles = reference::normal_angles(gpu_normals, float_normals);
  double worst_ratio = 0.0, largest_angle = 0.0;
  std::size_t ungraded = 0, differing = 0;
  for (std::size_t v = 0; v < angles.size(); ++v) {
    if (gpu_normals[v] != float_normals[v]) ++differing;
    largest_angle = std::max(largest_angle, angles[v]);
    if (std::isinf(bounds[v])) {
      ++ungraded;
      continue;
    }
    worst_ratio = std::max(worst_ratio, angles[v] / bounds[v]);
  }
  result.checks.push_back(bounded_check(
      "parity.normals.gpu_vs_float", worst_ratio, 1.0, std::nullopt,
      fmt::format("largest angle / its bound between the GPU's central-difference normals (step {:g}, the seed's ND) "
                  "and ref<float>'s at the GPU mesh's {} vertices; bound per vertex asin(δ/|d|) + 6u from ref<float>'s "
                  "differences d, δ = 2√3·a + 2u·|d|, a = {:.3g} per sample (the noise module's GPU-vs-float model); {} "
                  "vertices differ in any bit, the largest angle is {:.3g}°, {} vertices on a flat spot of the density "
                  "are not graded",
                  step, angles.size(), per_sample, differing, largest_angle * 180.0 / M_PI, ungraded)));
}

// Mesh `single` (float arithmetic: ref<float> or the GPU) against ref<double>.
void add_vs_double(const BlockMeshes& meshes, const TriangleMesh<float>& single,
                   const std::string& name, CaseResult& result) {
  const auto& changes = meshes.possible_side_changes;
  const auto differing = triangles_in_one_only(key_triangles(single), key_triangles(meshes.truth));
  const auto unexplained = std::count_if(differing.begin(), differing.end(), [&](const KeyTriangle& triangle) {
    const LatticeBox cube = triangle_cube(triangle);
    return std::none_of(changes.begin(), changes.end(), [&](const auto& point) { return cube.contains(point); });
  });
  result.checks.push_back(bounded_check(
      "parity.topology." + name, double(unexplained), 0.0, std::nullopt,
      fmt::format("triangles (by edge keys) in one mesh only whose cube has none of the samples within ε of the "
                  "threshold (ε a priori: parity.density.float_vs_double), the only ones that may change side; {} "
                  "triangles differ, {} samples within ε (the seed's lattice has many samples at the threshold up to "
                  "rounding)",
                  differing.size(), changes.size())));
  // Against the float samples meshed in double: the vertices differ by the float mesher's rounding
  // alone (ε = 0), none of the density's error enters.
  const VertexComparison vertices =
      compare_vertices(single, meshes.float_density_meshed, vertex_rounding_bound);
  result.checks.push_back(bounded_check(
      "parity.vertex_model." + name, vertices.max_bound_ratio, 1.0, std::nullopt,
      fmt::format("largest vertex distance / its bound over {} shared vertices, against ref<double>'s mesher on the "
                  "float density samples: the float mesher's rounding alone, √3·u·(4 + |a|) (t's roundings, GLSL's "
                  "division included, and the position's)",
                  vertices.matched)));
  const KeyedHausdorff hausdorff = keyed_hausdorff(to_double_mesh(single), meshes.truth);
  result.checks.push_back(informative_check(
      "parity.hausdorff." + name, hausdorff.distance,
      fmt::format("symmetric Hausdorff distance (lattice units): triangles of the same keys whose corners moved less "
                  "than 0.1 lie within {:.3g} of their twins; the other {} triangles are sampled by CGAL every {:.3g} "
                  "lattice units against the other mesh's triangles {}: {:.3g}",
                  hausdorff.shared_bound, hausdorff.sampled_triangles, hausdorff.grid_spacing,
                  hausdorff.whole_mesh_fallback ? "(all of them on a side)" : "within 2 lattice units",
                  hausdorff.sampled_distance)));
}

BlockMeshes run_reference(const Block& block, const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("CPU reference (double)");
  BlockMeshes meshes;
  time_cpu(std::max(options.cpu_reps, 1), [&] {
    meshes.density = block.volume ? *block.volume : reference::cave_density<double>(block.params);
    meshes.truth = mesh_block(block, meshes.density);
  }, result.timings);
  meshes.density_error = density_precision(block, meshes.density);
  meshes.possible_side_changes = possible_side_changes(meshes.density, meshes.density_error, block.params);
  meshes.density_float = block.volume ? block.volume->cast<float>() : reference::cave_density<float>(block.params);
  meshes.single = mesh_block(block, meshes.density_float);
  Block float_inputs = block;  // the float meshers' inputs, exact in double: their samples and threshold
  float_inputs.params.threshold = static_cast<float>(block.params.threshold);
  meshes.float_density_meshed = mesh_block(float_inputs, meshes.density_float.cast<double>());
  const double measured = max_abs_difference(meshes.density_float, meshes.density);
  result.checks.push_back(bounded_check(
      "parity.density.float_vs_double", measured, meshes.density_error, std::nullopt,
      fmt::format("max |density_float − density| over the block's samples against ε, fixed before the float density "
                  "is read: {}; the topology and vertex models below rest on it",
                  block.volume ? "one rounding to float of the largest |value|"
                               : "the noise module's float model (simplex3, coordinates up to the block's largest "
                                 "lattice coordinate / scale)")));
  return meshes;
}

gpu::EdgePlacement gpu_placement(EdgePlacement placement) {
  return placement == EdgePlacement::linear ? gpu::EdgePlacement::linear : gpu::EdgePlacement::midpoint;
}

gpu::MarchingTetrahedra gpu_mesher(const Block& block, const Volume<float>& density_float) {
  if (!block.volume) return gpu::MarchingTetrahedra(block.params, gpu_placement(block.placement));
  return gpu::MarchingTetrahedra(density_float, static_cast<float>(block.params.threshold), block.params.solid,
                                 block.params.origin, gpu_placement(block.placement));
}

TriangleMesh<float> run_gpu(const Block& block, const Volume<float>& density_float, const RunOptions& options,
                            CaseResult& result) {
  if (options.progress) options.progress->stage("GPU");
  gpu::MarchingTetrahedra mesher = gpu_mesher(block, density_float);
  mesher.run();
  const TriangleMesh<float> first = mesher.result();
  time_gpu(options.gpu_reps, [&] { mesher.run(); }, result.timings);
  mesher.run();
  const TriangleMesh<float> second = mesher.result();
  const VertexComparison repeat = compare_vertices(first, second);
  const std::size_t changed = repeat.bit_differences + repeat.only_in_a + repeat.only_in_b +
                              (first.triangles == second.triangles ? 0 : 1);
  result.checks.push_back(bounded_check("determinism.gpu", double(changed), 0.0, std::nullopt,
                                        "vertices (and the index buffer) differing between two GPU runs"));
  return first;
}

void add_gpu_vs_float(const TriangleMesh<float>& gpu_mesh, const TriangleMesh<float>& single, CaseResult& result) {
  const bool same_buffers = gpu_mesh.triangles == single.triangles && gpu_mesh.edge_keys == single.edge_keys;
  const std::size_t differing = same_buffers ? 0 : std::max<std::size_t>(1, triangle_difference(key_triangles(gpu_mesh), key_triangles(single)));
  result.checks.push_back(bounded_check("parity.topology.gpu_vs_float", double(differing), 0.0, std::nullopt,
                                        "triangles differing from ref<float> (index buffer, edge keys, order)"));
  const VertexComparison vertices = compare_vertices(gpu_mesh, single);
  double magnitude = 0.0;
  for (const auto& position : single.positions) {
    for (float coordinate : position) magnitude = std::max(magnitude, std::abs(double(coordinate)));
  }
  result.checks.push_back(bounded_check(
      "parity.max_abs.gpu_vs_float", vertices.max_distance, gpu_vertex_bound(magnitude), std::nullopt,
      fmt::format("largest vertex distance; same float operations, GLSL's division within 2.5 ulp: 3u of t plus one "
                  "rounding of positions up to {:g}; {} of {} vertices differ in any bit",
                  magnitude, vertices.bit_differences, vertices.matched)));
}

// Fields as data (compare/field_files.hpp): the density the meshers read, as .npy volumes that an
// ad-hoc run takes back as --input. A volume input is written once ("input"); the seed's noise as
// ref<double> samples it ("cpu") and as ref<float> and the GPU mesher read it ("cpu_float").
void write_density_fields(const Block& block, const BlockMeshes& meshes, const RunOptions& options,
                          CaseResult& result) {
  const std::string unit = "1";
  if (block.volume) {
    write_volume_field_file(meshes.density, {"density_input", "density", "input", unit, "the density volume read"},
                            options, result);
    return;
  }
  write_volume_field_file(meshes.density,
                          {"density_cpu", "density", "cpu", unit, "seed 004 density, rock below the threshold, ref<double>"},
                          options, result);
  write_volume_field_file(meshes.density_float.cast<double>(),
                          {"density_cpu_float", "density", "cpu_float", unit,
                           "seed 004 density in float, what ref<float> and the GPU mesher read"},
                          options, result);
}

bool same_mesh(const TriangleMesh<float>& a, const TriangleMesh<float>& b) {
  return a.triangles == b.triangles && a.edge_keys == b.edge_keys && a.positions == b.positions;
}

// A GPU mesh equal to ref<float>'s (index buffer, keys and positions) compares with ref<double> as
// ref<float>'s does: those checks are repeated under the GPU's names instead of measured again.
void repeat_float_vs_double_as_gpu(CaseResult& result) {
  const std::string float_suffix = ".float_vs_double";
  std::vector<Check> repeated;
  for (const Check& check : result.checks) {
    if (!check.name.starts_with("parity.") || !check.name.ends_with(float_suffix)) continue;
    if (check.name.starts_with("parity.density.")) continue;  // the GPU meshes ref<float>'s density
    Check gpu_check = check;
    gpu_check.name = check.name.substr(0, check.name.size() - float_suffix.size()) + ".gpu_vs_double";
    gpu_check.detail = "the GPU mesh is ref<float>'s, bit for bit: " + check.detail;
    repeated.push_back(std::move(gpu_check));
  }
  result.checks.insert(result.checks.end(), repeated.begin(), repeated.end());
}

// A user's mesh of the block (run --candidate) where the GPU's stands. It samples the density
// itself, in float or double, so it is held to ref<double> with the a-priori density error ε
// (parity.density.float_vs_double's), and it may split a tetrahedron's quad either way: its
// lattice edges are graded, its triangles' keys shown.
void run_candidate_half(const Block& block, const BlockMeshes& meshes, const CandidateMesh& candidate,
                        const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("candidate mesh");
  Mesh mesh = candidate.mesh;
  result.notes.push_back(fmt::format("graded: {} ({} vertices, {} triangles), standing where the GPU twin stands{}",
                                     candidate.file.string(), mesh.positions.size(), mesh.triangles.size(),
                                     candidate.notes.empty() ? "" : fmt::format(" ({})", fmt::join(candidate.notes, "; "))));
  const std::size_t unkeyed = key_by_lattice_edges(mesh);
  result.checks.push_back(bounded_check(
      "mesh.on_lattice_edges.candidate", double(unkeyed), 0.0, std::nullopt,
      fmt::format("vertices of {} on no edge of the Kuhn decomposition (axis edges, face diagonals a → a + (1,1,0) "
                  "and its kin, the body diagonal a → a + (1,1,1)) within a quarter of the edge margin, or on a lattice "
                  "point",
                  mesh.positions.size())));
  const auto checks = block_mesh_checks(block, mesh, check_mesh(mesh), "candidate");
  result.checks.insert(result.checks.end(), checks.begin(), checks.end());
  const double density_error = meshes.density_error + unit_roundoff_float * std::abs(block.params.threshold);
  const VertexCrossings crossings =
      vertex_crossings(mesh, meshes.density, block.params.threshold, lattice_origin(block.params),
                       block.placement == EdgePlacement::linear,
                       {.unit_roundoff = unit_roundoff_float, .density_error = density_error});
  result.checks.push_back(bounded_check(
      "spec.vertex_crossing.candidate", double(crossings.not_crossing + crossings.off_crossing), 0.0, std::nullopt,
      fmt::format("vertices on an edge the surface does not cross ({}) or off the linear crossing ({}) by more than δ "
                  "+ 8u·(m + 2) + 2e/(|v_b − v_a| − 2e) for a float mesher whose samples err by e = {:.3g} ({}); largest "
                  "distance {:.3g} lattice units, {:.3g} of its bound; {} vertices on edges whose crossing e leaves open",
                  crossings.not_crossing, crossings.off_crossing, density_error,
                  "ε of parity.density.float_vs_double plus the threshold's float rounding", crossings.max_distance,
                  crossings.max_bound_ratio, crossings.excused)));
  result.checks.push_back(bounded_check(
      "parity.crossing_edges.candidate_vs_double",
      double(crossing_edges_unexplained(mesh, meshes.truth, meshes.possible_side_changes)), 0.0, std::nullopt,
      fmt::format("lattice edges carrying a vertex in one mesh only and touching none of the {} samples within ε of "
                  "the threshold (the only ones that may change side): those must cross in both meshes or in neither",
                  meshes.possible_side_changes.size())));
  const std::size_t differing = triangle_difference(key_triangles(mesh), key_triangles(meshes.truth));
  result.checks.push_back(informative_check(
      "parity.topology.candidate_vs_double", double(differing),
      "triangles (by edge keys) in one mesh only: a quad of a tetrahedron may be split along either diagonal, and "
      "samples within ε of the threshold may change side, so this is shown, not graded"));
  const double bound = keyed_hausdorff_bound(meshes.truth, meshes.possible_side_changes);
  const KeyedHausdorff hausdorff = keyed_hausdorff(mesh, meshes.truth);
  const std::string hausdorff_detail = fmt::format(
      "symmetric Hausdorff distance to ref<double>'s mesh (lattice units; keyed twins bounded, the rest sampled by "
      "CGAL every {:.3g}); bound fixed before the candidate is read: 2√3 where both meshes cross the same edges, 3√3 + "
      "D near a sample that may change side, D its distance to the nearest vertex the meshes must share (valid where "
      "parity.crossing_edges passes)",
      hausdorff.grid_spacing);
  result.checks.push_back(std::isfinite(bound) ? bounded_check("parity.hausdorff.candidate_vs_double",
                                                               hausdorff.distance, bound, std::nullopt, hausdorff_detail)
                                               : informative_check("parity.hausdorff.candidate_vs_double",
                                                                   hausdorff.distance,
                                                                   hausdorff_detail + "; no finite bound here: a "
                                                                   "sample that may change side has no truth vertex "
                                                                   "within 8 lattice points"));
  result.checks.push_back(
      not_applicable_check("determinism.candidate", "a file is read once: run your mesher twice and compare the files"));
  write_mesh_artifact(mesh, "mesh.candidate." + block.mesh_format,
                      fmt::format("candidate mesh, {} triangles", mesh.triangles.size()), options, result);
  write_mesh_picture(mesh, "candidate", options, result);
}

// The GPU twin's half of a block case: its mesh against ref<float> and ref<double>, and its own
// CGAL and OpenMesh checks.
void run_gpu_half(const Block& block, const BlockMeshes& meshes, const RunOptions& options, CaseResult& result) {
  if (options.candidate.mesh) return run_candidate_half(block, meshes, *options.candidate.mesh, options, result);
  if (block.mesher == Mesher::cubes) {
    result.notes.push_back("no GPU twin, on purpose: the seed's marching cubes is kept on the CPU as the variant whose "
                           "holes the checks must catch");
    return;
  }
  if (!options.gpu_available) {
    // The GPU mesh's mesh.* checks are skipped where the CPU's are made (run_block).
    for (const char* name : {"parity.topology.gpu_vs_float", "parity.max_abs.gpu_vs_float", "parity.topology.gpu_vs_double",
                             "parity.hausdorff.gpu_vs_double", "parity.vertex_model.gpu_vs_double", "determinism.gpu"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
    if (!block.volume) result.checks.push_back(skipped_check("parity.normals.gpu_vs_float", options.gpu_unavailable_reason));
    return;
  }
  const TriangleMesh<float> gpu_mesh = run_gpu(block, meshes.density_float, options, result);
  add_gpu_vs_float(gpu_mesh, meshes.single, result);
  if (!block.volume) add_gpu_normals_check(block, gpu_mesh, result);  // normals of the seed's noise
  if (same_mesh(gpu_mesh, meshes.single)) {
    repeat_float_vs_double_as_gpu(result);
  } else {
    add_vs_double(meshes, gpu_mesh, "gpu_vs_double", result);
  }
  if (options.progress) options.progress->stage("CGAL and OpenMesh (gpu)");
  const Mesh gpu_double = to_double_mesh(gpu_mesh);
  const auto checks = block_mesh_checks(block, gpu_double, check_mesh(gpu_double), "gpu");
  result.checks.insert(result.checks.end(), checks.begin(), checks.end());
  write_mesh_artifact(gpu_double, "mesh.gpu." + block.mesh_format,
                      fmt::format("gpu mesh, {} triangles", gpu_double.triangles.size()), options, result);
  write_mesh_picture(gpu_double, "gpu", options, result);  // beside the cpu mesh's, from the same camera
}

void run_block(const Block& block, const std::string& volume_file, const nlohmann::json& expect,
               const RunOptions& options, CaseResult& result) {
  const std::string field = block.volume ? volume_file
                                         : fmt::format("seed 004 density (scale {:g}, kernel {:g})", block.params.scale,
                                                       block.params.kernel_radius_squared);
  result.input = fmt::format("{}, {}x{}x{} cells at ({}, {}, {}), threshold {:g}, {}", field, block.params.size[0],
                             block.params.size[1], block.params.size[2], block.params.origin[0], block.params.origin[1],
                             block.params.origin[2], block.params.threshold, block.params.solid ? "solid" : "open chunk");
  const BlockMeshes meshes = run_reference(block, options, result);
  write_density_fields(block, meshes, options, result);
  // The CPU mesh's CGAL and OpenMesh checks (a third of a 128³ case) run on a second thread while
  // this one does the rest; their checks are listed first all the same.
  if (options.progress) options.progress->stage("CGAL and OpenMesh (cpu, on a second thread) and parity");
  std::future<MeshReport> cpu_report = std::async(std::launch::async, [&meshes] { return check_mesh(meshes.truth); });
  const std::size_t cpu_checks_at = result.checks.size();
  add_expected_triangles(expect, meshes.truth.triangles.size(), "cpu", result);
  add_crossing_check(block, meshes, result);
  if (!block.volume) add_normal_checks(block, meshes.truth, result);  // normals of the seed's noise
  add_vs_double(meshes, meshes.single, "float_vs_double", result);
  write_mesh_artifact(meshes.truth, "mesh.cpu." + block.mesh_format,
                      fmt::format("cpu mesh, {} triangles", meshes.truth.triangles.size()), options, result);
  write_mesh_picture(meshes.truth, "cpu", options, result);
  run_gpu_half(block, meshes, options, result);

  const MeshReport report = cpu_report.get();
  std::vector<Check> cpu_checks = block_mesh_checks(block, meshes.truth, report, "cpu");
  if (auto volume = volume_check(block, meshes, report)) cpu_checks.push_back(std::move(*volume));
  if (block.params.solid && block.mesher == Mesher::tetrahedra) {
    cpu_checks.push_back(piecewise_linear_volume_check(block, meshes));
  }
  result.checks.insert(result.checks.begin() + static_cast<std::ptrdiff_t>(cpu_checks_at), cpu_checks.begin(),
                       cpu_checks.end());
  if (block.mesher == Mesher::tetrahedra && !options.gpu_available && !options.candidate.mesh) {
    skip_as_other_backend(result, "mesh.", ".cpu", ".gpu", options.gpu_unavailable_reason);
  }
}

Block block_from_json(Mesher mesher, const nlohmann::json& resolved, const LoadedInput& input) {
  const auto given = params_from_json(cave_mesh_param_table(), resolved);
  Block block;
  block.params = given.block;
  require_noise_range(block.params);
  if (input.volume) {
    block.volume = std::make_shared<const Volume<double>>(*input.volume);
    block.params.size = {input.volume->nx - 1, input.volume->ny - 1, input.volume->nz - 1};
  }
  block.mesher = mesher;
  block.placement = given.placement;
  block.mesh_format = given.mesh_format;
  const std::array<std::int64_t, 3> samples = {block.params.size[0] + 1, block.params.size[1] + 1,
                                               block.params.size[2] + 1};
  if (!lattice_range_fits(lattice_origin(block.params), samples, block.params.solid)) {
    throw InputError("the block (with its pad) leaves the lattice range of the edge keys, ±2^19 per axis");
  }
  require_checkable_block(block.params);
  return block;
}

PreparedTwin prepare_block(Mesher mesher, const nlohmann::json& resolved, const LoadedInput& input) {
  if (input.heights.size() != 0 || input.mesh) {
    throw InputError("the cave meshes the seed's noise or a volume ({\"volume\": \"file.npy\"}), not a heightmap or a mesh");
  }
  PreparedTwin prepared;
  prepared.kind = CaseRun([block = block_from_json(mesher, resolved, input), file = input.description](
                     const nlohmann::json& expect, const RunOptions& options, CaseResult& result) {
    run_block(block, file, expect, options, result);
  });
  return prepared;
}

// ---- performance rows: a solid block of side n, seed 004's density, marching tetrahedra ----------

constexpr int benchmark_sides[] = {32, 64, 128, 256};

BenchmarkRow mesher_row(const std::string& backend, int side, int reps, const std::vector<double>& times,
                        std::size_t triangles, const std::string& device) {
  BenchmarkRow row{.algorithm = "cave.marching_tetrahedra", .backend = backend, .size = side, .iterations = 1,
                   .reps = reps, .median_ms = median(times), .device = device, .dimensions = 3};
  row.mcell_iterations_per_s = std::pow(double(side), 3) / (row.median_ms * 1e-3) / 1e6;
  row.mtriangles_per_s = double(triangles) / (row.median_ms * 1e-3) / 1e6;
  return row;
}

// VTK's flying edges and marching cubes on the same density samples, as peer rows; one row with
// the reason when VTK cannot be run.
void add_vtk_peer_rows(const Volume<double>& density, const CaveParams& params, int reps, const Environment& environment,
                       std::vector<BenchmarkRow>& rows) {
  const int side = params.size[0];
  try {
    for (const IsosurfacePeerRun& run : run_vtk_isosurface(density, params.threshold, reps)) {
      BenchmarkRow row = mesher_row("peer", side, reps, run.ms, run.triangles, environment.cpu);
      row.peer = run.name;
      row.detail = "the same density samples, isosurface only (no capping faces)";
      rows.push_back(row);
    }
  } catch (const std::exception& error) {
    rows.push_back({.algorithm = "cave.marching_tetrahedra", .backend = "peer", .size = side, .iterations = 1,
                    .device = environment.cpu, .dimensions = 3, .note = error.what(), .peer = "VTK"});
  }
}

std::vector<BenchmarkRow> benchmark_mesher(const BenchmarkOptions& options, bool gpu_available,
                                           const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  for (const int side : benchmark_sides) {
    if (!within_table_sizes(std::pow(double(side), 3), options)) continue;
    CaveParams params;
    params.size = {side, side, side};
    const auto density = reference::cave_density<double>(params);
    std::vector<double> cpu_times;
    std::size_t triangles = 0;
    for (int rep = 0; rep < options.reps; ++rep) {
      cpu_times.push_back(cpu_wall_ms([&] {
        triangles = reference::marching_tetrahedra(density, params.threshold, params.solid, lattice_origin(params))
                        .triangles.size();
      }));
    }
    BenchmarkRow cpu_row = mesher_row("cpu", side, options.reps, cpu_times, triangles, environment.cpu);
    cpu_row.detail = "meshing only: the density is sampled beforehand";
    rows.push_back(cpu_row);
    add_vtk_peer_rows(density, params, options.reps, environment, rows);
    if (!gpu_available) continue;
    try {
      gpu::MarchingTetrahedra mesher(density.cast<float>(), static_cast<float>(params.threshold), params.solid,
                                     params.origin);
      mesher.run();
      std::vector<double> gpu_times;
      for (int rep = 0; rep < options.reps; ++rep) gpu_times.push_back(gpu_wall_ms([&] { mesher.run(); }));
      BenchmarkRow gpu_row = mesher_row("gpu", side, options.reps, gpu_times, triangles, environment.gl_renderer);
      gpu_row.detail = "meshing only: the same density samples, uploaded beforehand";
      rows.push_back(gpu_row);
    } catch (const std::runtime_error& error) {
      rows.push_back({.algorithm = "cave.marching_tetrahedra", .backend = "gpu", .size = side, .iterations = 1,
                      .device = environment.gl_renderer, .dimensions = 3, .note = error.what()});
    }
  }
  return rows;
}

// Lattice samples of the block: the volume's, or (size + 1) per axis, and 2 more of capping air
// when solid. Measured 5250 B a sample for marching tetrahedra (97³ vs 33³ samples, both backends:
// the meshes, their CGAL and OpenMesh checks, the density in double and float) and 2870 for
// marching cubes (65³ vs 33³, CPU only).
MemoryEstimate block_memory(const nlohmann::json& resolved, const LoadedInput& input) {
  double samples = 1.0;
  if (input.volume) {
    samples = static_cast<double>(input.volume->values.size());
  } else {
    const CaveParams block = params_from_json(cave_mesh_param_table(), resolved).block;
    const double padding = block.solid ? 2.0 : 0.0;
    for (const int cells : block.size) samples *= cells + 1.0 + padding;
  }
  return memory_for(samples, "lattice samples", 6000);
}

}  // namespace

CaveMeshParams cave_mesh_defaults_for_cubes() { return {.placement = EdgePlacement::midpoint}; }

const ParamTable<CaveMeshParams>& cave_mesh_param_table() {
  using C = CaveMeshParams;
  static const ParamTable<C> table = [] {
    ParamTable<C> rows = nested(&C::block, cave_param_table());
    rows.push_back(choice_param("placement", &C::placement, placement_choices, "",
                                "vertex on a crossing edge: linear interpolation (the seed's final version) or the "
                                "midpoint"));
    rows.push_back(choice_param("mesh_format", &C::mesh_format, {"ply", "obj", "off"}, "",
                                "file format of the meshes written beside the report"));
    return rows;
  }();
  return table;
}

std::vector<Algorithm> cave_algorithms() {
  return {
      {.name = "cave.marching_tetrahedra",
       .summary = "seed 004's cave block meshed by marching tetrahedra, welded by lattice edge key (CPU and GPU)",
       .source = "seed 004 digest §2.2-2.6, §2.8 (Kuhn decomposition, oriented case table)",
       .params = &block_specs(Mesher::tetrahedra),
       .prepare = [](const nlohmann::json& resolved,
                     const LoadedInput& input) { return prepare_block(Mesher::tetrahedra, resolved, input); },
       .kind = CaseKind::custom,
       .ad_hoc_input = AdHocInput::optional_volume,
       .candidate = CandidateOutput::mesh,
       .benchmark = benchmark_mesher,
       // Counted in reference/cave/marching_tetrahedra.cpp (meshing only, as the table times it) and
       // gpu/cave/marching_tetrahedra.cpp (meshing an uploaded volume); per voxel, output not counted.
       .traffic = {.cpu = 16.0, .gpu = 52.0},
       .expect_shape = {{"triangles", "integer"}},
       .memory = block_memory},
      {.name = "cave.marching_cubes",
       .summary = "the seed's dropped marching cubes (14 base cases, midpoints, no disambiguation): the variant with holes",
       .source = "seed 004 digest §2.5",
       .params = &block_specs(Mesher::cubes),
       .prepare = [](const nlohmann::json& resolved,
                     const LoadedInput& input) { return prepare_block(Mesher::cubes, resolved, input); },
       .kind = CaseKind::custom,
       .ad_hoc_input = AdHocInput::optional_volume,
       .memory = block_memory},
  };
}

}  // namespace gt
