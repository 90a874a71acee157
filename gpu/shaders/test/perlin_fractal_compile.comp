#version 450
// Test shader of tests/perlin_fractal_test.cpp (NoiseGlsl.PerlinAndFractalCompile): includes every
// Perlin and fractal GLSL file and uses each function, so that compiling and linking it checks them.
// Element i of `values` gets the functions' sum at a point that depends on i; nothing reads it.
// Inputs:  the permutation (binding 5), the uniform terms (GtFractalTerms), the texture (unit 0).
// Outputs: values (binding 0).
// Twin:    none: a compile test (reference/noise/perlin.hpp, perlin_texture.hpp, fractal.hpp are the
//          twins of the files it includes).
layout(local_size_x = 64, local_size_y = 1) in;

#include "noise/perlin.glsl"
#include "noise/perlin_texture.glsl"
#define FRACTAL_BASIS(q) gt_perlin3(q)
#include "noise/fractal.glsl"

layout(std430, binding = 0) writeonly buffer Values { float values[]; };

uniform GtFractalTerms terms;

void main() {
  vec3 p = vec3(float(gl_GlobalInvocationID.x) * 0.37, 0.25, -1.5);
  vec4 gradient = gt_perlin3_gradient(p);
  values[gl_GlobalInvocationID.x] = gt_perlin3(p) + gradient.x + gradient.y + gradient.z + gradient.w +
                                    gt_perlin3_texture(p) + gt_fbm(p, terms) + gt_ridged_multifractal(p, terms) +
                                    gt_hetero_terrain(p, terms);
}
