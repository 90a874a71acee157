#version 450 core
// Seed 004's Phong look (digest 004_cave.md §2.9), vertex stage: clip = P·V·(p, 1) with the
// reference's P·V (reference/render/phong.hpp) computed in double, rounded to float and set with
// transpose = GL_TRUE from its row-major array. The world position and the CPU's vertex normal
// (area-weighted; the noise gradient's for the cave's own meshes) go to the fragment stage,
// interpolated perspective-correctly (GL's default). The same for every look (GT_PHONG_LOOK).
// Inputs:  position (location 0), normal (location 1), view_projection (uniform location 0).
// Outputs: gl_Position; world_position, vertex_normal.
// Twin:    reference/render/phong.cpp.

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) uniform mat4 view_projection;

out vec3 world_position;
out vec3 vertex_normal;

void main() {
  gl_Position = view_projection * vec4(position, 1.0);
#ifdef GT_MUTANT_RENDER_PHONG_VERTICAL_FLIP
  gl_Position.y = -gl_Position.y;  // mutant (both twins): the picture upside down
#endif
  world_position = position;
  vertex_normal = normal;
}
