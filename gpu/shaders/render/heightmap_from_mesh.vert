#version 450 core
// Seed 000's heightmap from a mesh (digest 000_water_erosion.md §4.3), vertex stage: eq. 4.2.
// `projection` is M·T(c): the host subtracts the bounding-box centre c from every position in
// double before rounding it to float (so a mesh far from the origin keeps its precision), and M's
// translation column then reduces to (0, 0, 0.5). It is set with transpose = GL_TRUE from a
// row-major array, so projection * v is the seed's `v * M` with M row-major.
// z' = 0.5 - s_z·(z - c_z) ∈ [0, 1] (top 0) goes to the fragment stage as well as into depth.
// Inputs:  centred_position (location 0), projection (uniform location 0).
// Outputs: gl_Position; z_prime.
// Twin:    reference/render/heightmap_from_mesh.cpp.

layout(location = 0) in vec3 centred_position;
layout(location = 0) uniform mat4 projection;

out float z_prime;

void main() {
  gl_Position = projection * vec4(centred_position, 1.0);
  z_prime = gl_Position.z;
  // Mutants (both twins; the reference's in reference/render/heightmap_from_mesh.cpp):
#ifdef GT_MUTANT_RENDER_HEIGHTMAP_FROM_MESH_LOWEST_SURFACE
  gl_Position.z = 1.0 - z_prime;  // the box seen from below: the lowest surface wins the depth test
#endif
#ifdef GT_MUTANT_RENDER_HEIGHTMAP_FROM_MESH_ROWS_FLIPPED
  gl_Position.y = -gl_Position.y;  // north and south swapped
#endif
}
