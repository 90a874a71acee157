// Vegetation growth on the layered ground (digest 001 §3.15; decisions and units in vegetation.hpp).
#include "reference/erosion/layered/vegetation.hpp"

#include <algorithm>
#include <vector>

#include "core/rng.hpp"

namespace gt::reference {
namespace {

template <class Real>
bool has_organic_matter(const LayeredGround<Real>& ground, std::size_t c) {
  return ground.soil_at(0, 0, c) > Real(0) || ground.soil_at(1, 0, c) > Real(0);
}

// Σ of the old densities around (x, y): the 8 neighbours, plus the column itself for seed001_code.
template <class Real>
Real neighbour_vegetation(const LayeredGround<Real>& ground, const LayeredParams& params, int x, int y) {
  const bool with_centre = params.vegetation_quality == VegetationQuality::seed001_code;
  Real sum = with_centre ? ground.vegetation[ground.cell(x, y)] : Real(0);
  for (int k = 0; k < layered_neighbour_count; ++k) {
    const auto n = layered_neighbour(ground, params.border, x, y, k);
    if (n) sum += ground.vegetation[*n];
  }
  return sum;
}

template <class Real>
Real quality(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c) {
  const Real shallow = soil_quality(ground, params, c, static_cast<Real>(params.root_depth));
  if (params.vegetation_quality == VegetationQuality::thesis) return shallow;
  const Real veg = ground.vegetation[c];
  const Real deep = soil_quality(ground, params, c, static_cast<Real>(params.root_depth_deep));
  return (Real(1) - veg) * shallow + veg * deep - static_cast<Real>(params.vegetation_base);
}

}  // namespace

template <class Real>
Real soil_quality(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c, Real depth) {
  Real weighted = 0;
  Real left = depth;
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const Real thickness = ground.soil_thickness(layer, c);
    if (thickness <= Real(0) || left <= Real(0)) continue;
    const bool whole_layer = left >= thickness;
    const Real share = whole_layer ? Real(1) : left / thickness;
    for (int component = 0; component < soil_component_count; ++component) {
      const Real sampled = ground.soil_at(layer, component, c) * share;
      weighted += static_cast<Real>(params.vegetation_soil_quality[static_cast<std::size_t>(component)]) * sampled;
    }
    left = whole_layer ? left - thickness : Real(0);
  }
  const Real sampled_depth = std::min(depth, ground.soil_thickness(0, c) + ground.soil_thickness(1, c));
  return sampled_depth > Real(0) ? weighted / sampled_depth : Real(0);
}

template <class Real>
Real grown_vegetation(const LayeredGround<Real>& ground, const LayeredParams& params, int x, int y,
                      std::uint32_t step) {
  const std::size_t c = ground.cell(x, y);
  if (!has_organic_matter(ground, c)) return Real(0);
  const Real veg = ground.vegetation[c];
  const Real drive = quality(ground, params, c) - static_cast<Real>(params.vegetation_equilibrium) * veg +
                     static_cast<Real>(params.vegetation_neighbours) * neighbour_vegetation(ground, params, x, y);
  const Real rate = static_cast<Real>(params.vegetation_rate) * static_cast<Real>(params.time_step);
  const auto u = static_cast<Real>(uniform01(random_u32(params.seed, static_cast<std::uint32_t>(c), step,
                                                        vegetation_cell_stream)));
  return std::clamp(veg + u * (rate * drive), Real(0), Real(1));
}

template <class Real>
void vegetation_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                     LayeredConversions& /*conversions*/, const LayeredWater<Real>* water) {
  std::vector<Real> grown(ground.cells());
  const auto flood = static_cast<Real>(params.flood_wetness);
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t c = ground.cell(x, y);
      const bool flooded = water != nullptr && water->wetness[c] > flood;
      grown[c] = flooded ? Real(0) : grown_vegetation(ground, params, x, y, step);
    }
  }
  ground.vegetation = std::move(grown);
}

#define GT_LAYERED_VEGETATION_INSTANTIATE(Real)                                                             \
  template Real soil_quality(const LayeredGround<Real>&, const LayeredParams&, std::size_t, Real);          \
  template Real grown_vegetation(const LayeredGround<Real>&, const LayeredParams&, int, int, std::uint32_t); \
  template void vegetation_step(LayeredGround<Real>&, const LayeredParams&, std::uint32_t, LayeredConversions&, \
                               const LayeredWater<Real>*);
GT_LAYERED_VEGETATION_INSTANTIATE(float)
GT_LAYERED_VEGETATION_INSTANTIATE(double)
#undef GT_LAYERED_VEGETATION_INSTANTIATE

}  // namespace gt::reference
