// An exact CPU triangle rasterizer in double that follows OpenGL's rules (GL 4.5 core §13–14), CPU reference.
//
// The reference every rendering twin is compared against. Slow by design.
// rasterize(input, shade, target, settings = {})
// RasterTarget(width, height, channels, clear_colour = 0, clear_depth = 1): buffers cleared to
//   clear_colour (every channel) and clear_depth (clamped to [0, 1], as glClearDepth does).
//
// Pipeline and conventions, in GL's order:
//   1. Clipping: each triangle is clipped in homogeneous coordinates against the six planes
//      -w <= x, y, z <= w (Sutherland–Hodgman; attributes interpolated linearly in clip space, as
//      GL does), and the resulting convex polygon is drawn as a fan around its first corner. So a
//      perspective camera works (w > 0 after clipping against the near plane) and, for an
//      orthographic camera, depth clipping of z to [-1, 1] in NDC happens. Decision: GL drivers
//      clip x and y with a guard band instead; it changes nothing but sub-subpixel rounding.
//   2. Perspective division and the viewport transform of a viewport (0, 0, width, height) and
//      depth range [0, 1]: x_w = (x/w + 1)·width/2, y_w = (y/w + 1)·height/2, z_w = (z/w + 1)/2.
//      Row 0 of the buffers is the bottom (GL window y = 0); pixel (i, j) has its centre at
//      (i + 0.5, j + 0.5).
//   3. Coverage: window x, y are snapped to a grid of 2^-subpixel_bits pixels (GL_SUBPIXEL_BITS;
//      rounded to nearest, ties to even, as llvmpipe does), and the three edge functions are
//      evaluated at pixel centres in 64-bit integers, so coverage is exact. A pixel centre exactly
//      on an edge belongs to the triangle when that edge is a "left" edge (the interior lies at
//      +x) or, for a horizontal edge, when the interior lies at +y (tie_rule = lower_left) or -y
//      (upper_left). Either way an edge shared by two triangles draws its pixels exactly once. GL
//      leaves the choice to the implementation; lower_left is what Mesa's gallium drivers
//      (llvmpipe) do in framebuffer objects, whose row 0 is the bottom: D3D's top-left rule read
//      in memory-row order. Zero-area triangles (after snapping) draw nothing.
//   4. Interpolation uses the unsnapped window positions: barycentric weights λ at the pixel
//      centre, depth z_w = Σ λ_k z_k (linear in window space, as GL specifies for depth) clamped
//      to [0, 1], attributes a = Σ(λ_k a_k / w_k) / Σ(λ_k / w_k) (perspective-correct).
//   5. Depth test LESS (z_w < stored depth), then depth and colour are written. Triangles are
//      drawn in index order, so among equal depths the first triangle wins, as in GL.
//
// Inputs:  input.clip_positions  one homogeneous clip-space position per vertex: what the vertex shader
//                                writes to gl_Position (a camera matrix times the world position)
//          input.attributes      `attribute_count` doubles per vertex (the vertex shader's outputs)
//          input.triangles       three vertex indices each; both windings are drawn (no culling)
//          shade(attributes, colour)  the fragment shader: gets the perspective-correctly interpolated
//                                attributes, writes target.channels colour values
//          target                colour and depth buffers, read (depth test) and written
//          settings              subpixel_bits (GL_SUBPIXEL_BITS, 8 as llvmpipe and NVIDIA's drivers)
//                                and tie_rule
// Outputs: target's colour (channels per pixel, row-major, row 0 = bottom) and depth (window depth in
//          [0, 1]), written where fragments pass the depth test.
// Units:   clip coordinates in, window pixels and depth in [0, 1]; attributes as the caller gives them.
// Throws:  std::invalid_argument for buffer sizes outside [1, 16384], subpixel_bits outside [0, 16],
//          an index out of range or a wrong attribute count.
// Twin:    none: it stands for GL's own rasterization, which the GPU twins use (gpu/render/
//          offscreen_target.hpp); the rendering references draw through it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace gt::reference {

struct RasterTarget {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<double> colour;  // channels per pixel, row-major, row 0 = bottom
  std::vector<double> depth;   // window depth in [0, 1], one per pixel

  // Buffers cleared to clear_colour (every channel) and clear_depth (clamped to [0, 1], as
  // glClearDepth does).
  RasterTarget(int width, int height, int channels, double clear_colour = 0.0, double clear_depth = 1.0);

  std::size_t pixel(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
  double colour_at(int x, int y, int channel) const { return colour[pixel(x, y) * std::size_t(channels) + std::size_t(channel)]; }
  double depth_at(int x, int y) const { return depth[pixel(x, y)]; }
};

struct RasterInput {
  std::vector<std::array<double, 4>> clip_positions;
  int attribute_count = 0;
  std::vector<double> attributes;  // attribute_count per vertex
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

enum class TieRule { lower_left, upper_left };

struct RasterSettings {
  int subpixel_bits = 8;  // GL_SUBPIXEL_BITS of llvmpipe and of NVIDIA's drivers
  TieRule tie_rule = TieRule::lower_left;
};

using FragmentShader = std::function<void(std::span<const double> attributes, std::span<double> colour)>;

void rasterize(const RasterInput& input, const FragmentShader& shade, RasterTarget& target,
               const RasterSettings& settings = {});

}  // namespace gt::reference
