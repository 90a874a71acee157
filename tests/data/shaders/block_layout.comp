#version 450
// Test shader of tests/block_layout_test.cpp (GlProgram::check_block): a std140 uniform block and a
// std430 storage block with the members whose offsets the two layouts place differently (a float
// array, a vec3, a struct, an array of structs), and a packed block whose unread member the linker
// may drop. The offsets in the comments are the ones the test's C++ mirrors state.
layout(local_size_x = 1) in;

struct Pair {
  float first;  // 0
  vec2 second;  // 8 (a vec2 is 8-aligned in both layouts); the struct is 16 bytes in both
};

layout(std140, binding = 0) uniform LayoutUniforms {
  float scale;        // 0
  vec3 direction;     // 16 (a vec3 is 16-aligned)
  float weights[3];   // 32, std140 array stride 16: up to 80
  Pair pair;          // 80: pair.first 80, pair.second 88
  int count;          // 96
  float unread;       // 100, never read: std140 keeps it active; the block is 112 bytes
};

layout(std430, binding = 1) buffer LayoutStorage {
  float factor;     // 0
  float values[3];  // 4, std430 array stride 4: up to 16
  vec3 normal;      // 16
  uint flags;       // 28
  Pair records[];   // 32, stride 16; the block counts one record: 48 bytes
};

layout(packed, binding = 2) uniform PackedUniforms {
  float read_value;
  float dropped_value;  // never read
};

void main() {
  records[0].first = scale * factor + weights[2] + pair.second.y + float(count) + values[1] + normal.z + read_value;
  records[0].second = direction.xy + pair.first;
  flags = 1u;
}
