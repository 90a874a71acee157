// The parameter block of the GPU marching tetrahedra (gpu/cave/marching_tetrahedra.cpp mirrors it
// as CaveBlock, std140 offsets checked there) and the addressing of samples and cubes, as
// reference/cave/lattice_cubes.hpp states them.
//
// Samples: local (x, y, z) in 0..sample_counts - 1, index (z·ny + y)·nx + x (core/volume.hpp);
// global lattice point lattice_origin + local (world units, spacing 1).
// Cubes: named by their lower corner in local sample coordinates, first_cube .. first_cube +
// cube_counts - 1 per axis (solid: first -1, count samples + 1; open: first 0, count samples - 1),
// index x fastest, then y, then z: the reference's output order.
// Guarded: several cave programs include it.
// Inputs:  declares CaveBlock (uniform binding 0).
// Outputs: sample and cube addressing for the cave passes.
// Twin:    reference/cave/lattice_cubes.hpp; host: gpu/cave/marching_tetrahedra.cpp.
#ifndef GT_CAVE_BLOCK_GLSL
#define GT_CAVE_BLOCK_GLSL

layout(std140, binding = 0) uniform CaveBlock {
  ivec4 lattice_origin;          // xyz: global lattice point of sample (0, 0, 0); w unused
  ivec4 sample_counts;           // xyz: samples per axis; w: all samples
  ivec4 cube_counts;             // xyz: cubes per axis; w: all cubes
  int first_cube;                // -1 solid (air pad), 0 open
  float threshold;               // rock iff density < threshold (float(CaveParams::threshold))
  float world_to_noise;          // float(1 / scale), rounded once on the host (reference/cave/density.hpp)
  float kernel_radius_squared;   // simplex kernel r², rounded once on the host
  uint linear_placement;         // 1: t = (threshold - v_a) / (v_b - v_a); 0: midpoints
};

ivec3 sample_of(uint index) {
  uvec3 counts = uvec3(sample_counts.xyz);
  return ivec3(index % counts.x, (index / counts.x) % counts.y, index / (counts.x * counts.y));
}

uint sample_index(ivec3 point) {
  uvec3 counts = uvec3(sample_counts.xyz);
  return (uint(point.z) * counts.y + uint(point.y)) * counts.x + uint(point.x);
}

ivec3 cube_of(uint index) {
  uvec3 counts = uvec3(cube_counts.xyz);
  return ivec3(index % counts.x, (index / counts.x) % counts.y, index / (counts.x * counts.y)) + ivec3(first_cube);
}

uint cube_index(ivec3 cube) {
  uvec3 counts = uvec3(cube_counts.xyz);
  uvec3 local = uvec3(cube - ivec3(first_cube));
  return (local.z * counts.y + local.y) * counts.x + local.x;
}

#endif
