// Spherical Voronoi of the region centroids (digest 002 §2.8, §9.3 step 11), CPU reference.
//
// For each direction, the region whose centroid is nearest, exactly (up to double rounding of the
// distances), by CGAL's k-d tree (dD Spatial Searching, exact with ε = 0). On the unit sphere the
// nearest centroid in Euclidean (chord) distance is the nearest in great-circle distance, so the
// 3-D search answers the spherical question.
// VoronoiSearch(positions).nearest(direction) -> the nearest region, its chord distance and the
// second-nearest distance (a tie when they are equal within rounding); the tree is built once.
// nearest_sites(positions, directions) -> the same for many directions.
//
// Inputs:  positions 3 per region (unit length), directions of unit length.
// Outputs: NearestSite per direction (second_distance +inf with a single region).
// Units:   chord lengths.
// Throws:  nothing.
// Twin:    gpu/planet/voronoi.hpp (PlanetVoronoi) with gpu/shaders/planet/voronoi.comp and
//          voronoi_search.glsl, which searches the cell grid as Algorithm 1 does.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/planet/planet_state.hpp"

namespace gt::reference {

struct NearestSite {
  std::int32_t region = -1;
  double distance = 0.0;
  double second_distance = 0.0;  // +inf with a single region
};

class VoronoiSearch {
 public:
  explicit VoronoiSearch(const std::vector<double>& positions);
  ~VoronoiSearch();
  NearestSite nearest(const Vector3<double>& direction) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

std::vector<NearestSite> nearest_sites(const std::vector<double>& positions, const std::vector<Vector3<double>>& directions);

}  // namespace gt::reference
