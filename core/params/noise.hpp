// Parameters of the noise algorithms and how a grid of samples is laid out in noise space. Shared
// by the references (reference/noise/), the GPU sampling kernel (gpu/noise/noise_field.cpp) and the
// driver.
//
// Sampling: sample (i, j) of a width x height grid sits at origin + (i·step, j·step, 0, 0) in noise
// units (one lattice cell of the noise = 1 unit); 2-D functions read (x, y), 3-D (x, y, z), 4-D all.
// In float both twins compute each coordinate as origin_c + float(i)·step, rounded per operation.
//
// Large coordinates: float spacing grows with |origin| (2^-24·|x|), so far from the origin the
// float twins see coordinates that differ from the exact ones by up to u·|x|. The remedy
// `reduce_origin` moves the origin by a period of the noise before it is rounded to float: every
// lattice noise here hashes its cell with `& 255`, so a shift whose lattice (skewed, for simplex)
// coordinates are multiples of 256 changes nothing. The shift is computed in double on the host.
// Fractal sums stay periodic only when the lacunarity is an integer (then every octave's shift is a
// multiple of the period); otherwise reduction is refused.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "core/param_table.hpp"
#include "core/params/noise_fractal.hpp"

namespace gt {

// The cellular bases (voronoi_*, cell_noise) are Blender's (seed 001 §3.18), 3-D, and jump where a
// coordinate crosses a lattice plane (reference/noise/cellular.hpp).
enum class NoiseBasis {
  simplex2,
  simplex3,
  simplex4,
  perlin3,
  perlin3_texture,
  voronoi_f1,
  voronoi_f2,
  voronoi_f3,
  voronoi_f4,
  voronoi_f2f1,
  voronoi_crackle,
  cell_noise
};
enum class Fractal { none, fbm, ridged, hetero_terrain };

int noise_dimension(NoiseBasis basis);
const char* noise_basis_name(NoiseBasis basis);
bool is_cellular(NoiseBasis basis);

struct NoiseSampling {
  int width = 0;
  int height = 0;
  std::array<double, 4> origin{};  // noise-space position of sample (0, 0)
  double step = 0.05;              // noise units between neighbouring samples
};

struct NoiseParams {
  NoiseBasis basis = NoiseBasis::simplex3;
  Fractal fractal = Fractal::none;
  std::uint32_t seed = 0;               // 0: Perlin's reference permutation
  double kernel_radius_squared = 0.6;   // simplex 3-D/4-D: 0.6 (seed 004) or 0.5 (Gustavson's correction)
  bool reduce_origin = false;
  // Seed 001's wrapping noise (digest 001 §3.18, the code's InitTerrainObject): each sample is the
  // bilinear cross-blend of the function at p, p + N_x, p + N_y and p + N_x + N_y (N = the grid's
  // extent, width·step and height·step), weights c_x = i·(1/width), c_y = j·(1/height), so that the
  // field repeats with the grid's period.
  bool tileable = false;
  FractalParams fractal_params;         // fbm, ridged, hetero_terrain
  double amplitude = 1.0;               // terrain synthesis: height = base + amplitude·value (m),
  double base = 0.0;                    //   applied by the driver to both twins' outputs
  NoiseSampling sampling;
};

// The declarations (core/param_table.hpp) of a single function (fractal none: noise.simplex2 ...)
// or of a fractal sum (noise.fbm ..., whose basis is a parameter), and each variant's defaults: the
// struct's, but a single function sums one octave, a fractal sums perlin3, hetero_terrain takes 3
// octaves of lacunarity 3 and ridged a gain of 2 (Blender's).
ParamTable<NoiseParams> noise_param_table(NoiseBasis basis, Fractal fractal);
NoiseParams noise_defaults(NoiseBasis basis, Fractal fractal);

// Their ParamSpecs for the single-function algorithms and the fractal ones.
ParamSpecs noise_param_specs(NoiseBasis basis);
ParamSpecs fractal_param_specs(Fractal fractal);

// From resolved parameters and the sampling grid size. Throws InputError when reduce_origin is
// asked of a fractal with a non-integer lacunarity.
NoiseParams noise_params_from_json(NoiseBasis basis, Fractal fractal, const nlohmann::json& resolved, int width,
                                   int height);

// The origin moved by a period of the noise (see above); the identity when reduction is off.
std::array<double, 4> reduced_origin(const NoiseParams& params);

// Largest |coordinate| any sample of the grid reaches, in noise units.
double largest_coordinate(const NoiseParams& params);

// The largest |noise coordinate| either twin may be given: 2^27. Beyond it the lattice index
// int(floor(q + skew)) or the simplex sum of N such indices (a GLSL int, which wraps) overflows
// 32 bits (see check_lattice_range in noise.cpp).
constexpr double largest_lattice_coordinate = 134217728.0;

}  // namespace gt
