#version 450
// The seed's central-difference normals (seed 004 Listing 3.3, digest §2.8) at given vertices, in
// float: for each axis c, n_c = f(p + step·e_c) − f(p − step·e_c) with f the cave density
// gt_simplex3(q · world_to_noise, kernel_radius_squared), each shifted coordinate p_c ± step one
// float addition, each product one multiplication (precise: no contraction); then n / sqrt((n_x² +
// n_y²) + n_z²), the zero vector left as it is. Points along +∇f, from rock into air.
// Inputs:  CaveNormalsBlock (uniform binding 0), positions (binding 1: x, y, z per vertex, world
//          units), the permutation (binding 5, noise/permutation.glsl).
// Outputs: normals (binding 2: x, y, z per vertex, unit or zero).
// Twin:    reference/cave/normals.cpp central_difference_normals<float>.
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"
#include "noise/simplex.glsl"

layout(std140, binding = 0) uniform CaveNormalsBlock {
  uint vertex_count;
  float step;                   // ND in world units, float(step)
  float world_to_noise;         // float(1 / scale), rounded once on the host
  float kernel_radius_squared;  // simplex kernel r², rounded once on the host
};
layout(std430, binding = 1) readonly buffer Positions { float positions[]; };
layout(std430, binding = 2) writeonly buffer Normals { float normals[]; };

float density_at(vec3 world) {
  precise vec3 noise_point = world * world_to_noise;
  return gt_simplex3(noise_point, kernel_radius_squared);
}

void main() {
  uint vertex = linear_invocation();
  if (vertex >= vertex_count) return;
  vec3 p = vec3(positions[3u * vertex], positions[3u * vertex + 1u], positions[3u * vertex + 2u]);
  precise vec3 difference;
  for (int axis = 0; axis < 3; ++axis) {
    precise vec3 plus = p;
    precise vec3 minus = p;
    plus[axis] = p[axis] + step;
    minus[axis] = p[axis] - step;
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_GPU_NORMALS_FORWARD_DIFFERENCE
    minus = p;  // mutant cave.marching_tetrahedra.gpu_normals_forward_difference: f(p + h) − f(p)
#endif
    difference[axis] = density_at(plus) - density_at(minus);
  }
  precise float length = sqrt((difference.x * difference.x + difference.y * difference.y) +
                              difference.z * difference.z);
  vec3 normal = length == 0.0 ? difference : difference / length;
  normals[3u * vertex] = normal.x;
  normals[3u * vertex + 1u] = normal.y;
  normals[3u * vertex + 2u] = normal.z;
}
