#version 450 core
// The planet drawn as the seed's demo draws it (digest 002 §4.3), vertex stage: clip = P·V·(p, 1)
// with the reference's P·V (reference/render/phong.hpp) computed in double, rounded to float and
// set with transpose = GL_TRUE from its row-major array; the world position goes to the fragment
// stage, interpolated perspective-correctly (GL's default).
// Inputs:  position (location 0), view_projection (uniform location 0).
// Outputs: gl_Position; world_position.
// Twin:    reference/planet/render.cpp.

layout(location = 0) in vec3 position;
layout(location = 0) uniform mat4 view_projection;

out vec3 world_position;

void main() {
  gl_Position = view_projection * vec4(position, 1.0);
  world_position = position;
}
