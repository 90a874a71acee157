// Texture-based classic Perlin noise of Gustavson 2004 (seed 004, digest 004 §2.1), CPU reference.
//
// The noise seed 004's fragment shader uses for its solid texture.
// perlin3_texture(rgba, x, y, z) -> what the 2004 shader returns for P = (x, y, z) when `rgba` is
//   bound with GL_NEAREST filtering and GL_REPEAT wrap. It is NOT improved Perlin noise with exact
//   gradients, and it is not perlin3 (another hash order and gradient table); see the hazards in
//   perlin_texture.cpp. With N_int the same lattice sum using the integer gradients,
//     N_tex = (256/255)·N_int + (1/255)·Σ_axis (t_axis − fade(t_axis))   (t = local coordinate),
//   so |N_tex − N_int| <= (1.5 + 3·0.14675)/255 < 0.0077 (|N_int| <= 1.5, |t − fade(t)| <= 0.14675).
// perlin_texture_gradient_component(byte) -> the gradient component the shader reads from a stored
//   byte: byte/255·4 − 1 (0, 64, 128 give −1, 1/255, 257/255 in exact arithmetic).
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  rgba: the texture bytes, core/noise/perlin_texture_table.hpp. Coordinates in lattice
//          units, |x|, |y|, |z| < 2^23 (beyond that floor(P)/256 + 0.5/256 is no longer a texel
//          centre in float); period 256.
// Outputs: the noise value at P.
// Units:   coordinates in lattice units; values dimensionless.
// Throws:  std::invalid_argument when rgba is not 256·256·4 bytes.
// Twin:    gpu/shaders/noise/perlin_texture.glsl; the texture on the GPU: gpu/noise/perlin_texture.hpp.
#pragma once

#include <cstdint>
#include <vector>

namespace gt::reference {

// The gradient component the shader reads from a stored byte: byte/255·4 − 1 (0, 64, 128 give −1,
// 1/255, 257/255 in exact arithmetic).
template <class Real>
Real perlin_texture_gradient_component(std::uint8_t byte);

template <class Real>
Real perlin3_texture(const std::vector<std::uint8_t>& rgba, Real x, Real y, Real z);

}  // namespace gt::reference
