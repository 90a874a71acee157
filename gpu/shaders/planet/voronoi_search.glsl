// Algorithm 1's cell-grid search for the nearest region centroid (digest 002 §2.8, §9.3 step 11),
// shared by gpu/shaders/planet/voronoi.comp (per query direction) and render.frag (per pixel):
//   1. the cell holding the direction: the face of its largest component (ties to z, then x, then
//      y, as core/planet/cube_sphere.hpp), (u, v) = (Pᵀ·w).xy / (Pᵀ·w).z, unwarped by
//      atan(u·tan θ)/θ (u itself for no warp, θ = 0), a = (u + 1)/2, b = (1 − v)/2, cell = clamp(floor(a·R), 0, R − 1);
//   2. the nearest centroid (squared chord distance, the first found on ties) among that cell, its
//      8 neighbours and, with SEARCH_RINGS 2, their neighbours: the 3×3 or 5×5 block of Algorithm 1
//      (the seed's shader searches 3×3, its thesis 5×5), found through the shared neighbour table,
//      so across cube edges and corners without the wrap arithmetic (§9.1).
// Host: gpu/planet/voronoi.cpp (voronoi_block).
// Units: unit-sphere positions; distances as squared chords.
// Inputs:  declares VoronoiBlock (uniform binding 0: face matrices, R, θ, tan θ, query count),
//          neighbours (0), positions (1); a direction.
// Outputs: the nearest region of the direction.
// Twin:    reference/planet/voronoi.hpp (exact).
#ifndef GT_PLANET_VORONOI_SEARCH_GLSL
#define GT_PLANET_VORONOI_SEARCH_GLSL

// Mirrored by VoronoiBlock in gpu/planet/voronoi.cpp.
layout(std140, binding = 0) uniform VoronoiBlock {
  ivec4 face_rows[18];   // face_matrix(face) row r at 3·face + r (core/planet/cube_sphere.hpp)
  int resolution;        // R
  int direction_count;   // voronoi.comp's queries (unused by the renderer)
  float warp_angle;      // θ, rounded once to float
  float tan_warp_angle;  // tan θ, computed in double, rounded once
};
layout(std430, binding = 0) readonly buffer Neighbours { int neighbours[]; };  // 8 per region, −1 invalid
layout(std430, binding = 1) readonly buffer Positions { vec4 positions[]; };   // xyz per region

const int neighbour_count = 8;

#ifndef SEARCH_RINGS
#define SEARCH_RINGS 2
#endif

int face_of(vec3 w) {
  vec3 magnitude = abs(w);
  if (magnitude.z >= magnitude.x && magnitude.z >= magnitude.y) return w.z >= 0.0 ? 0 : 2;
  if (magnitude.x >= magnitude.y) return w.x >= 0.0 ? 1 : 3;
  return w.y >= 0.0 ? 4 : 5;
}

// Pᵀ·w: component i is Σ_r P[r][i]·w[r].
vec3 to_face_space(int face, vec3 w) {
  vec3 result = vec3(0.0);
  for (int row = 0; row < 3; ++row) result += vec3(face_rows[3 * face + row].xyz) * w[row];
  return result;
}

int cell_index(float coordinate) { return clamp(int(floor(coordinate * float(resolution))), 0, resolution - 1); }

int region_of(vec3 w) {
  int face = face_of(w);
  vec3 face_space = to_face_space(face, w);
  vec2 uv = face_space.xy / face_space.z;
  vec2 unwarped = warp_angle == 0.0 ? uv : atan(uv * tan_warp_angle) / warp_angle;  // no warp: θ = 0
  int x = cell_index((unwarped.x + 1.0) * 0.5);
  int y = cell_index((1.0 - unwarped.y) * 0.5);
  return (face * resolution + y) * resolution + x;
}

#ifdef GT_MUTANT_PLANET_VORONOI_GPU_CELL_CENTRES
// Mutant (this twin alone): the site of a region taken at its cell's centre, as Algorithm 1's
// massCenterOfCell would compute it, instead of its jittered centroid.
vec3 site_of(int region) {
  int face = region / (resolution * resolution);
  int cell = region % (resolution * resolution);
  vec2 local = (vec2(cell % resolution, cell / resolution) + 0.5) / float(resolution);
  vec2 face_space = vec2(2.0 * local.x - 1.0, 1.0 - 2.0 * local.y);
  vec2 warped = warp_angle == 0.0 ? face_space : tan(warp_angle * face_space) / tan_warp_angle;
  vec3 cube = vec3(0.0);
  for (int row = 0; row < 3; ++row) cube[row] = dot(vec3(face_rows[3 * face + row].xyz), vec3(warped, 1.0));
  return normalize(cube);
}
#else
vec3 site_of(int region) { return positions[region].xyz; }
#endif

float squared_distance(vec3 w, int region) {
  vec3 difference = site_of(region) - w;
  return dot(difference, difference);
}

// The nearest centroid to the unit direction w in the 3×3 or 5×5 block around its cell.
int nearest_region(vec3 w) {
  int centre = region_of(w);
  int nearest = centre;
  float nearest_squared = squared_distance(w, centre);
  for (int k = 0; k < neighbour_count; ++k) {
    int ring_one = neighbours[neighbour_count * centre + k];
    if (ring_one < 0) continue;
    float squared = squared_distance(w, ring_one);
    if (squared < nearest_squared) {
      nearest = ring_one;
      nearest_squared = squared;
    }
#if SEARCH_RINGS >= 2
    for (int j = 0; j < neighbour_count; ++j) {
      int ring_two = neighbours[neighbour_count * ring_one + j];
      if (ring_two < 0) continue;
      float squared_two = squared_distance(w, ring_two);
      if (squared_two < nearest_squared) {
        nearest = ring_two;
        nearest_squared = squared_two;
      }
    }
#endif
  }
  return nearest;
}

#endif  // GT_PLANET_VORONOI_SEARCH_GLSL
