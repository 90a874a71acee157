// A noise function or fractal sum sampled on a grid (every function of core/params/noise.hpp), CPU reference.
//
// noise_field<Real>(params, origin) -> Grid<Real> of params.sampling.width x height
//   sample (i, j) at origin + (i·step, j·step, 0, 0), each coordinate computed in Real as
//   Real(origin_c) + Real(i)·Real(step) (two roundings in float, as the shader does).
//   Tileable (params.tileable): seed 001's cross-blend of the samples at (i, j), (i + W, j),
//   (i, j + H), (i + W, j + H) with weights c_x = i·(1/W), c_y = j·(1/H) (digest 001 §3.18).
// noise_samples_at(params, origin, cells) -> samples (i, j) in double, for any i, j.
// noise_at(params, point) -> the function at one point, in double (spec vectors, error models).
// noise_gradient_at(params, point) -> its analytic gradient at one point, in double, for the functions
//   that have one (simplex2, simplex3, perlin3 without a fractal sum); std::nullopt otherwise.
// Real = double is the truth; Real = float repeats the shader's arithmetic.
//
// Inputs:  params (NoiseParams: basis, fractal sum, seed, sampling grid); `origin` is
//          params.sampling.origin or reduced_origin(params) (core/params/noise.hpp).
// Outputs: the grid of values (row j, column i); a value; a gradient.
// Units:   coordinates in noise units (one lattice cell = 1); values dimensionless.
// Throws:  std::invalid_argument from fractal_terms for fractal octaves outside [1, 32], lacunarity <= 0
//          or gain < 0.
// Twin:    gpu/noise/noise_field.hpp (NoiseField) with gpu/shaders/noise/noise_field.comp.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/grid.hpp"
#include "core/params/noise.hpp"

namespace gt::reference {

template <class Real>
Grid<Real> noise_field(const NoiseParams& params, const std::array<double, 4>& origin);

// Samples (i, j) as noise_field<double> gives them (tiled where params.tileable), for any i and j:
// the tile's period check reads one grid extent past the edge.
std::vector<double> noise_samples_at(const NoiseParams& params, const std::array<double, 4>& origin,
                                     const std::vector<std::array<int, 2>>& cells);

// The function at one point, in double (spec vectors, error models).
double noise_at(const NoiseParams& params, const std::array<double, 4>& point);

// Its analytic gradient at one point, in double, for the functions that have one (simplex2,
// simplex3, perlin3 without a fractal sum); std::nullopt otherwise.
std::optional<std::array<double, 4>> noise_gradient_at(const NoiseParams& params, const std::array<double, 4>& point);

}  // namespace gt::reference
