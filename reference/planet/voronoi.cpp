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

std::vector<NearestSite> nearest_sites(const std::vector<double>& positions, const std::vector<Vector3<double>>& directions) {
  std::vector<Site> sites;
  for (std::size_t region = 0; 3 * region + 2 < positions.size(); ++region) {
    sites.emplace_back(Point(positions[3 * region], positions[3 * region + 1], positions[3 * region + 2]),
                       static_cast<std::int32_t>(region));
  }
  const Search::Tree tree(sites.begin(), sites.end());
  const Search::Distance distance;
  std::vector<NearestSite> nearest;
  nearest.reserve(directions.size());
  for (const auto& direction : directions) {
    const Point query(direction[0], direction[1], direction[2]);
    // k = 2, ε = 0 (exact), nearest first, squared distances.
    const Search search(tree, query, 2, 0.0, true, distance);
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
    nearest.push_back(site);
  }
  return nearest;
}

}  // namespace gt::reference
