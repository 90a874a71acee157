#version 450
// Pass 4 of the GPU marching tetrahedra: every cube writes its triangles at its offset (the
// exclusive scan of the triangle counts) in the reference's order, and the vertices it owns in
// order of first use: position (three floats, cave/lattice.glsl) and edge key (low, high word).
// A corner's vertex is its edge's owner's vertex offset (the scan of the own-vertex counts) + the
// edge's rank among the owner's own edges (cave/tetrahedra.glsl, cave/cube_cases.glsl), from the
// owner's rock corners the count pass stored. Every output element is written by one invocation,
// so the result does not depend on scheduling.
// One dispatch emits the cubes first_emitted_cube .. end_emitted_cube - 1 into windows of the output
// buffers that start at triangle triangle_base and vertex vertex_base: outputs larger than
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE are emitted chunk by chunk (gpu/cave/marching_tetrahedra.cpp).
// A cube writes only its own triangles and the vertices it owns, which lie in its chunk's windows;
// the vertex numbers it writes into triangles stay global.
// Inputs:  CaveBlock (uniform binding 0), density (1), the cube-case tables (storage binding 0),
//          triangle_offsets (2), vertex_offsets (3), cube_rock (5); the uniforms first_emitted_cube,
//          end_emitted_cube, triangle_base, vertex_base.
// Outputs: triangles (4), positions (6), edge_keys (7).
// Twin:    reference/cave/marching_tetrahedra.hpp (the output specification).
layout(local_size_x = 256) in;

uniform uint first_emitted_cube;
uniform uint end_emitted_cube;
uniform uint triangle_base;
uniform uint vertex_base;

#include "cave/linear_dispatch.glsl"
#include "cave/cube_cases.glsl"

layout(std430, binding = 2) readonly buffer TriangleOffsets { uint triangle_offsets[]; };
layout(std430, binding = 3) readonly buffer VertexOffsets { uint vertex_offsets[]; };
layout(std430, binding = 4) writeonly buffer Triangles { uint triangles[]; };
layout(std430, binding = 5) readonly buffer CubeRock { uint cube_rock[]; };
layout(std430, binding = 6) writeonly buffer Positions { float positions[]; };
layout(std430, binding = 7) writeonly buffer EdgeKeys { uvec2 edge_keys[]; };

void write_vertex(uint vertex, ivec3 cube, ivec2 edge) {
  ivec3 lower = cube + corner_offset(edge.x);
  int direction = edge.y - edge.x;
  vec3 position = vertex_position(lower, direction);
  uint slot = vertex - vertex_base;
  positions[3u * slot] = position.x;
  positions[3u * slot + 1u] = position.y;
  positions[3u * slot + 2u] = position.z;
  edge_keys[slot] = lattice_edge_key(lattice_origin.xyz + lower, direction);
}

void main() {
  uint index = first_emitted_cube + linear_invocation();
  if (index >= end_emitted_cube) return;
  ivec3 cube = cube_of(index);
  uint rock = cube_rock[index];
  if (case_triangles[rock] == 0u) return;
  uint triangle_slot = triangle_offsets[index];
  uvec2 met = uvec2(0u);
  for (int tet = 0; tet < 6; ++tet) {
    uint code = tet_code(rock, tet);
    for (int triangle = 0; triangle < tet_triangle_count(code); ++triangle) {
      for (int corner = 0; corner < 3; ++corner) {
        ivec2 edge = corner_edge(tet, code, triangle, corner);
        OwnedEdge owned = owner_of(cube, edge);
        bool own = owned.cube == cube;
        uint owner_index = cube_index(owned.cube);
        uint vertex = vertex_offsets[owner_index] + owned_rank(cube_rock[owner_index], owned.cube, owned.edge);
        if (own && !edge_set_has(met, edge)) {
          met = edge_set_with(met, edge);
          write_vertex(vertex, cube, edge);
        }
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_VERTEX_NUMBERS_FROM_ONE
        vertex += 1u;  // mutant (both twins): indices counted from 1, as an OBJ file counts them
#endif
        triangles[3u * (triangle_slot - triangle_base) + uint(corner)] = vertex;
      }
      ++triangle_slot;
    }
  }
}
