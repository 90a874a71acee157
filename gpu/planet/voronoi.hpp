// The spherical Voronoi of seed 002's region centroids on the GPU (digest 002 §2.8, Algorithm 1), GPU twin.
//
// For each query direction, the nearest centroid among the 3×3 (rings = 1, the seed's shader) or 5×5
// (rings = 2, its thesis) block of cells around the cell holding the direction, through the cube
// sphere's neighbour table. Shader: gpu/shaders/planet/voronoi.comp.
// PlanetVoronoi(sphere, rings, cube_warp) compiles the pass and uploads the neighbour table; the cell
//   of a direction is found through the inverse of the warp the centroids were placed with.
// labels(positions, directions) uploads positions and directions and returns one region per direction.
// voronoi_block(resolution, direction_count, cube_warp) -> the std140 block of
//   planet/voronoi_search.glsl (binding 0): the face matrices, R, the warp's θ and tan θ rounded to
//   float once (θ = 0: no warp), and the number of queries
//   (voronoi.comp's; 0 for the renderer).
// check_voronoi_block(program): checks a program's VoronoiBlock (voronoi.comp's, the renderer's)
//   against voronoi_block's C++ mirror.
// padded_xyz(xyz): x, y, z per item -> x, y, z, 0 per item: std430 vec4s, as the shaders read positions.
//
// Inputs:  sphere, rings; positions (3 per region, unit length), directions (unit length). Needs a
//          current GlContext.
// Outputs: one region per direction.
// Units:   positions and directions dimensionless (unit sphere).
// Throws:  std::invalid_argument for rings outside 1..2 or positions of the wrong size;
//          std::runtime_error (GlProgram::check_block) on a block mismatch and when the shader does not
//          compile or link.
// Twin:    reference/planet/voronoi.hpp (exact, by k-d tree).
#pragma once

#include <cstdint>
#include <vector>

#include "core/planet/cube_sphere.hpp"
#include "core/planet/planet_state.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// The std140 block of planet/voronoi_search.glsl (binding 0): the face matrices, R, the warp's θ and
// tan θ rounded to float once, and the number of queries (voronoi.comp's; 0 for the renderer).
UniformBuffer voronoi_block(int resolution, std::size_t direction_count, CubeWarp cube_warp);
// Checks a program's VoronoiBlock (voronoi.comp's, the renderer's) against voronoi_block's C++
// mirror (GlProgram::check_block: std::runtime_error on a mismatch).
void check_voronoi_block(const GlProgram& program);

// x, y, z per item -> x, y, z, 0 per item: std430 vec4s, as the shaders read positions.
std::vector<float> padded_xyz(const std::vector<float>& xyz);

class PlanetVoronoi {
 public:
  PlanetVoronoi(const CubeSphere& sphere, int rings, CubeWarp cube_warp = {});
  std::vector<std::int32_t> labels(const std::vector<float>& positions, const std::vector<Vector3<float>>& directions);

 private:
  int resolution_;
  CubeWarp warp_;
  std::size_t region_count_;
  ComputeProgram program_;
  StorageBuffer neighbours_;
};

}  // namespace gt::gpu
