// The planet drawn as the seed's demo draws it (digest 002 §4.3, §9.3 steps 10–11), CPU reference.
//
// The cube-sphere mesh through a perspective camera, each fragment coloured by the region whose
// centroid is nearest its direction (the spherical Voronoi per pixel) in the elevation palette.
// Rasterized by the reference rasterizer (GL's rules, reference/render/rasterizer.hpp); the nearest
// centroid exactly, by reference/planet/voronoi.hpp.
// elevation_colour(e) -> §4.3's palette: base (107, 193, 255)/255 below sea level (e < 0), else
//   (255, 189, 97)/255, times 1 − |e|/4 clamped to [0, 1] (the code wraps as unsigned beyond |e| = 4:
//   clamped here).
// render_planet(mesh, camera, positions, elevation, subpixel_bits) -> the image (RGB8, rows top
//   first) and per pixel the region drawn (−1 where no triangle covers it), rows top first.
// The fragment's direction is its perspective-correctly interpolated world position, normalised.
//
// Inputs:  mesh (the cube sphere's), camera (reference/render/phong.hpp), positions 3 per region
//          (unit length), elevation 1 per region, subpixel_bits (GL_SUBPIXEL_BITS to match).
// Outputs: PlanetImage: Rgb8Image (with covered_pixels) and the region per pixel.
// Units:   elevations in generator units; colours in [0, 1] before quantising to 8 bits.
// Throws:  std::invalid_argument from the rasterizer: image sides outside [1, 16384], subpixel_bits
//          outside [0, 16], a triangle index out of range.
// Twin:    gpu/planet/render.hpp (PlanetRenderer) with gpu/shaders/planet/render.{vert,frag} and
//          voronoi_search.glsl.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.hpp"
#include "reference/render/phong.hpp"

namespace gt::reference {

Vec3 elevation_colour(double elevation);

struct PlanetImage {
  Rgb8Image image;
  std::vector<std::int32_t> regions;  // per pixel, rows top first; −1 uncovered
};

PlanetImage render_planet(const Mesh& mesh, const Camera& camera, const std::vector<double>& positions,
                          const std::vector<double>& elevation, int subpixel_bits = 8);

}  // namespace gt::reference
