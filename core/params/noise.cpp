// Parameter tables of the noise algorithms and the origin reduction and lattice range (see noise.hpp).
#include "core/params/noise.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

constexpr double period = 256.0;  // every noise here hashes lattice coordinates with & 255

// Skew and unskew factors of the simplex lattice in d dimensions: F = (sqrt(d+1) - 1)/d,
// G = (1 - 1/sqrt(d+1))/d (Gustavson 2005).
double skew_factor(int dimension) { return (std::sqrt(dimension + 1.0) - 1.0) / dimension; }
double unskew_factor(int dimension) { return (1.0 - 1.0 / std::sqrt(dimension + 1.0)) / dimension; }

bool is_simplex(NoiseBasis basis) {
  return basis == NoiseBasis::simplex2 || basis == NoiseBasis::simplex3 || basis == NoiseBasis::simplex4;
}

std::array<double, 4> reduced_simplex_origin(const std::array<double, 4>& origin, int dimension) {
  double sum = 0.0;
  for (int axis = 0; axis < dimension; ++axis) sum += origin[axis];
  const double skew = sum * skew_factor(dimension);
  std::array<double, 4> lattice_shift{};
  double shift_sum = 0.0;
  for (int axis = 0; axis < dimension; ++axis) {
    lattice_shift[axis] = period * std::floor((origin[axis] + skew) / period);
    shift_sum += lattice_shift[axis];
  }
  std::array<double, 4> reduced = origin;
  for (int axis = 0; axis < dimension; ++axis) {
    reduced[axis] -= lattice_shift[axis] - shift_sum * unskew_factor(dimension);
  }
  return reduced;
}

constexpr Choice<NoiseBasis> fractal_basis_choices[] = {
    {"perlin3", NoiseBasis::perlin3},           {"simplex3", NoiseBasis::simplex3},
    {"voronoi_f1", NoiseBasis::voronoi_f1},     {"voronoi_f2", NoiseBasis::voronoi_f2},
    {"voronoi_f3", NoiseBasis::voronoi_f3},     {"voronoi_f4", NoiseBasis::voronoi_f4},
    {"voronoi_f2f1", NoiseBasis::voronoi_f2f1}, {"voronoi_crackle", NoiseBasis::voronoi_crackle},
    {"cell_noise", NoiseBasis::cell_noise}};
constexpr const char* origin_names[] = {"origin_x", "origin_y", "origin_z", "origin_w"};

// Where the samples lie: the permutation, the step and the origin on each of `dimension` axes.
ParamTable<NoiseParams> sampling_rows(int dimension) {
  using P = NoiseParams;
  ParamTable<P> rows = {
      integer_param("seed", &P::seed, 0, 4294967295.0, "1",
                    "permutation: 0 = Perlin's reference table, otherwise a shuffle by the counter RNG"),
      nested(&P::sampling, real_param("step", &NoiseSampling::step, 1e-9, 1e6, "noise unit",
                                      "distance between neighbouring samples")),
      boolean_param("reduce_origin", &P::reduce_origin,
                    "move the origin by a period of the noise (in double) before the float twins see it"),
      boolean_param("tileable", &P::tileable,
                    "seed 001's wrapping noise: each sample the cross-blend of four, one grid extent apart, so the "
                    "field repeats with the grid's period"),
  };
  for (int axis = 0; axis < dimension; ++axis) {
    rows.push_back(nested(&P::sampling, real_param(origin_names[axis], element(&NoiseSampling::origin, axis), -1e9,
                                                   1e9, "noise unit", "noise-space position of sample (0, 0)")));
  }
  return rows;
}

// The octaves of a fractal sum: hetero_terrain has no gain, fbm no H and offset.
ParamTable<FractalParams> octave_rows(Fractal fractal) {
  using F = FractalParams;
  ParamTable<F> rows = {
      real_param("octaves", &F::octaves, 1.0, max_fractal_octaves, "count",
                 fractal == Fractal::ridged ? "octaves summed (whole part)"
                                            : "octaves summed; a fraction adds part of one more"),
      real_param("lacunarity", &F::lacunarity, 1e-3, 16.0, "1", "frequency ratio of successive octaves"),
  };
  if (fractal != Fractal::hetero_terrain) {
    rows.push_back(real_param("gain", &F::gain, 0.0, 16.0, "1",
                              fractal == Fractal::fbm ? "amplitude ratio of successive octaves"
                                                      : "weight feedback gain (Blender's ridged default 2)"));
  }
  if (fractal != Fractal::fbm) {
    rows.push_back(real_param("H", &F::H, 0.0, 4.0, "1", "fractal increment: octave k weighted lacunarity^(-H·k)"));
    rows.push_back(real_param("offset", &F::offset, -4.0, 4.0, "1", "added to the basis noise"));
  }
  return rows;
}

ParamTable<NoiseParams> fractal_rows(Fractal fractal) {
  using P = NoiseParams;
  ParamTable<P> rows = sampling_rows(3);
  rows.push_back(choice_param("basis", &P::basis, fractal_basis_choices, "", "the noise summed"));
  rows.push_back(real_param("kernel", &P::kernel_radius_squared, 0.5, 0.6, "noise unit²",
                            "kernel radius² of a simplex3 basis"));
  for (auto& row : nested(&P::fractal_params, octave_rows(fractal))) rows.push_back(std::move(row));
  rows.push_back(real_param("amplitude", &P::amplitude, -1e6, 1e6, "m",
                            "height = base + amplitude·value (terrain synthesis)"));
  rows.push_back(real_param("base", &P::base, -1e6, 1e6, "m", "height = base + amplitude·value"));
  return rows;
}

ParamTable<NoiseParams> function_rows(NoiseBasis basis) {
  ParamTable<NoiseParams> rows = sampling_rows(noise_dimension(basis));
  if (basis == NoiseBasis::simplex3 || basis == NoiseBasis::simplex4) {
    rows.push_back(real_param("kernel", &NoiseParams::kernel_radius_squared, 0.5, 0.6, "noise unit²",
                              "kernel radius²: 0.6 as seed 004 (slightly discontinuous), 0.5 corrected"));
  }
  return rows;
}

}  // namespace

int noise_dimension(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::simplex2: return 2;
    case NoiseBasis::simplex4: return 4;
    default: return 3;
  }
}

const char* noise_basis_name(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::simplex2: return "simplex2";
    case NoiseBasis::simplex3: return "simplex3";
    case NoiseBasis::simplex4: return "simplex4";
    case NoiseBasis::perlin3: return "perlin3";
    case NoiseBasis::perlin3_texture: return "perlin3_texture";
    case NoiseBasis::voronoi_f1: return "voronoi_f1";
    case NoiseBasis::voronoi_f2: return "voronoi_f2";
    case NoiseBasis::voronoi_f3: return "voronoi_f3";
    case NoiseBasis::voronoi_f4: return "voronoi_f4";
    case NoiseBasis::voronoi_f2f1: return "voronoi_f2f1";
    case NoiseBasis::voronoi_crackle: return "voronoi_crackle";
    case NoiseBasis::cell_noise: return "cell_noise";
  }
  return "?";
}

bool is_cellular(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::voronoi_f1:
    case NoiseBasis::voronoi_f2:
    case NoiseBasis::voronoi_f3:
    case NoiseBasis::voronoi_f4:
    case NoiseBasis::voronoi_f2f1:
    case NoiseBasis::voronoi_crackle:
    case NoiseBasis::cell_noise: return true;
    default: return false;
  }
}

ParamTable<NoiseParams> noise_param_table(NoiseBasis basis, Fractal fractal) {
  return fractal == Fractal::none ? function_rows(basis) : fractal_rows(fractal);
}

NoiseParams noise_defaults(NoiseBasis basis, Fractal fractal) {
  NoiseParams defaults;
  defaults.basis = fractal == Fractal::none ? basis : NoiseBasis::perlin3;
  defaults.fractal = fractal;
  auto& octaves = defaults.fractal_params;
  if (fractal == Fractal::none) octaves.octaves = 1.0;
  if (fractal == Fractal::hetero_terrain) octaves.octaves = octaves.lacunarity = 3.0;
  if (fractal == Fractal::ridged) octaves.gain = 2.0;
  return defaults;
}

ParamSpecs noise_param_specs(NoiseBasis basis) {
  return param_specs(noise_param_table(basis, Fractal::none), noise_defaults(basis, Fractal::none));
}

ParamSpecs fractal_param_specs(Fractal fractal) {
  return param_specs(noise_param_table(NoiseBasis::perlin3, fractal), noise_defaults(NoiseBasis::perlin3, fractal));
}

namespace {

// Both twins find a sample's lattice cell as int(floor(q + skew)), the skew being F·Σq (at most
// 4·0.309·max|q| in 4-D, F4 = (√5 − 1)/4): beyond 2^31 that conversion is undefined in C++ and in
// GLSL. The simplex bases then sum the N cell indices in a GLSL int, which wraps: N·(1 + N·F)·max|q|
// ≤ 8.95·max|q| must stay below 2^31, so max|q| ≤ 2^27. The finest octave samples the largest
// coordinates, p·lacunarity^(n−1) for n = ceil(octaves) octaves (a fraction adds part of one more).
void check_lattice_range(const NoiseParams& params) {
  const double lacunarity = params.fractal_params.lacunarity;
  const double finest_power = params.fractal == Fractal::none ? 0.0 : std::ceil(params.fractal_params.octaves) - 1.0;
  const double growth = lacunarity > 1.0 ? std::pow(lacunarity, finest_power) : 1.0;
  const double largest = largest_coordinate(params) * growth;
  if (!(largest <= largest_lattice_coordinate)) {
    throw InputError(fmt::format("noise coordinates reach {:.3g} (largest |origin + extent| {:.3g} x lacunarity^{} = "
                                 "{:.3g} at the finest octave), beyond 2^27: the lattice indices int(floor(q)) and their "
                                 "sum would overflow 32 bits (undefined in C++ and in GLSL); lower the origin, step, octaves "
                                 "or lacunarity",
                                 largest, largest_coordinate(params), finest_power, growth));
  }
}

}  // namespace

NoiseParams noise_params_from_json(NoiseBasis basis, Fractal fractal, const nlohmann::json& resolved, int width,
                                   int height) {
  NoiseParams params = params_from_json(noise_param_table(basis, fractal), resolved, noise_defaults(basis, fractal));
  params.sampling.width = width;
  params.sampling.height = height;
  const double lacunarity = params.fractal_params.lacunarity;
  if (params.reduce_origin && fractal != Fractal::none && lacunarity != std::floor(lacunarity)) {
    throw InputError(fmt::format("reduce_origin needs an integer lacunarity (got {}): only then is every octave "
                                 "periodic with the same shift",
                                 lacunarity));
  }
  check_lattice_range(params);
  return params;
}

std::array<double, 4> reduced_origin(const NoiseParams& params) {
  const auto& origin = params.sampling.origin;
  if (!params.reduce_origin) return origin;
  if (is_simplex(params.basis)) return reduced_simplex_origin(origin, noise_dimension(params.basis));
  std::array<double, 4> reduced = origin;
  for (double& coordinate : reduced) coordinate -= period * std::floor(coordinate / period);
  return reduced;
}

double largest_coordinate(const NoiseParams& params) {
  const auto& sampling = params.sampling;
  double largest = 0.0;
  for (int axis = 0; axis < noise_dimension(params.basis); ++axis) {
    // A tileable field also samples one grid extent further along x and y.
    const int copies = params.tileable ? 2 : 1;
    const double extent = axis == 0 ? (copies * sampling.width - 1) * sampling.step
                          : axis == 1 ? (copies * sampling.height - 1) * sampling.step
                                      : 0.0;
    largest = std::max({largest, std::abs(sampling.origin[axis]), std::abs(sampling.origin[axis] + extent)});
  }
  return largest;
}

}  // namespace gt
