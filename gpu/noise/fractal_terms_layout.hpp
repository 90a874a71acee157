// The layout of FractalTerms<float> (core/params/noise_fractal.hpp), the C++ mirror of the GLSL
// struct GtFractalTerms (gpu/shaders/noise/fractal.glsl), for the blocks that hold one as a struct
// member (noise_field.comp's NoiseFieldBlock, planet.glsl's PlanetBlock): checked against the
// linked program by GlProgram::check_block.
#pragma once

#include <cstddef>
#include <string>

#include "core/params/noise_fractal.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// The members of the block member `name` (a GtFractalTerms) whose mirror sits at `offset` in the
// block's C++ struct: "name.whole_octaves" .. "name.offset".
inline BlockLayout fractal_terms_layout(const std::string& name, std::size_t offset) {
  using Terms = FractalTerms<float>;
  return nested_layout(name + ".", offset,
                       {{"whole_octaves", offsetof(Terms, whole_octaves)},
                        {"remainder", offsetof(Terms, remainder)},
                        {"lacunarity", offsetof(Terms, lacunarity)},
                        {"gain", offsetof(Terms, gain)},
                        {"spectral_ratio", offsetof(Terms, spectral_ratio)},
                        {"fbm_normalisation", offsetof(Terms, fbm_normalisation)},
                        {"offset", offsetof(Terms, offset)}});
}

}  // namespace gt::gpu
