#version 450 core
// The planet drawn as the seed's demo draws it (digest 002 §4.3, §9.3 steps 10–11), fragment stage:
// the region whose centroid is nearest the fragment's direction (normalize of the interpolated
// world position) by Algorithm 1's 5×5 search (planet/voronoi_search.glsl; the seed's shader
// searches 3×3), coloured in the elevation palette:
//   base (107, 193, 255)/255 below sea level (e < 0), else (255, 189, 97)/255, times
//   clamp(1 − |e|/4, 0, 1).
// Inputs:  world_position from the vertex stage; VoronoiBlock (uniform binding 0), neighbours (0),
//          positions (1) (planet/voronoi_search.glsl); elevation (4): one per region.
// Outputs: colour (location 0): rgb the colour, alpha the region + 1 (the target is RGBA32F, cleared
//          to 0: alpha 0 where nothing is drawn).
// Twin:    reference/planet/render.cpp; host: gpu/planet/render.cpp.

#include "planet/voronoi_search.glsl"

layout(std430, binding = 4) readonly buffer Elevation { float elevation[]; };  // per region

in vec3 world_position;
layout(location = 0) out vec4 colour;

vec3 elevation_colour(float height) {
  vec3 base = height < 0.0 ? vec3(107.0, 193.0, 255.0) : vec3(255.0, 189.0, 97.0);
#ifdef GT_MUTANT_PLANET_RENDER_GPU_DARKER_PALETTE
  float factor = clamp(1.0 - abs(height) / 2.0, 0.0, 1.0);  // mutant (this twin alone): |e|/2 for |e|/4
#else
  float factor = clamp(1.0 - abs(height) / 4.0, 0.0, 1.0);
#endif
  return base * factor / 255.0;
}

void main() {
  int region = nearest_region(normalize(world_position));
  colour = vec4(elevation_colour(elevation[region]), float(region + 1));
}
