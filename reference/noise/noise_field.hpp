// A noise function or fractal sum sampled on a grid, CPU reference of gpu/noise/noise_field.cpp.
//
// noise_field<Real>(params, origin) -> Grid<Real> of params.sampling.width x height
//   sample (i, j) at origin + (i·step, j·step, 0, 0), each coordinate computed in Real as
//   Real(origin_c) + Real(i)·Real(step) (two roundings in float, as the shader does);
//   `origin` is params.sampling.origin or reduced_origin(params) (core/params/noise.hpp).
// Real = double is the truth; Real = float repeats the shader's arithmetic.
#pragma once

#include <array>
#include <optional>

#include "core/grid.hpp"
#include "core/params/noise.hpp"

namespace gt::reference {

template <class Real>
Grid<Real> noise_field(const NoiseParams& params, const std::array<double, 4>& origin);

// The function at one point, in double (spec vectors, error models).
double noise_at(const NoiseParams& params, const std::array<double, 4>& point);

// Its analytic gradient at one point, in double, for the functions that have one (simplex2,
// simplex3, perlin3 without a fractal sum); std::nullopt otherwise.
std::optional<std::array<double, 4>> noise_gradient_at(const NoiseParams& params, const std::array<double, 4>& point);

}  // namespace gt::reference
