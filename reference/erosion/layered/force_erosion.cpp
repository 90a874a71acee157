// Force erosion and deposition on the layered ground (digest 001 §3.12; see force_erosion.hpp).
#include "reference/erosion/layered/force_erosion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/mutant.hpp"
#include "reference/erosion/layered/column.hpp"

namespace gt::reference {
namespace {

template <class Real>
Real flux_or_zero(const LayeredWater<Real>& water, int pipe, const std::optional<std::size_t>& cell) {
  return cell ? water.flux_at(pipe, *cell) : Real(0);
}

// |v| of column c (eq. 2.2 and the code's w̄ floor), m/s.
template <class Real>
Real water_speed(const LayeredGround<Real>& ground, const LayeredWater<Real>& water, const LayeredParams& params,
                 int x, int y) {
  const NetFlux<Real> flux = net_flux(ground, water, params, x, y);
  const Real mean = mean_depth(water, params, ground.cell(x, y));
  if (mean <= Real(0)) return 0;
  const Real speed_x = std::abs(flux.x) / (static_cast<Real>(ground.cell_size_y) * mean);
  const Real speed_y = std::abs(flux.y) / (static_cast<Real>(ground.cell_size_x) * mean);
  return std::sqrt(speed_x * speed_x + speed_y * speed_y);
}

// max(sin φ, slope_floor) of column (x, y) from the surface snapshot.
template <class Real>
Real slope_sine(const LayeredGround<Real>& ground, const std::vector<Real>& surface, const LayeredParams& params,
                int x, int y) {
  const std::size_t c = ground.cell(x, y);
  const auto height = [&](int k) {
    const auto n = layered_neighbour(ground, params.border, x, y, k);
    return surface[n ? *n : c];
  };
  const bool thesis = params.slope_form == SlopeForm::thesis;
  const auto scale_x = static_cast<Real>(thesis ? 0.5 / ground.cell_size_x : 1.0);
  const auto scale_y = static_cast<Real>(thesis ? 0.5 / ground.cell_size_y : 1.0);
  const Real gradient_x = (height(1) - height(0)) * scale_x;
  const Real gradient_y = (height(2) - height(3)) * scale_y;
  const Real squared = gradient_x * gradient_x + gradient_y * gradient_y;
  return std::max(std::sqrt(squared / (Real(1) + squared)), static_cast<Real>(params.slope_floor));
}

template <class Real>
int first_bedrock_layer(const LayeredGround<Real>& ground, std::size_t c) {
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    if (ground.bedrock_at(layer, c) > Real(0)) return layer;
  }
  return -1;
}

// Erodes every source size j ≥ i into suspended size i, then the bedrock into size i.
template <class Real>
void erode_into_size(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                     std::size_t c, int size, Real strength, LayeredConversions& conversions) {
  const double area = ground.cell_size_x * ground.cell_size_y;
  const auto erosion_rate = static_cast<Real>(params.erosion_rate);
  const auto i = static_cast<std::size_t>(size);
  for (int source = size; source < fragment_size_count; ++source) {
    const auto j = static_cast<std::size_t>(source);
    const Real request = erosion_rate * breakdown(params.breakdown_form, params.breakdown_slopes[j][i],
                                                  params.breakdown_thresholds[j][i], strength);
    if (request <= Real(0)) continue;
    const Real taken = erode_component(ground, c, source + 1, request, params);
    water.carried_at(suspended_kind(size + 1), c) += taken;
    if (source != size && taken > Real(0) && !mutant_active("erosion.layered.breakdown_uncounted")) {
      conversions.broken_from[j + 1] += static_cast<double>(taken) * area;
      conversions.broken_into[i + 1] += static_cast<double>(taken) * area;
    }
  }
  const int layer = first_bedrock_layer(ground, c);
  if (layer < 0) return;
  const auto type = static_cast<std::size_t>(ground.bedrock_type_at(layer, c));
  const BedrockType& rock = params.bedrock_types[type];
  const Real request = erosion_rate *
                       breakdown(params.breakdown_form, rock.erosion_slopes[i], rock.erosion_thresholds[i], strength) *
                       soil_transparency(ground, c, params);
  if (request <= Real(0)) return;
  const Real taken = erode_bedrock(ground, c, request).amount;
  water.carried_at(suspended_kind(size + 1), c) += taken;
  conversions.bedrock_eroded_from.at(type) += static_cast<double>(taken) * area;
  conversions.bedrock_eroded_into[i + 1] += static_cast<double>(taken) * area;
}

// The amount of suspended kind `component` above `capacity` that settles (K_d of the gap), taken
// from the water; 0 at or below the capacity.
template <class Real>
Real settle(LayeredWater<Real>& water, std::size_t c, int component, Real capacity, const LayeredParams& params) {
  Real& suspended = water.carried_at(suspended_kind(component), c);
  if (!(suspended > capacity)) return 0;
  const Real amount = static_cast<Real>(params.deposition_rate) * (suspended - capacity);
  const Real left = suspended - amount;
  if (left < static_cast<Real>(negligible_amount)) {
    const Real all = suspended;
    suspended = 0;
    return all;
  }
  suspended = left;
  return amount;
}

template <class Real>
void erode_and_deposit(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                       std::size_t c, Real strength, LayeredConversions& conversions) {
  Composition<Real> deposited{};
  const Real organic_capacity = static_cast<Real>(params.organic_capacity) * strength;
  Real& organic = water.carried_at(suspended_kind(0), c);
  if (organic < organic_capacity) {
    organic += erode_component(ground, c, 0, static_cast<Real>(params.erosion_rate) * (organic_capacity - organic),
                               params);
  } else {
    deposited[0] = settle(water, c, 0, organic_capacity, params);
  }
  for (int size = 0; size < fragment_size_count; ++size) erode_into_size(ground, water, params, c, size, strength, conversions);
  for (int size = 0; size < fragment_size_count; ++size) {
    const auto i = static_cast<std::size_t>(size);
    const Real capacity = breakdown(params.breakdown_form, params.breakdown_slopes[i][i],
                                    params.breakdown_thresholds[i][i], strength);
    deposited[i + 1] = settle(water, c, size + 1, capacity, params);
  }
  deposit_soil(ground, c, deposited, static_cast<Real>(params.topsoil_max));
}

}  // namespace

template <class Real>
NetFlux<Real> net_flux(const LayeredGround<Real>& ground, const LayeredWater<Real>& water, const LayeredParams& params,
                       int x, int y) {
  const std::size_t c = ground.cell(x, y);
  const auto left = layered_neighbour(ground, params.border, x, y, 0);
  const auto right = layered_neighbour(ground, params.border, x, y, 1);
  const auto top = layered_neighbour(ground, params.border, x, y, 2);
  const auto bottom = layered_neighbour(ground, params.border, x, y, 3);
  return {Real(0.5) * ((flux_or_zero(water, 1, left) - water.flux_at(0, c)) +
                       (water.flux_at(1, c) - flux_or_zero(water, 0, right))),
          Real(0.5) * ((flux_or_zero(water, 2, bottom) - water.flux_at(3, c)) +
                       (water.flux_at(2, c) - flux_or_zero(water, 3, top)))};
}

template <class Real>
Real mean_depth(const LayeredWater<Real>& water, const LayeredParams& params, std::size_t c) {
  return std::max(Real(0.5) * (water.water[c] + water.previous_water[c]), static_cast<Real>(params.velocity_depth_floor));
}

template <class Real>
Real water_strength(const LayeredGround<Real>& ground, const std::vector<Real>& surface,
                    const LayeredWater<Real>& water, const LayeredParams& params, int x, int y) {
  const std::size_t c = ground.cell(x, y);
  const Real depth = water.water[c];
  if (!(depth > Real(0))) return 0;
  const Real speed = water_speed(ground, water, params, x, y);
  const Real sine = slope_sine(ground, surface, params, x, y);
  const Real ramp = std::min(depth / static_cast<Real>(params.depth_ramp), Real(1));
  const Real protection = Real(1) + static_cast<Real>(params.vegetation_protection) * ground.vegetation[c];
  return static_cast<Real>(params.erosion_strength) * sine * speed * ramp / protection;
}

template <class Real>
Real breakdown(BreakdownForm form, double slope, double threshold, Real strength) {
  const auto a = static_cast<Real>(slope);
  const auto b = static_cast<Real>(threshold);
  const Real amount = form == BreakdownForm::thesis ? a * (strength - b) : a * strength - b;
  return std::max(amount, Real(0));
}

template <class Real>
void force_erosion_step(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                        LayeredConversions& conversions) {
  conversions.fit_types(params.bedrock_types.size());
  const std::vector<Real> surface = ground.surface;
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const Real strength = water_strength(ground, surface, water, params, x, y);
      erode_and_deposit(ground, water, params, ground.cell(x, y), strength, conversions);
    }
  }
}

#define GT_LAYERED_FORCE_EROSION_INSTANTIATE(Real)                                                              \
  template Real water_strength(const LayeredGround<Real>&, const std::vector<Real>&, const LayeredWater<Real>&, \
                               const LayeredParams&, int, int);                                                \
  template Real breakdown(BreakdownForm, double, double, Real);                                                \
  template NetFlux<Real> net_flux(const LayeredGround<Real>&, const LayeredWater<Real>&, const LayeredParams&, int, \
                                  int);                                                                        \
  template Real mean_depth(const LayeredWater<Real>&, const LayeredParams&, std::size_t);                       \
  template void force_erosion_step(LayeredGround<Real>&, LayeredWater<Real>&, const LayeredParams&,            \
                                   LayeredConversions&);
GT_LAYERED_FORCE_EROSION_INSTANTIATE(float)
GT_LAYERED_FORCE_EROSION_INSTANTIATE(double)
#undef GT_LAYERED_FORCE_EROSION_INSTANTIATE

}  // namespace gt::reference
