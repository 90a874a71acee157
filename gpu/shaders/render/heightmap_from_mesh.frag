#version 450 core
// Seed 000's heightmap from a mesh (digest 000_water_erosion.md §4.3), fragment stage: eq. 4.4,
// red = 1 - z' (top of the box 1, bottom 0). The depth test LESS has already kept the highest
// surface; uncovered texels keep the clear colour 0.
// Inputs:  z_prime from the vertex stage.
// Outputs: red (location 0) = 1 - z'.
// Twin:    reference/render/heightmap_from_mesh.cpp.

in float z_prime;

layout(location = 0) out float red;

void main() {
  red = 1.0 - z_prime;
#ifdef GT_MUTANT_RENDER_HEIGHTMAP_FROM_MESH_DRAW_ORDER_GPU
  gl_FragDepth = 0.0;  // mutant (this shader only): every fragment at depth 0, the first drawn stays
#endif
}
