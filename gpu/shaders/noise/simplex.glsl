// Simplex noise in 2, 3 and 4 dimensions with the analytic gradient in 2-D and 3-D (seed 004 digest
// §2.2.3-2.2.4: Eshelman's port of Gustavson 2005).
//
// float gt_simplex2(vec2 p)                                  kernel radius² 0.5, scale 70
// float gt_simplex3(vec3 p, float kernel_radius_squared)     0.6 (seed 004) or 0.5, scale 32
// float gt_simplex4(vec4 p, float kernel_radius_squared)     scale 27
// vec3 gt_simplex2_gradient(vec2 p)                          (value, d/dx, d/dy)
// vec4 gt_simplex3_gradient(vec3 p, float r2)                (value, d/dx, d/dy, d/dz)
// p in noise units; the permutation comes from noise/permutation.glsl (binding 5).
//
// Twin contract: every float operation is the C++ float instantiation's, in the same order, and
// every intermediate is `precise` (no fused multiply-add, no reassociation):
//   skew = (Σ p) · F, origin = ivec(floor(p + skew)), unskew = float(Σ origin) · G,
//   offset0 = p - (origin - unskew); axis ranks (3-D: >=, ties to the lower axis; 2-D, 4-D: >);
//   corner m steps along the axes of rank >= n - m, offset = (offset0 - step) + m·G;
//   hash = perm[x + perm[y + perm[z]]] on the doubled table with x = (origin & 255) + step;
//   t = ((r2 - d.x²) - d.y²) - ..., value term (t²·t²)·(g·d) with g·d summed left to right,
//   derivative term (-8·(t²·t))·(g·d)·d + t⁴·g, total summed corner by corner, times the scale.
// The constants are the floats nearest to the exact values (the C++ side rounds the same decimals
// once; tests/simplex_test.cpp checks that the literals here equal those floats).
// Guarded: included by several programs.
// Inputs:  p in noise units, kernel_radius_squared; the permutation buffer (binding 5).
// Outputs: the values and gradients listed above.
// Twin:    reference/noise/simplex.cpp.
#ifndef GT_NOISE_SIMPLEX_GLSL
#define GT_NOISE_SIMPLEX_GLSL

#include "noise/permutation.glsl"

// Skew factors F = (sqrt(n + 1) - 1) / n; corner unskew offsets m·G, G = (1 - 1/sqrt(n + 1)) / n.
const float GT_SIMPLEX_SKEW2 = 0.366025418;
const float GT_SIMPLEX_CORNER_UNSKEW2[3] = float[3](0.0, 0.211324871, 0.422649741);
const float GT_SIMPLEX_SKEW3 = 0.333333343;
const float GT_SIMPLEX_CORNER_UNSKEW3[4] = float[4](0.0, 0.166666672, 0.333333343, 0.5);
const float GT_SIMPLEX_SKEW4 = 0.309017003;
const float GT_SIMPLEX_CORNER_UNSKEW4[5] = float[5](0.0, 0.138196602, 0.276393205, 0.414589792, 0.55278641);

// Eshelman's grad3 (2-D uses its x, y parts) and Gustavson's grad4.
const vec3 GT_SIMPLEX_GRAD3[12] = vec3[12](
    vec3(1, 1, 0), vec3(-1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0),
    vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
    vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, 1, -1), vec3(0, -1, -1));
const vec4 GT_SIMPLEX_GRAD4[32] = vec4[32](
    vec4(0, 1, 1, 1), vec4(0, 1, 1, -1), vec4(0, 1, -1, 1), vec4(0, 1, -1, -1),
    vec4(0, -1, 1, 1), vec4(0, -1, 1, -1), vec4(0, -1, -1, 1), vec4(0, -1, -1, -1),
    vec4(1, 0, 1, 1), vec4(1, 0, 1, -1), vec4(1, 0, -1, 1), vec4(1, 0, -1, -1),
    vec4(-1, 0, 1, 1), vec4(-1, 0, 1, -1), vec4(-1, 0, -1, 1), vec4(-1, 0, -1, -1),
    vec4(1, 1, 0, 1), vec4(1, 1, 0, -1), vec4(1, -1, 0, 1), vec4(1, -1, 0, -1),
    vec4(-1, 1, 0, 1), vec4(-1, 1, 0, -1), vec4(-1, -1, 0, 1), vec4(-1, -1, 0, -1),
    vec4(1, 1, 1, 0), vec4(1, 1, -1, 0), vec4(1, -1, 1, 0), vec4(1, -1, -1, 0),
    vec4(-1, 1, 1, 0), vec4(-1, 1, -1, 0), vec4(-1, -1, 1, 0), vec4(-1, -1, -1, 0));

// ---- per-dimension helpers (overloaded on the vector size) ----

float gt_simplex_sum(vec2 v) {
  precise float sum = v.x + v.y;
  return sum;
}
float gt_simplex_sum(vec3 v) {
  precise float sum = (v.x + v.y) + v.z;
  return sum;
}
float gt_simplex_sum(vec4 v) {
  precise float sum = ((v.x + v.y) + v.z) + v.w;
  return sum;
}

// t = r2 - |d|², subtracted term by term.
float gt_simplex_falloff(float kernel_radius_squared, vec2 d) {
  precise float falloff = (kernel_radius_squared - d.x * d.x) - d.y * d.y;
  return falloff;
}
float gt_simplex_falloff(float kernel_radius_squared, vec3 d) {
  precise float falloff = ((kernel_radius_squared - d.x * d.x) - d.y * d.y) - d.z * d.z;
  return falloff;
}
float gt_simplex_falloff(float kernel_radius_squared, vec4 d) {
  precise float falloff = (((kernel_radius_squared - d.x * d.x) - d.y * d.y) - d.z * d.z) - d.w * d.w;
  return falloff;
}

// g·d summed left to right (not dot(), whose order is the driver's).
float gt_simplex_dot(vec2 g, vec2 d) {
  precise float along = g.x * d.x + g.y * d.y;
  return along;
}
float gt_simplex_dot(vec3 g, vec3 d) {
  precise float along = (g.x * d.x + g.y * d.y) + g.z * d.z;
  return along;
}
float gt_simplex_dot(vec4 g, vec4 d) {
  precise float along = ((g.x * d.x + g.y * d.y) + g.z * d.z) + g.w * d.w;
  return along;
}

// rank[a]: how many axes axis a precedes (largest offset first).
ivec2 gt_simplex_ranks(vec2 d) { return d.x > d.y ? ivec2(1, 0) : ivec2(0, 1); }
ivec3 gt_simplex_ranks(vec3 d) {  // ties go to the lower axis, as Gustavson's 3-D branches
  ivec3 rank = ivec3(0);
  if (d.x >= d.y) rank.x += 1; else rank.y += 1;
  if (d.x >= d.z) rank.x += 1; else rank.z += 1;
  if (d.y >= d.z) rank.y += 1; else rank.z += 1;
  return rank;
}
ivec4 gt_simplex_ranks(vec4 d) {  // ties go to the higher axis, as Gustavson's 4-D table
  ivec4 rank = ivec4(0);
  if (d.x > d.y) rank.x += 1; else rank.y += 1;
  if (d.x > d.z) rank.x += 1; else rank.z += 1;
  if (d.x > d.w) rank.x += 1; else rank.w += 1;
  if (d.y > d.z) rank.y += 1; else rank.z += 1;
  if (d.y > d.w) rank.y += 1; else rank.w += 1;
  if (d.z > d.w) rank.z += 1; else rank.w += 1;
  return rank;
}

// corner = (origin & 255) + step, components 0..256: indices stay below 512.
uint gt_simplex_hash(ivec2 corner) { return perm[uint(corner.x) + perm[corner.y]]; }
uint gt_simplex_hash(ivec3 corner) { return perm[uint(corner.x) + perm[uint(corner.y) + perm[corner.z]]]; }
uint gt_simplex_hash(ivec4 corner) {
  return perm[uint(corner.x) + perm[uint(corner.y) + perm[uint(corner.z) + perm[corner.w]]]];
}

// (t⁴ (g·d), -8 t³ (g·d) d + t⁴ g); zero outside the kernel.
vec3 gt_simplex_corner(vec2 g, vec2 d, float kernel_radius_squared) {
  precise float falloff = gt_simplex_falloff(kernel_radius_squared, d);
  if (!(falloff > 0.0)) return vec3(0.0);
  precise float along = gt_simplex_dot(g, d);
  precise float falloff2 = falloff * falloff;
  precise float falloff4 = falloff2 * falloff2;
  precise float slope = (-8.0 * (falloff2 * falloff)) * along;
  precise float value = falloff4 * along;
  precise vec2 derivative = (slope * d) + (falloff4 * g);
  return vec3(value, derivative);
}
vec4 gt_simplex_corner(vec3 g, vec3 d, float kernel_radius_squared) {
  precise float falloff = gt_simplex_falloff(kernel_radius_squared, d);
  if (!(falloff > 0.0)) return vec4(0.0);
  precise float along = gt_simplex_dot(g, d);
  precise float falloff2 = falloff * falloff;
  precise float falloff4 = falloff2 * falloff2;
  precise float slope = (-8.0 * (falloff2 * falloff)) * along;
  precise float value = falloff4 * along;
  precise vec3 derivative = (slope * d) + (falloff4 * g);
  return vec4(value, derivative);
}
float gt_simplex_corner(vec4 g, vec4 d, float kernel_radius_squared) {
  precise float falloff = gt_simplex_falloff(kernel_radius_squared, d);
  if (!(falloff > 0.0)) return 0.0;
  precise float along = gt_simplex_dot(g, d);
  precise float falloff2 = falloff * falloff;
  precise float falloff4 = falloff2 * falloff2;
  precise float value = falloff4 * along;
  return value;
}

// Mutant hooks (compare/mutants/noise.cpp). GT_MUTANT_NOISE_SIMPLEX3_GRAD3_SWAPPED is
// also in the reference (both twins); the others are this twin's alone.
// grad3's entry for a hash; the mutant exchanges the table's first two entries.
uint gt_simplex_grad3_index(uint hash) {
  uint index = hash % 12u;
#ifdef GT_MUTANT_NOISE_SIMPLEX3_GRAD3_SWAPPED
  if (index < 2u) index = 1u - index;
#endif
  return index;
}

#ifdef GT_MUTANT_NOISE_SIMPLEX2_GPU_KERNEL
const float GT_SIMPLEX2_KERNEL_RADIUS_SQUARED = 0.6;  // mutant: the 3-D seed kernel in 2-D
#else
const float GT_SIMPLEX2_KERNEL_RADIUS_SQUARED = 0.5;
#endif

#ifdef GT_MUTANT_NOISE_SIMPLEX3_GPU_SKEW
#define GT_SIMPLEX3_SKEW_FACTOR GT_SIMPLEX_SKEW2  // mutant: the 2-D skew factor in 3-D
#else
#define GT_SIMPLEX3_SKEW_FACTOR GT_SIMPLEX_SKEW3
#endif

// ---- the noises ----

vec3 gt_simplex2_gradient(vec2 p) {
  precise float skew = gt_simplex_sum(p) * GT_SIMPLEX_SKEW2;
  precise vec2 skewed = p + vec2(skew);
  ivec2 cell_origin = ivec2(floor(skewed));
  precise float unskew = float(cell_origin.x + cell_origin.y) * GT_SIMPLEX_CORNER_UNSKEW2[1];
  precise vec2 offset0 = p - (vec2(cell_origin) - vec2(unskew));
  ivec2 rank = gt_simplex_ranks(offset0);
  ivec2 wrapped = cell_origin & 255;
  precise vec3 total = vec3(0.0);
  for (int corner = 0; corner <= 2; ++corner) {
    ivec2 lattice_step = ivec2(greaterThanEqual(rank, ivec2(2 - corner)));
    precise vec2 corner_offset = (offset0 - vec2(lattice_step)) + vec2(GT_SIMPLEX_CORNER_UNSKEW2[corner]);
    vec2 g = GT_SIMPLEX_GRAD3[gt_simplex_grad3_index(gt_simplex_hash(wrapped + lattice_step))].xy;
    total = total + gt_simplex_corner(g, corner_offset, GT_SIMPLEX2_KERNEL_RADIUS_SQUARED);
  }
  precise vec3 scaled = 70.0 * total;
  return scaled;
}

vec4 gt_simplex3_gradient(vec3 p, float kernel_radius_squared) {
  precise float skew = gt_simplex_sum(p) * GT_SIMPLEX3_SKEW_FACTOR;
  precise vec3 skewed = p + vec3(skew);
  ivec3 cell_origin = ivec3(floor(skewed));
  precise float unskew = float((cell_origin.x + cell_origin.y) + cell_origin.z) * GT_SIMPLEX_CORNER_UNSKEW3[1];
  precise vec3 offset0 = p - (vec3(cell_origin) - vec3(unskew));
  ivec3 rank = gt_simplex_ranks(offset0);
  ivec3 wrapped = cell_origin & 255;
  precise vec4 total = vec4(0.0);
  for (int corner = 0; corner <= 3; ++corner) {
    ivec3 lattice_step = ivec3(greaterThanEqual(rank, ivec3(3 - corner)));
    precise vec3 corner_offset = (offset0 - vec3(lattice_step)) + vec3(GT_SIMPLEX_CORNER_UNSKEW3[corner]);
    vec3 g = GT_SIMPLEX_GRAD3[gt_simplex_grad3_index(gt_simplex_hash(wrapped + lattice_step))];
    total = total + gt_simplex_corner(g, corner_offset, kernel_radius_squared);
  }
  precise vec4 scaled = 32.0 * total;
  return scaled;
}

float gt_simplex4(vec4 p, float kernel_radius_squared) {
  precise float skew = gt_simplex_sum(p) * GT_SIMPLEX_SKEW4;
  precise vec4 skewed = p + vec4(skew);
  ivec4 cell_origin = ivec4(floor(skewed));
  int origin_sum = ((cell_origin.x + cell_origin.y) + cell_origin.z) + cell_origin.w;
  precise float unskew = float(origin_sum) * GT_SIMPLEX_CORNER_UNSKEW4[1];
  precise vec4 offset0 = p - (vec4(cell_origin) - vec4(unskew));
  ivec4 rank = gt_simplex_ranks(offset0);
  ivec4 wrapped = cell_origin & 255;
  precise float total = 0.0;
  for (int corner = 0; corner <= 4; ++corner) {
    ivec4 lattice_step = ivec4(greaterThanEqual(rank, ivec4(4 - corner)));
    precise vec4 corner_offset = (offset0 - vec4(lattice_step)) + vec4(GT_SIMPLEX_CORNER_UNSKEW4[corner]);
    vec4 g = GT_SIMPLEX_GRAD4[gt_simplex_hash(wrapped + lattice_step) % 32u];
    total = total + gt_simplex_corner(g, corner_offset, kernel_radius_squared);
  }
  precise float scaled = 27.0 * total;
  return scaled;
}

// The values alone: the same operations, the compiler drops the unused derivatives.
float gt_simplex2(vec2 p) { return gt_simplex2_gradient(p).x; }

float gt_simplex3(vec3 p, float kernel_radius_squared) { return gt_simplex3_gradient(p, kernel_radius_squared).x; }

#endif
