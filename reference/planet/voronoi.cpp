// Spherical Voronoi by nearest centroid; see voronoi.hpp.
#include "reference/planet/voronoi.hpp"

#include <cmath>
#include <limits>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <boost/tuple/tuple.hpp>

namespace gt::reference {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Site = boost::tuple<Point, std::int32_t>;
using Traits = CGAL::Search_traits_adapter<Site, CGAL::Nth_of_tuple_property_map<0, Site>, CGAL::Search_traits_3<Kernel>>;
using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;

}  // namespace

// The k-d tree keeps its own copy of the sites.
struct VoronoiSearch::Tree {
  Search::Tree tree;
  Search::Distance distance;
  explicit Tree(const std::vector<Site>& sites) : tree(sites.begin(), sites.end()) {}
};

namespace {

std::vector<Site> sites_of(const std::vector<double>& positions) {
  std::vector<Site> sites;
  for (std::size_t region = 0; 3 * region + 2 < positions.size(); ++region) {
    sites.emplace_back(Point(positions[3 * region], positions[3 * region + 1], positions[3 * region + 2]),
                       static_cast<std::int32_t>(region));
  }
  return sites;
}

}  // namespace

VoronoiSearch::VoronoiSearch(const std::vector<double>& positions) : tree_(std::make_unique<Tree>(sites_of(positions))) {}

VoronoiSearch::~VoronoiSearch() = default;

NearestSite VoronoiSearch::nearest(const Vector3<double>& direction) const {
  // k = 2, ε = 0 (exact), nearest first, squared distances.
  const Search search(tree_->tree, Point(direction[0], direction[1], direction[2]), 2, 0.0, true, tree_->distance);
  NearestSite site{-1, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  int rank = 0;
  for (const auto& [found, squared] : search) {
    if (rank++ == 0) {
      site.region = boost::get<1>(found);
      site.distance = std::sqrt(squared);
    } else {
      site.second_distance = std::sqrt(squared);
    }
  }
  return site;
}

std::vector<NearestSite> nearest_sites(const std::vector<double>& positions, const std::vector<Vector3<double>>& directions) {
  const VoronoiSearch search(positions);
  std::vector<NearestSite> nearest;
  nearest.reserve(directions.size());
  for (const auto& direction : directions) nearest.push_back(search.nearest(direction));
  return nearest;
}

}  // namespace gt::reference
