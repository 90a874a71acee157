// Host side of the GPU noise sampler: the defines that pick the function, the std140 parameter
// block, the permutation buffer and (for perlin3_texture) the texture. See noise_field.hpp.
//
// Memory traffic per sample (the performance table's floor column): one dispatch writing 4 B
// (the float value), nothing read but the permutation buffer or texture.
#include "gpu/noise/noise_field.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/noise/permutation.hpp"
#include "core/params/noise_fractal.hpp"
#include "gpu/noise/fractal_terms_layout.hpp"

namespace gt::gpu {
namespace {

// Mirror of `NoiseFieldBlock` in gpu/shaders/noise/noise_field.comp (std140). The fractal terms
// are a struct member: std140 aligns it to 16 bytes.
struct NoiseFieldBlock {
  float origin[4];
  std::int32_t grid_size[2];
  float step;
  float kernel_radius_squared;
  FractalTerms<float> fractal_terms;
  float padding;
};

constexpr int local_size = 16;  // local_size_x/y of noise_field.comp
constexpr GLuint block_binding = 0, values_binding = 1, permutation_binding = 5;

// gt_voronoi's feature number (gpu/shaders/noise/cellular.glsl): 1..4 for F_k, 5 for F2 − F1,
// 6 for crackle.
int voronoi_feature(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::voronoi_f2: return 2;
    case NoiseBasis::voronoi_f3: return 3;
    case NoiseBasis::voronoi_f4: return 4;
    case NoiseBasis::voronoi_f2f1: return 5;
    case NoiseBasis::voronoi_crackle: return 6;
    default: return 1;
  }
}

// The GLSL expression of the basis at a vec3 q. The kernel is a literal of the float the
// reference uses (9 significant digits round-trip a float): fractal.glsl, which calls the basis,
// comes before the parameter block.
std::string basis_call(const NoiseParams& params, const std::string& q) {
  switch (params.basis) {
    case NoiseBasis::simplex3:
      return fmt::format("gt_simplex3({}, {:.9g})", q, static_cast<float>(params.kernel_radius_squared));
    case NoiseBasis::perlin3_texture: return "gt_perlin3_texture(" + q + ")";
    case NoiseBasis::perlin3: return "gt_perlin3(" + q + ")";
    case NoiseBasis::cell_noise: return "gt_cell_noise(" + q + ")";
    default: return fmt::format("gt_voronoi({}, {})", q, voronoi_feature(params.basis));
  }
}

// TILEABLE and the tile's weights per sample, 1/width and 1/height rounded once from double as the
// reference rounds them (printed to 9 digits: the same float).
std::vector<std::string> tile_defines(const NoiseParams& params) {
  if (!params.tileable) return {};
  return {"TILEABLE",
          fmt::format("TILE_INVERSE_WIDTH={:.9g}", static_cast<float>(1.0 / params.sampling.width)),
          fmt::format("TILE_INVERSE_HEIGHT={:.9g}", static_cast<float>(1.0 / params.sampling.height))};
}

std::vector<std::string> function_defines(const NoiseParams& params) {
  switch (params.fractal) {
    case Fractal::fbm: return {"FRACTAL_BASIS(q)=" + basis_call(params, "q"), "NOISE_VALUE(p)=gt_fbm(p.xyz, fractal_terms)"};
    case Fractal::ridged:
      return {"FRACTAL_BASIS(q)=" + basis_call(params, "q"),
              "NOISE_VALUE(p)=gt_ridged_multifractal(p.xyz, fractal_terms)"};
    case Fractal::hetero_terrain:
      return {"FRACTAL_BASIS(q)=" + basis_call(params, "q"),
              "NOISE_VALUE(p)=gt_hetero_terrain(p.xyz, fractal_terms)"};
    case Fractal::none: break;
  }
  switch (params.basis) {
    case NoiseBasis::simplex2: return {"NOISE_VALUE(p)=gt_simplex2(p.xy)"};
    case NoiseBasis::simplex4: return {"NOISE_VALUE(p)=gt_simplex4(p, kernel_radius_squared)"};
    default: return {"NOISE_VALUE(p)=" + basis_call(params, "p.xyz")};
  }
}

// noise_field.comp for `params`, its NoiseFieldBlock checked against the mirror. Without a fractal
// the GLSL block has no fractal_terms and ends where they would begin.
ComputeProgram noise_field_program(const NoiseParams& params) {
  std::vector<std::string> defines = function_defines(params);
  for (auto& define : tile_defines(params)) defines.push_back(std::move(define));
  ComputeProgram program = ComputeProgram::load("noise/noise_field.comp", defines);
  BlockLayout layout = {{"origin", offsetof(NoiseFieldBlock, origin)},
                        {"grid_size", offsetof(NoiseFieldBlock, grid_size)},
                        {"step", offsetof(NoiseFieldBlock, step)},
                        {"kernel_radius_squared", offsetof(NoiseFieldBlock, kernel_radius_squared)}};
  const bool fractal = params.fractal != Fractal::none;
  if (fractal) {
    const auto terms = fractal_terms_layout("fractal_terms", offsetof(NoiseFieldBlock, fractal_terms));
    layout.insert(layout.end(), terms.begin(), terms.end());
  }
  program.check_block("NoiseFieldBlock", fractal ? sizeof(NoiseFieldBlock) : offsetof(NoiseFieldBlock, fractal_terms),
                      layout);
  return program;
}

UniformBuffer block_buffer(const NoiseParams& params) {
  NoiseFieldBlock block{};
  const auto origin = reduced_origin(params);
  for (int axis = 0; axis < 4; ++axis) block.origin[axis] = static_cast<float>(origin[axis]);
  block.grid_size[0] = params.sampling.width;
  block.grid_size[1] = params.sampling.height;
  block.step = static_cast<float>(params.sampling.step);
  block.kernel_radius_squared = static_cast<float>(params.kernel_radius_squared);
  block.fractal_terms = fractal_terms<float>(params.fractal_params);
  return UniformBuffer::from(block);
}

}  // namespace

NoiseField::NoiseField(const NoiseParams& params)
    : sampling_(params.sampling),
      program_(noise_field_program(params)),
      block_(block_buffer(params)),
      permutation_(StorageBuffer::from(doubled_permutation(seeded_permutation(params.seed)))),
      values_(static_cast<std::size_t>(params.sampling.width) * params.sampling.height * sizeof(float)) {
  if (params.basis == NoiseBasis::perlin3_texture) {
    texture_ = std::make_unique<PerlinTexture>(seeded_permutation(params.seed));
  }
}

void NoiseField::run() {
  block_.bind(block_binding);
  values_.bind(values_binding);
  permutation_.bind(permutation_binding);
  if (texture_) texture_->bind(perlin_texture_unit);
  program_.dispatch(sampling_.width, sampling_.height, local_size, local_size);
}

Grid<float> NoiseField::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  Grid<float> field(sampling_.width, sampling_.height);
  field.values = values_.download<float>(field.size());
  return field;
}

}  // namespace gt::gpu
