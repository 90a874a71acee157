// Sampling a noise function or fractal sum on a grid; see noise_field.hpp. The dispatch on
// NoiseBasis and Fractal is here; the functions are in simplex.cpp, perlin.cpp, perlin_texture.cpp,
// cellular.cpp and fractal.hpp.
//
// Memory traffic per sample (ref<double>, the performance table's floor column): 16 B written
// (the grid's zero fill and the value), nothing read but the permutation tables.
#include "reference/noise/noise_field.hpp"

#include <type_traits>
#include <vector>

#include "core/mutant.hpp"
#include "core/noise/perlin_texture_table.hpp"
#include "core/noise/permutation.hpp"
#include "reference/noise/cellular.hpp"
#include "reference/noise/fractal.hpp"
#include "reference/noise/perlin.hpp"
#include "reference/noise/perlin_texture.hpp"
#include "reference/noise/simplex.hpp"

namespace gt::reference {
namespace {

// One function of a point, bound to its tables, in precision Real.
template <class Real>
class Evaluator {
 public:
  explicit Evaluator(const NoiseParams& params)
      : params_(params),
        permutation_(seeded_permutation(params.seed)),
        kernel_(static_cast<Real>(params.kernel_radius_squared)),
        terms_(fractal_terms<Real>(params.fractal_params)) {
    if (params.basis == NoiseBasis::perlin3_texture) texture_ = perlin_texture_rgba(permutation_);
  }

  Real operator()(const std::array<Real, 4>& p) const {
    const auto basis = [this](Real x, Real y, Real z) { return basis3(x, y, z); };
    switch (params_.fractal) {
      case Fractal::fbm: return fbm(basis, terms_, p[0], p[1], p[2]);
      case Fractal::ridged: return ridged_multifractal(basis, terms_, p[0], p[1], p[2]);
      case Fractal::hetero_terrain: return hetero_terrain(basis, terms_, p[0], p[1], p[2]);
      case Fractal::none: break;
    }
    switch (params_.basis) {
      case NoiseBasis::simplex2: return simplex2(permutation_, p[0], p[1]);
      case NoiseBasis::simplex4: return simplex4(permutation_, p[0], p[1], p[2], p[3], kernel_);
      default: return basis3(p[0], p[1], p[2]);
    }
  }

  std::optional<std::array<Real, 4>> gradient(const std::array<Real, 4>& p) const {
    if (params_.fractal != Fractal::none) return std::nullopt;
    switch (params_.basis) {
      case NoiseBasis::simplex2: {
        const auto value_and_gradient = simplex2_gradient(permutation_, p[0], p[1]);
        return std::array<Real, 4>{value_and_gradient[0], value_and_gradient[1], value_and_gradient[2], Real(0)};
      }
      case NoiseBasis::simplex3: return simplex3_gradient(permutation_, p[0], p[1], p[2], kernel_);
      case NoiseBasis::perlin3: return perlin3_gradient(permutation_, p[0], p[1], p[2]);
      default: return std::nullopt;
    }
  }

 private:
  // The 3-D functions a fractal sum can use as its basis.
  Real basis3(Real x, Real y, Real z) const {
    switch (params_.basis) {
      case NoiseBasis::simplex3: return simplex3(permutation_, x, y, z, kernel_);
      case NoiseBasis::perlin3_texture: return perlin3_texture(texture_, x, y, z);
      case NoiseBasis::perlin3: return perlin3(permutation_, x, y, z);
      default: return cellular(permutation_, params_.basis, x, y, z);
    }
  }

  NoiseParams params_;
  Permutation permutation_;
  Real kernel_;
  FractalTerms<Real> terms_;
  std::vector<std::uint8_t> texture_;
};

}  // namespace

// A sample as stored. Mutants (the GPU twin makes the same changes, gpu/shaders/noise/noise_field.comp):
// the calibrated pair of the float precision model, the float samples 2^-13 (above the bound) or
// 2^-17 (below) high; and in both twins the texture convention v/2 + 1/2 instead of v.
template <class Real>
Real stored_sample(Real value) {
  if constexpr (std::is_same_v<Real, float>) {
    if (mutant_active("noise.perlin3.float_off_above_bound")) return value + 0x1p-13f;
    if (mutant_active("noise.perlin3.float_off_below_bound")) return value + 0x1p-17f;
  }
  if (mutant_active("noise.perlin3.unit_interval")) return value * Real(0.5) + Real(0.5);
  return value;
}

// The point of sample (i, j): origin + (i·step, j·step), each coordinate rounded twice in Real.
template <class Real>
std::array<Real, 4> sample_point(const std::array<Real, 4>& start, Real step, int i, int j) {
  std::array<Real, 4> point = start;
  point[0] = start[0] + static_cast<Real>(i) * step;
  point[1] = start[1] + static_cast<Real>(j) * step;
  return point;
}

// Sample (i, j), any i and j (the tile's period check reads one grid past the edge). Tileable: seed
// 001's cross-blend c_y·(c_x·n(i, j) + (1 − c_x)·n(i + W, j)) + (1 − c_y)·(c_x·n(i, j + H) +
// (1 − c_x)·n(i + W, j + H)), the shifted points formed like any sample's, c_x = i·(1/W) with 1/W
// rounded once from double (both twins multiply: no division). Mutant noise.hetero_terrain.tile_weights_mirrored
// (both twins): c_x and 1 − c_x exchanged, so the blend no longer wraps.
template <class Real>
Real sample_at(const Evaluator<Real>& evaluate, const NoiseParams& params, const std::array<Real, 4>& start, Real step,
               int i, int j) {
  if (!params.tileable) return evaluate(sample_point(start, step, i, j));
  const int width = params.sampling.width, height = params.sampling.height;
  const Real near_x = static_cast<Real>(i) * static_cast<Real>(1.0 / width);
  const Real near_y = static_cast<Real>(j) * static_cast<Real>(1.0 / height);
  const bool mirrored = mutant_active("noise.hetero_terrain.tile_weights_mirrored");
  const Real weight_x = mirrored ? Real(1) - near_x : near_x;
  const Real other_x = mirrored ? near_x : Real(1) - near_x;
  const Real here = weight_x * evaluate(sample_point(start, step, i, j)) +
                    other_x * evaluate(sample_point(start, step, i + width, j));
  const Real above = weight_x * evaluate(sample_point(start, step, i, j + height)) +
                     other_x * evaluate(sample_point(start, step, i + width, j + height));
  return near_y * here + (Real(1) - near_y) * above;
}

template <class Real>
std::array<Real, 4> rounded_origin(const std::array<double, 4>& origin) {
  std::array<Real, 4> start{};
  for (int axis = 0; axis < 4; ++axis) start[axis] = static_cast<Real>(origin[axis]);
  return start;
}

template <class Real>
Grid<Real> noise_field(const NoiseParams& params, const std::array<double, 4>& origin) {
  const auto& sampling = params.sampling;
  const Evaluator<Real> evaluate(params);
  const Real step = static_cast<Real>(sampling.step);
  const std::array<Real, 4> start = rounded_origin<Real>(origin);
  Grid<Real> field(sampling.width, sampling.height);
  for (int j = 0; j < sampling.height; ++j) {
    for (int i = 0; i < sampling.width; ++i) field.at(i, j) = stored_sample(sample_at(evaluate, params, start, step, i, j));
  }
  return field;
}

std::vector<double> noise_samples_at(const NoiseParams& params, const std::array<double, 4>& origin,
                                     const std::vector<std::array<int, 2>>& cells) {
  const Evaluator<double> evaluate(params);
  const std::array<double, 4> start = rounded_origin<double>(origin);
  std::vector<double> samples;
  samples.reserve(cells.size());
  for (const auto& [i, j] : cells) samples.push_back(sample_at(evaluate, params, start, params.sampling.step, i, j));
  return samples;
}

double noise_at(const NoiseParams& params, const std::array<double, 4>& point) {
  return Evaluator<double>(params)(point);
}

std::optional<std::array<double, 4>> noise_gradient_at(const NoiseParams& params, const std::array<double, 4>& point) {
  return Evaluator<double>(params).gradient(point);
}

template Grid<float> noise_field(const NoiseParams&, const std::array<double, 4>&);
template Grid<double> noise_field(const NoiseParams&, const std::array<double, 4>&);

}  // namespace gt::reference
