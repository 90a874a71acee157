// The driver's view of the noise functions (issue: noise and terrain synthesis as twins): each
// function and fractal sum as a generated field on the input's grid, with the error model of
// float coordinates, and the checks that belong to noise: spec vectors, range, mean, gradient,
// the lattice gradients against the published tables (Perlin 2002, Gustavson 2005), fractal sums
// against Musgrave's formulas written out here, and the walk away from the origin. Mutants that
// these checks kill (issue 11): compare/mutants/noise.cpp.
//
// Error model (absolute, in output units):
//   coordinates: each float coordinate origin_c + i·step is rounded twice, so it is off by at
//     most 2u·C (C = the largest |coordinate| of the float twins' grid, after any origin
//     reduction, times lacunarity^(octaves-1) for fractal sums); the value then moves by at most
//     lipschitz·2u·C·sqrt(dimension) (lipschitz = largest gradient norm of the function).
//   arithmetic: the evaluation itself rounds each of its operations; its terms are at most
//     `arithmetic_terms` in magnitude (the output scale of the function times the number of
//     corner contributions) and each carries a few roundings: 8u·terms.
//   The precision bound (float or GPU vs double) is their sum, strict; beyond it the outcome is
//   `warn` with the coordinate, as the far-from-origin walk expects. The logic bound (GPU vs
//   float, same operations, no divisions) is the arithmetic part alone and fails beyond it.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/noise_error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/report/plots.hpp"
#include "core/errors.hpp"
#include "core/noise/permutation.hpp"
#include "core/params/noise.hpp"
#include "gpu/noise/noise_field.hpp"
#include "reference/noise/noise_field.hpp"

namespace gt {
namespace {

double float_grid_extent(const NoiseParams& params) {
  NoiseParams float_side = params;
  float_side.sampling.origin = reduced_origin(params);
  return largest_coordinate(float_side);
}

// A bound on |value| of the function: its terms' scale times the octaves' weights.
double value_scale(const NoiseParams& params) { return traits_of(params.basis).largest_value * octave_sums(params).first; }

// Seed 001's tile blends four values with weights that sum to 1, so each sample's error carries
// over at most once; the blend itself rounds the weights (c = i·(1/W) and 1 − c, both twins alike)
// and its four products and three sums: 8u of the value's scale.
double tile_blend_bound(const NoiseParams& params) {
  return params.tileable ? 8.0 * 0x1p-24 * value_scale(params) : 0.0;
}

// A tileable field repeats with the grid's period: ref<double>'s sample one grid past the right edge
// equals the first of its row, and one past the top the first of its column (the points are the
// same numbers and the weights 1 and 0 there, up to one rounding of W·(1/W): u of the difference of
// two values, plus the blend's other roundings, 8u of the value's scale, at each end).
void add_tile_period_check(const NoiseParams& params, CaseResult& result) {
  if (!params.tileable) return;
  const int width = params.sampling.width, height = params.sampling.height;
  std::vector<std::array<int, 2>> cells;
  for (int j = 0; j < height; ++j) cells.insert(cells.end(), {{0, j}, {width, j}});
  for (int i = 0; i < width; ++i) cells.insert(cells.end(), {{i, 0}, {i, height}});
  const auto samples = reference::noise_samples_at(params, params.sampling.origin, cells);
  double worst = 0.0;
  for (std::size_t pair = 0; pair + 1 < samples.size(); pair += 2) worst = std::max(worst, std::abs(samples[pair + 1] - samples[pair]));
  const double bound = 2.0 * 10.0 * 0x1p-53 * value_scale(params);
  result.checks.push_back(bounded_check(
      "spec.tile_period.cpu", worst, bound, std::nullopt,
      fmt::format("largest |sample(i + {}, j) − sample(i, j)| over the first column and |sample(i, j + {}) − sample(i, j)| "
                  "over the first row, ref<double>: a tile repeats; bound 2·10u·{:.3g} (the value's scale), the "
                  "blend's roundings at each end",
                  width, height, value_scale(params))));
}

FieldTwin::GeneratedField noise_bounds(const NoiseParams& params) {
  const double weights = octave_sums(params).first;
  const double arithmetic = noise_arithmetic_bound(params) + tile_blend_bound(params);
  // float_grid_extent reaches one grid further along x and y where the field is tileable.
  const double precision = noise_precision_bound(params, float_grid_extent(params)) + tile_blend_bound(params);
  return {{arithmetic, arithmetic,
           is_cellular(params.basis) ? "same float operations in the same order, the square root's licence apart"
                                     : "same float operations in the same order, no division: 8u per term"},
          {precision, precision,
           fmt::format("float coordinates up to |x| = {:.4g} (2u·|x|·lipschitz), arithmetic, and {:.3g} for "
                       "simplex corners the kernel switches at boundaries: an upper bound, no warn band",
                       float_grid_extent(params), switched_contribution(params) * weights)},
          lattice_jump_samples(params),
          "where a rounding may move a coordinate across a lattice plane and the cellular basis jumps there (found "
          "from the coordinates before any twin ran)"};
}

// Terrain synthesis: height = base + amplitude·value, in the twin's own precision (so the float
// twins still do identical arithmetic), on the sampling grid's geometry.
template <class Real>
Grid<Real> as_terrain(Grid<Real> field, const NoiseParams& params, const Heightmap& grid) {
  const bool scaled = params.amplitude != 1.0 || params.base != 0.0;
  if (scaled) {
    const Real amplitude = static_cast<Real>(params.amplitude), base = static_cast<Real>(params.base);
    for (auto& value : field.values) value = base + amplitude * value;
  }
  field.cell_size_x = grid.cell_size_x;
  field.cell_size_y = grid.cell_size_y;
  field.horizontal_unit = grid.horizontal_unit;
  field.vertical_unit = scaled ? "m" : "1";
  return field;
}

// The bounds of the unscaled field times |amplitude|, plus the rounding of the scaling itself.
FieldTwin::GeneratedField terrain_bounds(const NoiseParams& params) {
  auto bounds = noise_bounds(params);
  const double scaling = 2.0 * unit_roundoff_float * (std::abs(params.base) + std::abs(params.amplitude));
  for (Bounds* bound : {&bounds.logic, &bounds.precision}) {
    bound->strict = bound->strict * std::abs(params.amplitude) + scaling;
    bound->loose = std::max(bound->loose, bound->strict);
  }
  return bounds;
}


// spec.points: {"points": [[x, y, z, (w,) value], ...], "tolerance": t}, evaluated in double (as
// base + amplitude·value for terrain synthesis).
void add_point_spec(const NoiseParams& params, const nlohmann::json& expect, CaseResult& result) {
  if (!expect.contains("points")) return;
  double worst = 0.0;
  for (const auto& entry : expect["points"]) {
    if (entry.size() < 2 || entry.size() > 5) {
      throw InputError(fmt::format("expect.points: {} is not [x, (y, (z, (w,))) value]", entry.dump()));
    }
    std::array<double, 4> point{};
    const std::size_t coordinates = entry.size() - 1;
    for (std::size_t axis = 0; axis < coordinates && axis < 4; ++axis) point[axis] = entry[axis];
    const double value = params.base + params.amplitude * reference::noise_at(params, point);
    worst = std::max(worst, std::abs(value - entry.back().get<double>()));
  }
  const double tolerance = expect.value("tolerance", 0.0);
  result.checks.push_back(bounded_check("spec.points", worst, tolerance, std::nullopt,
                                        fmt::format("largest deviation from the case's listed values; tolerance {} "
                                                    "(the case's description says where they come from)",
                                                    tolerance)));
}

// spec.lattice_nonnegative: {"lattice_nonnegative": {"size": n, "count": c}}: how many points of
// {0..n-1}^3 have noise >= 0, in double (seed 004's "Total points drawn").
void add_lattice_spec(const NoiseParams& params, const nlohmann::json& expect, CaseResult& result) {
  if (!expect.contains("lattice_nonnegative")) return;
  const int size = expect["lattice_nonnegative"].at("size");
  const int expected = expect["lattice_nonnegative"].at("count");
  int count = 0;
  for (int x = 0; x < size; ++x) {
    for (int y = 0; y < size; ++y) {
      for (int z = 0; z < size; ++z) count += reference::noise_at(params, {double(x), double(y), double(z), 0.0}) >= 0.0;
    }
  }
  result.checks.push_back(bounded_check("spec.lattice_nonnegative", std::abs(count - expected), 0.0, std::nullopt,
                                        fmt::format("{} of {}^3 lattice points have noise >= 0; the seed printed {}",
                                                    count, size, expected)));
}

// The largest |value| of a basis (and of normalised fBm over it). The lattice noises stay inside
// [-1, 1] (the seeds' claim); the texture variant's decoded gradients are 256/255 too long and
// biased by up to 1/255·0.44 (reference/noise/perlin_texture.hpp): [-1.0056, 1.0056]. The cellular
// bases (reference/noise/cellular.hpp): F1 <= sqrt(3) (the own cell's point), so 2·F1 − 1 <= 2.4641;
// F2..F4 and F2 − F1 <= sqrt(4.25) (the own cell's and the three nearest face neighbours' points),
// so <= 3.1232; crackle and cell noise stay in [-1, 1].
double largest_basis_value(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::perlin3_texture: return 256.0 / 255.0 + 0.0017;
    case NoiseBasis::voronoi_f1: return 2.0 * std::sqrt(3.0) - 1.0;
    case NoiseBasis::voronoi_f2:
    case NoiseBasis::voronoi_f3:
    case NoiseBasis::voronoi_f4:
    case NoiseBasis::voronoi_f2f1: return 2.0 * std::sqrt(4.25) - 1.0;
    default: return 1.0;
  }
}

// Basis functions and normalised fBm stay inside their range and, but for the Voronoi distances,
// have mean 0 (gradient sets and cell values are symmetric). The mean of N_eff ≈ (extent in lattice units)² roughly
// independent cells has standard deviation σ/sqrt(N_eff): bound 4σ/sqrt(N_eff).
void add_distribution_checks(const NoiseParams& params, const Grid<double>& field, CaseResult& result) {
  if (params.fractal == Fractal::ridged || params.fractal == Fractal::hetero_terrain) return;
  const auto totals = field_totals(field);
  const double largest = std::max(std::abs(totals.low), std::abs(totals.high));
  const double limit = largest_basis_value(params.basis);
  result.checks.push_back(bounded_check("spec.range.cpu", largest, limit, std::nullopt,
                                        fmt::format("max |value| <= {:.4g}", limit)));
  if (is_cellular(params.basis) && params.basis != NoiseBasis::cell_noise) {
    result.checks.push_back(not_applicable_check(
        "spec.mean.cpu", "distances to feature points are not centred: 2·F − 1 has no mean of 0 to hold"));
    return;
  }
  const double cells = static_cast<double>(totals.cells);
  const double mean = totals.sum / cells;
  const double deviation = std::sqrt(std::max(0.0, totals.sum_squares / cells - mean * mean));
  const auto& sampling = params.sampling;
  const double independent = (sampling.width * sampling.step) * (sampling.height * sampling.step);
  if (independent < 16.0) {
    result.checks.push_back(not_applicable_check("spec.mean.cpu", "the grid spans fewer than 16 lattice cells"));
    return;
  }
  result.checks.push_back(bounded_check("spec.mean.cpu", std::abs(mean), 4.0 * deviation / std::sqrt(independent),
                                        std::nullopt,
                                        fmt::format("|mean| over {:.0f} lattice cells; bound 4σ/sqrt(cells)", independent)));
}

// Analytic gradient vs central differences with step h in double: truncation h²/6·M3 (M3 the
// largest third derivative, below 2e3 for these functions at scale 70/32) plus rounding
// 2·2^-53·|f|/h. Sampled at up to 400 grid points.
void add_gradient_check(const NoiseParams& params, CaseResult& result) {
  const auto& sampling = params.sampling;
  const std::array<double, 4> origin = sampling.origin;
  if (!reference::noise_gradient_at(params, origin)) return;
  if (switched_contribution(params) > 0.0) {
    result.checks.push_back(not_applicable_check("spec.gradient.cpu",
                                          "kernel radius² above 0.5 makes the field jump at simplex boundaries "
                                          "(digest 004 §2.2.5): central differences straddle the jumps"));
    return;
  }
  constexpr double h = 1e-4;
  const double bound = h * h / 6.0 * 2e3 + 2.0 * 0x1p-53 * 70.0 / h;
  const int stride = std::max(1, static_cast<int>(std::sqrt(double(sampling.width) * sampling.height / 400.0)));
  double worst = 0.0;
  for (int j = 0; j < sampling.height; j += stride) {
    for (int i = 0; i < sampling.width; i += stride) {
      std::array<double, 4> point = origin;
      point[0] += i * sampling.step;
      point[1] += j * sampling.step;
      const auto gradient = *reference::noise_gradient_at(params, point);
      for (int axis = 0; axis < noise_dimension(params.basis); ++axis) {
        auto ahead = point, behind = point;
        ahead[axis] += h;
        behind[axis] -= h;
        const double difference = (reference::noise_at(params, ahead) - reference::noise_at(params, behind)) / (2 * h);
        worst = std::max(worst, std::abs(difference - gradient[axis + 1]));
      }
    }
  }
  result.checks.push_back(bounded_check("spec.gradient.cpu", worst, bound, std::nullopt,
                                        "analytic gradient vs central differences (h = 1e-4): h²/6·M3 + rounding"));
}

// The 16 gradients of improved Perlin noise as Perlin 2002 ("Improving noise", §3) lists them: the
// 12 cube-edge midpoints, padded to 16 with (1,1,0), (0,-1,1), (-1,1,0), (0,-1,-1), indexed by the
// hash's low 4 bits. Gustavson 2005's grad3 for simplex noise is the first 12, in the same order.
// Transcribed from the papers for the check below, independently of both twins' tables.
constexpr std::array<std::array<int, 3>, 16> published_gradients{{{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                                                 {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                                                 {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1},
                                                                 {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}}};

// Lattice vertices the check visits: integer (skewed, for simplex) coordinates in {-3..4}^n.
constexpr int lattice_low = -3, lattice_high = 4;

struct LatticeExpectation {
  std::array<double, 4> point;     // the vertex in noise space
  std::array<double, 4> expected;  // {value, ∂/∂x, ∂/∂y, ∂/∂z}
};

// Improved Perlin noise at an integer point: every fade weight is 0 and fade' is 0, so the value is
// the cell's own corner term g·0 = 0 and the gradient is that corner's g, hashed as Perlin's Java
// code does: P[P[P[X] + Y] + Z] & 15 with X = x & 255 (P the table doubled, written here & 255).
LatticeExpectation perlin_vertex(const Permutation& perm, const std::array<int, 3>& vertex) {
  const auto wrap = [](int value) { return value & 255; };
  const int hash = perm[wrap(perm[wrap(perm[wrap(vertex[0])] + wrap(vertex[1]))] + wrap(vertex[2]))] & 15;
  const auto& g = published_gradients[hash];
  return {{double(vertex[0]), double(vertex[1]), double(vertex[2]), 0.0}, {0.0, double(g[0]), double(g[1]), double(g[2])}};
}

// Simplex noise at a vertex of its lattice (skewed coordinates i, unskewed x = i - (Σi)·G):
// every other vertex lies at distance² >= 0.667 (2-D) or 0.75 (3-D) from it, beyond both kernels
// (0.5, 0.6), so only the vertex's own corner contributes, with d = 0: value 0 and gradient
// scale·r²⁴·g, g = grad3[hash % 12], hash perm[i + perm[j]] (2-D) or perm[i + perm[j + perm[k]]]
// (3-D) on the doubled table (Gustavson 2005); scale 70 (2-D) or 32 (3-D); r² 0.5 in 2-D, the
// case's kernel in 3-D.
LatticeExpectation simplex_vertex(const Permutation& perm, const std::array<int, 3>& vertex, int dimension,
                                  double kernel_radius_squared_3d) {
  const double kernel_radius_squared = dimension == 2 ? 0.5 : kernel_radius_squared_3d;
  const auto wrap = [](int value) { return value & 255; };
  const double unskew = (std::sqrt(dimension + 1.0) - 1.0) / std::sqrt(dimension + 1.0) / dimension;  // G
  const int sum = dimension == 2 ? vertex[0] + vertex[1] : vertex[0] + vertex[1] + vertex[2];
  const int inner = dimension == 2 ? wrap(vertex[1]) : wrap(wrap(vertex[1]) + perm[wrap(vertex[2])]);
  const int hash = perm[wrap(wrap(vertex[0]) + perm[inner])] % 12;
  const double scale = dimension == 2 ? 70.0 : 32.0;
  const double slope = scale * std::pow(kernel_radius_squared, 4);
  LatticeExpectation expectation{};
  for (int axis = 0; axis < dimension; ++axis) {
    expectation.point[axis] = vertex[axis] - sum * unskew;
    expectation.expected[axis + 1] = slope * published_gradients[hash][axis];
  }
  return expectation;
}

// spec.lattice_gradient: the value and analytic gradient (double reference) at the lattice
// vertices in {-3..4}^n against the published gradient tables and hash orders above.
// Error model: improved Perlin at integer points is exact (weights 0 and 1, corner gradients ±1,
// a + 0·(b - a) = a): bound 0. Simplex: the vertex x_a = i_a - s·G is rounded, so d = O(4u·|x|)
// with |x| <= 8 (u = 2^-53), changing the gradient by O(scale·r²³·|d|²) (nothing at first order:
// -8t³(g·d)d is quadratic in d) and the value by scale·r²⁴·|g|·|d| <= 70·0.0625·1.5·4u·8 ≈ 2e-14;
// the roundings of the corner arithmetic (about 12 operations on terms <= scale·r²⁴·|g| <= 6.2)
// add 12u·6.2 ≈ 1e-14. Bound 1e-13, a few times their sum.
void add_lattice_gradient_check(const NoiseParams& params, CaseResult& result) {
  if (params.fractal != Fractal::none) return;
  const bool perlin = params.basis == NoiseBasis::perlin3;
  if (!perlin && params.basis != NoiseBasis::simplex2 && params.basis != NoiseBasis::simplex3) return;
  const Permutation perm = seeded_permutation(params.seed);
  const int dimension = noise_dimension(params.basis);
  double worst = 0.0;
  const int z_high = dimension == 2 ? lattice_low : lattice_high;
  for (int x = lattice_low; x <= lattice_high; ++x) {
    for (int y = lattice_low; y <= lattice_high; ++y) {
      for (int z = lattice_low; z <= z_high; ++z) {
        const std::array<int, 3> vertex = {x, y, dimension == 2 ? 0 : z};
        const auto expectation = perlin ? perlin_vertex(perm, vertex)
                                        : simplex_vertex(perm, vertex, dimension, params.kernel_radius_squared);
        const auto actual = *reference::noise_gradient_at(params, expectation.point);
        for (int component = 0; component <= dimension; ++component) {
          worst = std::max(worst, std::abs(actual[component] - expectation.expected[component]));
        }
      }
    }
  }
  const double bound = perlin ? 0.0 : 1e-13;
  result.checks.push_back(bounded_check(
      "spec.lattice_gradient.cpu", worst, bound, std::nullopt,
      fmt::format("largest |(value, gradient) - (0, {})| at the {}^{} lattice vertices in [{}, {}]: the published "
                  "gradient table and hash (Perlin 2002 / Gustavson 2005)",
                  perlin ? "g" : "scale·r²⁴·g", lattice_high - lattice_low + 1, dimension, lattice_low, lattice_high)));
}

// The cellular bases written out from their definition (reference/noise/cellular.hpp states it; this
// transcription is the check's own): every feature point of the 27 cells around floor(p) placed in
// absolute coordinates, their distances to p sorted, Blender's signed variant of the basis.
double transcribed_cellular(const Permutation& perm, NoiseBasis basis, const std::array<double, 4>& point) {
  const auto entry = [&perm](int index) { return static_cast<int>(perm[static_cast<unsigned>(index) & 255u]); };
  const auto hash = [&entry](int x, int y, int z) { return entry(entry(entry(x) + (y & 255)) + (z & 255)); };
  const std::array<int, 3> cell = {static_cast<int>(std::floor(point[0])), static_cast<int>(std::floor(point[1])),
                                   static_cast<int>(std::floor(point[2]))};
  if (basis == NoiseBasis::cell_noise) return (entry(hash(cell[0], cell[1], cell[2]) + 128) + 0.5) / 128.0 - 1.0;
  std::vector<double> distances;
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const std::array<int, 3> neighbour = {cell[0] + dx, cell[1] + dy, cell[2] + dz};
        const int h = hash(neighbour[0], neighbour[1], neighbour[2]);
        double squared = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
          const double feature = neighbour[axis] + (entry(h + 85 * axis) + 0.5) / 256.0;
          squared += (point[axis] - feature) * (point[axis] - feature);
        }
        distances.push_back(std::sqrt(squared));
      }
    }
  }
  std::sort(distances.begin(), distances.end());
  switch (basis) {
    case NoiseBasis::voronoi_f2: return 2.0 * distances[1] - 1.0;
    case NoiseBasis::voronoi_f3: return 2.0 * distances[2] - 1.0;
    case NoiseBasis::voronoi_f4: return 2.0 * distances[3] - 1.0;
    case NoiseBasis::voronoi_f2f1: return 2.0 * (distances[1] - distances[0]) - 1.0;
    case NoiseBasis::voronoi_crackle: return 2.0 * std::min(1.0, 10.0 * (distances[1] - distances[0])) - 1.0;
    default: return 2.0 * distances[0] - 1.0;
  }
}

// spec.cellular.cpu: the double reference's basis against transcribed_cellular at up to 400 grid
// points (the basis alone where a fractal sums it). Error model: both evaluate the same double
// point, so the same 27 cells; they differ by rounding only. The transcription's p − (n + j) rounds
// twice on coordinates up to |p| + 2, the reference's (p − floor p) − (o + j) once more: 4u·(|p| + 2)
// per axis and distance, plus the rest of the distance's arithmetic, 11u·2.062 (traits_of); the
// signed variants multiply a distance's error by 2 (F_k), 4 (F2 − F1) or 40 (crackle), plus
// 8u of rounding on the result. Cell noise is exact in both.
void add_cellular_check(const NoiseParams& params, CaseResult& result) {
  if (!is_cellular(params.basis)) return;
  NoiseParams basis_params = params;
  basis_params.fractal = Fractal::none;
  constexpr double u = 0x1p-53;
  const double distance_error = u * (4.0 * (largest_coordinate(params) + 2.0) + 11.0 * 2.062);
  const double bound = params.basis == NoiseBasis::cell_noise ? 0.0
                                                               : traits_of(params.basis).lipschitz * distance_error + 8.0 * u;
  const Permutation perm = seeded_permutation(params.seed);
  const auto& sampling = params.sampling;
  const int stride = std::max(1, static_cast<int>(std::sqrt(double(sampling.width) * sampling.height / 400.0)));
  double worst = 0.0;
  for (int j = 0; j < sampling.height; j += stride) {
    for (int i = 0; i < sampling.width; i += stride) {
      std::array<double, 4> point = sampling.origin;
      point[0] += i * sampling.step;
      point[1] += j * sampling.step;
      worst = std::max(worst, std::abs(reference::noise_at(basis_params, point) -
                                       transcribed_cellular(perm, params.basis, point)));
    }
  }
  result.checks.push_back(bounded_check(
      "spec.cellular.cpu", worst, bound, std::nullopt,
      fmt::format("largest |ref<double> − the definition written out| ({}: {}) over the grid's points; bound: the two "
                  "evaluations' roundings",
                  noise_basis_name(params.basis),
                  params.basis == NoiseBasis::cell_noise ? "the cell's value from its hash, exact in both"
                                                         : "the 27 cells' feature points, their distances sorted")));
}

// Musgrave's fractal sums written out from their published formulas (reference/noise/fractal.hpp
// states them; this transcription is the check's own): octave k samples the basis b at p·λ^k with
// weights as closed-form powers, where the twins keep running products.
double octave_sum(const NoiseParams& params, const std::array<double, 4>& point) {
  NoiseParams basis_params = params;
  basis_params.fractal = Fractal::none;
  const auto& fractal = params.fractal_params;
  const int whole = static_cast<int>(std::floor(fractal.octaves));
  const double remainder = fractal.octaves - whole;
  const auto basis = [&](int octave) {
    const double frequency = std::pow(fractal.lacunarity, octave);
    return reference::noise_at(basis_params, {point[0] * frequency, point[1] * frequency, point[2] * frequency, 0.0});
  };
  const auto spectral = [&](int octave) { return std::pow(fractal.lacunarity, -fractal.H * octave); };
  switch (params.fractal) {
    case Fractal::fbm: {  // Σ_k g^k·b_k / Σ_k g^k, the last octave weighted by the remainder
      double sum = 0.0, weights = 0.0;
      for (int octave = 0; octave <= whole; ++octave) {
        const double share = octave < whole ? 1.0 : remainder;
        if (share == 0.0) break;
        sum += share * std::pow(fractal.gain, octave) * basis(octave);
        weights += share * std::pow(fractal.gain, octave);
      }
      return sum / weights;
    }
    case Fractal::ridged: {  // s_k = (offset - |b_k|)²·clamp(s_{k-1}·gain, 0, 1), Σ_k s_k·λ^(-Hk)
      double signal = std::pow(fractal.offset - std::abs(basis(0)), 2);
      double sum = signal;
      for (int octave = 1; octave < whole; ++octave) {
        signal = std::pow(fractal.offset - std::abs(basis(octave)), 2) * std::clamp(signal * fractal.gain, 0.0, 1.0);
        sum += signal * spectral(octave);
      }
      return sum;
    }
    case Fractal::hetero_terrain: {  // v = offset + b_0; v += (b_k + offset)·λ^(-Hk)·v
      double value = fractal.offset + basis(0);
      for (int octave = 1; octave <= whole; ++octave) {
        const double share = octave < whole ? 1.0 : remainder;
        if (share == 0.0) break;
        value += share * (basis(octave) + fractal.offset) * spectral(octave) * value;
      }
      return value;
    }
    case Fractal::none: break;
  }
  return reference::noise_at(basis_params, point);
}

// Whether a point's octave points, formed as octave_sum forms them (p·λ^k) and as the references do
// (running products), lie in different lattice cells at some octave: a cellular basis jumps between
// them, by up to its whole range.
bool octave_cells_differ(const NoiseParams& params, const std::array<double, 4>& point) {
  if (!is_cellular(params.basis)) return false;
  const auto& fractal = params.fractal_params;
  std::array<double, 3> running = {point[0], point[1], point[2]};
  for (int octave = 0; octave < static_cast<int>(std::ceil(fractal.octaves)); ++octave) {
    const double frequency = std::pow(fractal.lacunarity, octave);
    for (int axis = 0; axis < 3; ++axis) {
      if (std::floor(point[axis] * frequency) != std::floor(running[axis])) return true;
      running[axis] = running[axis] * fractal.lacunarity;
    }
  }
  return false;
}

// spec.octave_sum: the double reference's fractal sum against octave_sum at up to 400 grid points.
// Error model: the two differ only by rounding. The octave point p·λ^k is rounded once here and k
// times by the running product (relative (k + 1)·u, u = 2^-53), weights likewise; octave_sums gives
// how an error in one octave's basis value grows through the sum (Σ w_k for the values, Σ w_k·λ^k
// for coordinate errors): bound (n + 2)·(8u·terms·Σw + lipschitz·u·|p|·Σw·λ^k·sqrt(3)), n octaves.
void add_octave_sum_check(const NoiseParams& params, CaseResult& result) {
  if (params.fractal == Fractal::none) return;
  const auto traits = traits_of(params.basis);
  const auto [weights, weighted_frequencies] = octave_sums(params);
  constexpr double u = 0x1p-53;
  const double octaves = std::ceil(params.fractal_params.octaves);
  const double bound = (octaves + 2.0) * (8.0 * u * traits.arithmetic_terms * weights +
                                          traits.lipschitz * u * largest_coordinate(params) * weighted_frequencies *
                                              std::sqrt(3.0));
  const auto& sampling = params.sampling;
  const int stride = std::max(1, static_cast<int>(std::sqrt(double(sampling.width) * sampling.height / 400.0)));
  double worst = 0.0;
  int left_out = 0, compared = 0;
  for (int j = 0; j < sampling.height; j += stride) {
    for (int i = 0; i < sampling.width; i += stride) {
      std::array<double, 4> point = sampling.origin;
      point[0] += i * sampling.step;
      point[1] += j * sampling.step;
      if (octave_cells_differ(params, point)) {
        ++left_out;
        continue;
      }
      ++compared;
      worst = std::max(worst, std::abs(reference::noise_at(params, point) - octave_sum(params, point)));
    }
  }
  const std::string jumps =
      left_out == 0 ? "" : fmt::format("; {} of {} points left out, where the two octave points lie in different lattice "
                                       "cells and the cellular basis jumps between them", left_out, left_out + compared);
  result.checks.push_back(bounded_check("spec.octave_sum.cpu", worst, bound, std::nullopt,
                                        "fractal sum vs Musgrave's formula written out with closed-form weights "
                                        "(rounding of running products vs powers)" + jumps));
}

struct WalkPoint {
  double magnitude;
  double float_error;  // ref<float> vs ref<double>
  double gpu_error;    // GPU vs ref<double>, NaN without a GPU
  double bound;
};

WalkPoint walk_point(NoiseParams params, double magnitude, const std::array<double, 4>& direction, bool gpu) {
  for (int axis = 0; axis < 4; ++axis) params.sampling.origin[axis] = magnitude * direction[axis];
  const auto truth = reference::noise_field<double>(params, params.sampling.origin);
  const auto float_side = reference::noise_field<float>(params, reduced_origin(params));
  WalkPoint point{magnitude, field_difference(truth, float_side).max_abs, std::nan(""),
                  noise_bounds(params).precision.strict};
  if (gpu) {
    gpu::NoiseField field(params);
    field.run();
    point.gpu_error = field_difference(truth, field.result()).max_abs;
  }
  return point;
}

std::vector<WalkPoint> walk(const NoiseParams& params, const nlohmann::json& walk_spec, bool gpu) {
  std::array<double, 4> direction{};
  double norm = 0.0;
  for (std::size_t axis = 0; axis < walk_spec.at("direction").size() && axis < 4; ++axis) {
    direction[axis] = walk_spec["direction"][axis];
    norm += direction[axis] * direction[axis];
  }
  if (norm == 0.0) throw InputError("walk direction must not be zero");
  for (double& component : direction) component /= std::sqrt(norm);
  std::vector<WalkPoint> points;
  for (const auto& magnitude : walk_spec.at("magnitudes")) points.push_back(walk_point(params, magnitude, direction, gpu));
  return points;
}

constexpr double walk_acceptance = 1e-4;  // the absolute agreement users ask of noise twins near the origin

double walk_error(const WalkPoint& point, bool gpu) { return gpu ? point.gpu_error : point.float_error; }

// The error model is an upper bound: exceeding it anywhere on the walk fails.
Check walk_model_check(const std::string& name, const std::vector<WalkPoint>& points, bool gpu) {
  double worst_ratio = 0.0;
  for (const auto& point : points) worst_ratio = std::max(worst_ratio, walk_error(point, gpu) / point.bound);
  return bounded_check(name, worst_ratio, 1.0, std::nullopt,
                       "largest (error vs double) / (error model) along the walk; the model bounds the error");
}

// Where the error first passes the 1e-4 acceptance, naming the coordinate. Without the remedy this
// shows the float trap far from the origin (informative: the walk goes there to show it); with
// the origin reduced it is a bound (`bounded`).
Check walk_acceptance_check(const std::string& name, const std::vector<WalkPoint>& points, bool gpu, bool bounded) {
  double worst = 0.0;
  std::string first_exceeded;
  for (const auto& point : points) {
    const double error = walk_error(point, gpu);
    worst = std::max(worst, error);
    if (error > walk_acceptance && first_exceeded.empty()) {
      first_exceeded = fmt::format("; first over it at |x| = {:.3g} (error {:.3g})", point.magnitude, error);
    }
  }
  const std::string detail =
      fmt::format("largest error vs double along the walk against {:g}{}", walk_acceptance, first_exceeded);
  return bounded ? bounded_check(name, worst, walk_acceptance, std::nullopt, detail)
                 : informative_check(name, worst, detail + " (without reduce_origin: shown, not judged)");
}

void add_walk(const NoiseParams& params, const nlohmann::json& expect, const RunOptions& options, CaseResult& result) {
  if (!expect.contains("walk")) return;
  if (is_cellular(params.basis)) {
    result.checks.push_back(not_applicable_check(
        "parity.walk_model", "a cellular basis jumps by up to its range where a rounding moves a coordinate across a "
                             "lattice plane, which grows likelier with |x|: a walk's largest error would be a jump"));
    return;
  }
  if (options.progress != nullptr) options.progress->stage("walk away from the origin");
  NoiseParams direct = params, remedied = params;
  direct.reduce_origin = false;
  remedied.reduce_origin = true;
  const auto plain = walk(direct, expect["walk"], options.gpu_available);
  const auto reduced = walk(remedied, expect["walk"], options.gpu_available);
  const std::string backend = options.gpu_available ? "gpu_vs_double" : "float_vs_double";
  const bool gpu = options.gpu_available;
  result.checks.push_back(walk_model_check("parity.walk_model." + backend, plain, gpu));
  result.checks.push_back(walk_acceptance_check("parity.walk_acceptance." + backend, plain, gpu, false));
  result.checks.push_back(walk_model_check("parity.walk_model_reduced_origin." + backend, reduced, gpu));
  result.checks.push_back(walk_acceptance_check("parity.walk_acceptance_reduced_origin." + backend, reduced, gpu, true));
  SeriesPlot plot{fmt::format("{}: largest error vs double along the walk", result.name), "|origin| (noise units)",
                  "max |error|", true, true, {}};
  const auto series = [](const std::vector<WalkPoint>& points, double WalkPoint::*member, std::string label, bool dashed) {
    Series line{std::move(label), {}, {}, dashed};
    for (const auto& point : points) {
      line.x.push_back(point.magnitude);
      line.y.push_back(point.*member);
    }
    return line;
  };
  plot.series.push_back(series(plain, &WalkPoint::float_error, "ref<float>", false));
  if (options.gpu_available) plot.series.push_back(series(plain, &WalkPoint::gpu_error, "GPU", false));
  plot.series.push_back(series(reduced, &WalkPoint::float_error, "ref<float>, origin reduced by a period", false));
  if (options.gpu_available) plot.series.push_back(series(reduced, &WalkPoint::gpu_error, "GPU, origin reduced", false));
  plot.series.push_back(series(plain, &WalkPoint::bound, "error model", true));
  plot.series.push_back(series(reduced, &WalkPoint::bound, "error model, origin reduced", true));
  attach_plot({plot}, options, "walk.png", "largest error vs double along the walk away from the origin",
              result);
}

PreparedTwin prepare_noise(NoiseBasis basis, Fractal fractal, const nlohmann::json& resolved, const Heightmap& input) {
  if (input.size() == 0) throw InputError("a noise case samples the grid of its input: give {\"generator\": \"flat\", ...}");
  check_grid_fits(input.width, input.height, 32, "noise grid");
  const NoiseParams params = noise_params_from_json(basis, fractal, resolved, input.width, input.height);
  GeneratedCase generated{.grid = input};
  FieldTwin& twin = generated.twin;
  twin.bounds = terrain_bounds(params);
  twin.reference_double = [params, input](const Grid<double>&) {
    return as_terrain(reference::noise_field<double>(params, params.sampling.origin), params, input);
  };
  twin.reference_float = [params, input](const Grid<float>&) {
    return as_terrain(reference::noise_field<float>(params, reduced_origin(params)), params, input);
  };
  twin.make_gpu = [params, input] {
    auto field = std::make_shared<gpu::NoiseField>(params);
    return GpuFieldRunner{[](const Grid<float>&) {}, [field] { field->run(); },
                          [field, params, input] { return as_terrain(field->result(), params, input); }};
  };
  PreparedTwin prepared{.kind = std::move(generated)};
  prepared.extra_checks = [params](const nlohmann::json& expect, const RunOptions& options, CaseResult& result) {
    add_distribution_checks(params, reference::noise_field<double>(params, params.sampling.origin), result);
    add_tile_period_check(params, result);
    add_gradient_check(params, result);
    add_lattice_gradient_check(params, result);
    add_octave_sum_check(params, result);
    add_cellular_check(params, result);
    if (!expect.is_object()) return;
    add_point_spec(params, expect, result);
    add_lattice_spec(params, expect, result);
    add_walk(params, expect, options, result);
  };
  return prepared;
}

struct NoiseAlgorithm {
  const char* name;
  NoiseBasis basis;
  Fractal fractal;
  const char* summary;
  const char* source;
};

constexpr NoiseAlgorithm noise_table[] = {
    {"noise.simplex2", NoiseBasis::simplex2, Fractal::none, "2-D simplex noise (kernel 0.5, scale 70)",
     "Gustavson 2005 via seed 004 §2.2.4"},
    {"noise.simplex3", NoiseBasis::simplex3, Fractal::none, "3-D simplex noise (kernel 0.6 or 0.5, scale 32)",
     "Gustavson 2005 / Eshelman via seed 004 §2.2.3"},
    {"noise.simplex4", NoiseBasis::simplex4, Fractal::none, "4-D simplex noise (kernel 0.6 or 0.5, scale 27)",
     "Gustavson 2005 via seed 004 §2.2.4"},
    {"noise.perlin3", NoiseBasis::perlin3, Fractal::none, "improved Perlin noise, 3-D", "Perlin 2002 via seed 002 §4.4.3"},
    {"noise.perlin3_texture", NoiseBasis::perlin3_texture, Fractal::none,
     "texture-based GLSL Perlin noise with its inexact gradient decode", "Gustavson 2004 via seed 004 §2.1"},
    {"noise.voronoi_f1", NoiseBasis::voronoi_f1, Fractal::none,
     "Voronoi F1: 2·(distance to the nearest feature point) − 1, one point per lattice cell",
     "Worley 1996 as Blender's VORONOI_F1 (seed 001 §3.18)"},
    {"noise.voronoi_f2", NoiseBasis::voronoi_f2, Fractal::none, "Voronoi F2: the second nearest feature point",
     "Worley 1996 as Blender's VORONOI_F2 (seed 001 §3.18)"},
    {"noise.voronoi_f3", NoiseBasis::voronoi_f3, Fractal::none, "Voronoi F3: the third nearest feature point",
     "Worley 1996 as Blender's VORONOI_F3 (seed 001 §3.18)"},
    {"noise.voronoi_f4", NoiseBasis::voronoi_f4, Fractal::none, "Voronoi F4: the fourth nearest feature point",
     "Worley 1996 as Blender's VORONOI_F4 (seed 001 §3.18)"},
    {"noise.voronoi_f2f1", NoiseBasis::voronoi_f2f1, Fractal::none, "Voronoi F2 − F1: the cells' borders",
     "Worley 1996 as Blender's VORONOI_F2F1 (seed 001 §3.18)"},
    {"noise.voronoi_crackle", NoiseBasis::voronoi_crackle, Fractal::none,
     "Voronoi crackle: min(1, 10·(F2 − F1)), thin dark cracks", "Blender's VORONOI_CRACKLE (seed 001 §3.18)"},
    {"noise.cell_noise", NoiseBasis::cell_noise, Fractal::none, "cell noise: one random value per lattice cell",
     "Blender's CELLNOISE (seed 001 §3.18)"},
    {"noise.fbm", NoiseBasis::perlin3, Fractal::fbm, "fractal Brownian motion, normalised by the sum of weights",
     "seed 002 §4.4.3 normalizedOctaveNoise3D; seed 004 §2.2.4"},
    {"noise.ridged", NoiseBasis::perlin3, Fractal::ridged, "Musgrave's ridged multifractal", "Musgrave 1994 (Blender)"},
    {"noise.hetero_terrain", NoiseBasis::perlin3, Fractal::hetero_terrain,
     "Musgrave's heterogeneous terrain as Blender implements it", "seed 001 §3.18"},
};

// The field's spec vectors plus what add_point_spec ("points"), add_lattice_spec and add_walk read.
nlohmann::json noise_spec_shape() {
  nlohmann::json shape = field_spec_shape();
  shape["points"] = nlohmann::json::array({nlohmann::json::array({"number"})});  // [[x, y, (z, (w,)) value], ...]
  shape["lattice_nonnegative"] = {{"size", "integer"}, {"count", "integer"}};
  shape["walk"] = {{"magnitudes", nlohmann::json::array({"number"})}, {"direction", nlohmann::json::array({"number", "number", "number"})}};
  return shape;
}

const ParamSpecs& specs_of(const NoiseAlgorithm& entry) {
  static std::map<std::string, ParamSpecs> specs;
  auto [position, inserted] = specs.try_emplace(entry.name);
  if (inserted) {
    position->second = entry.fractal == Fractal::none ? noise_param_specs(entry.basis) : fractal_param_specs(entry.fractal);
  }
  return position->second;
}

std::vector<Peer> noise_peers(const NoiseAlgorithm& entry) {
  std::vector<Peer> peers = glm_noise_peers(entry.basis, entry.fractal);
  for (Peer& peer : libnoise_peers(entry.basis, entry.fractal)) peers.push_back(std::move(peer));
  return peers;
}

}  // namespace

std::vector<Algorithm> noise_algorithms() {
  std::vector<Algorithm> list;
  for (const auto& entry : noise_table) {
    list.push_back({.name = entry.name,
                    .summary = entry.summary,
                    .source = entry.source,
                    .params = &specs_of(entry),
                    .prepare = [entry](const nlohmann::json& resolved, const LoadedInput& input) {
                      return prepare_noise(entry.basis, entry.fractal, resolved, input.heights);
                    },
                    .kind = CaseKind::generated,
                    .candidate = CandidateOutput::field,
                    // Counted in reference/noise/noise_field.cpp and gpu/noise/noise_field.cpp.
                    .traffic = {.cpu = 16.0, .gpu = 4.0},
                    .peers = noise_peers(entry),
                    .expect_shape = noise_spec_shape(),
                    // Measured 112 B a sample (noise.fbm, 1024² vs 256², both backends).
                    .memory = [](const nlohmann::json&, const LoadedInput& input) {
                      // terrain.* cases also describe their terrain (compare/case_descriptors.hpp)
                      return memory_for(static_cast<double>(input.heights.size()), "samples",
                                        150 + descriptor_bytes_per_cell);
                    }});
  }
  return list;
}

}  // namespace gt
