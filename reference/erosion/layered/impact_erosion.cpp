// Impact erosion on the layered ground, two passes (digest 001 §3.14; see impact_erosion.hpp).
#include "reference/erosion/layered/impact_erosion.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "core/mutant.hpp"
#include "reference/erosion/layered/column.hpp"
#include "reference/erosion/layered/force_erosion.hpp"

namespace gt::reference {
namespace {

template <class Real>
using PipeLoads = std::array<std::array<Real, soil_component_count>, water_pipe_count>;  // per pipe, per size

// What one column's impact erosion broke and took from bedrock, summed in Real.
template <class Real>
struct ImpactTally {
  std::array<std::array<Real, fragment_size_count>, fragment_size_count> broken{};  // [source][result]
  std::array<Real, fragment_size_count> bedrock{};
  int bedrock_type = -1;
};

// v of neighbour n's water toward the target through pipe k of the target (0 when it stands or
// moves away), m/s.
template <class Real>
Real speed_toward(const LayeredGround<Real>& ground, const LayeredWater<Real>& water, const LayeredParams& params,
                  int nx, int ny, int k) {
  const std::size_t n = ground.cell(nx, ny);
  if (!(water.water[n] > Real(0))) return 0;
  const Real mean = mean_depth(water, params, n);
  if (mean <= Real(0)) return 0;
  const NetFlux<Real> flux = net_flux(ground, water, params, nx, ny);
  // Pipe k of the target points at n; n's water comes back along −offset_k.
  const Real toward = k == 0 ? flux.x : k == 1 ? -flux.x : k == 2 ? -flux.y : flux.y;
  if (!(toward > Real(0))) return 0;
  const double face = k < 2 ? ground.cell_size_y : ground.cell_size_x;
  return toward / (static_cast<Real>(face) * mean);
}

// Erodes soil layer `layer` of c with impact strength `strength` into `load` (suspended sizes).
template <class Real>
void erode_soil_layer(LayeredGround<Real>& ground, std::size_t c, int layer, Real strength,
                      const LayeredParams& params, std::array<Real, soil_component_count>& load,
                      ImpactTally<Real>& tally) {
  const auto erosion_rate = static_cast<Real>(params.erosion_rate);
  const Real organic = erosion_rate * (static_cast<Real>(params.organic_capacity) * strength);
  Real taken_total = 0;
  if (organic > Real(0) && ground.soil_at(layer, 0, c) > Real(0)) {
    const Real taken = take_from_layer(ground, c, layer, 0, organic, params);
    load[0] += taken;
    taken_total += taken;
  }
  for (int size = 0; size < fragment_size_count; ++size) {
    for (int source = size; source < fragment_size_count; ++source) {
      const auto i = std::size_t(size), j = std::size_t(source);
      const Real request = erosion_rate * breakdown(params.breakdown_form, params.breakdown_slopes[j][i],
                                                    params.breakdown_thresholds[j][i], strength);
      if (!(request > Real(0)) || !(ground.soil_at(layer, source + 1, c) > Real(0))) continue;
      const Real taken = take_from_layer(ground, c, layer, source + 1, request, params);
      load[i + 1] += taken;
      taken_total += taken;
      if (source != size) tally.broken[j][i] += taken;
    }
  }
  ground.surface[c] -= taken_total;
}

template <class Real>
void erode_bedrock_layer(LayeredGround<Real>& ground, std::size_t c, int layer, Real strength,
                         const LayeredParams& params, std::array<Real, soil_component_count>& load,
                         ImpactTally<Real>& tally) {
  const int type = ground.bedrock_type_at(layer, c);
  if (tally.bedrock_type >= 0 && type != tally.bedrock_type) return;  // one type a column a step (header)
  const BedrockType& rock = params.bedrock_types[std::size_t(type)];
  for (int size = 0; size < fragment_size_count; ++size) {
    const auto i = std::size_t(size);
    const Real request = static_cast<Real>(params.erosion_rate) *
                         breakdown(params.breakdown_form, rock.erosion_slopes[i], rock.erosion_thresholds[i], strength);
    Real& thickness = ground.bedrock_at(layer, c);
    if (!(request > Real(0)) || !(thickness > Real(0))) continue;
    const Real taken = std::min(request, thickness);
    thickness -= taken;
    ground.surface[c] -= taken;
    load[i + 1] += taken;
    tally.bedrock[i] += taken;
    tally.bedrock_type = type;
  }
}

// Pass 1 for target (x, y): the loads of its 4 pipes.
template <class Real>
PipeLoads<Real> impact_column(LayeredGround<Real>& ground, const LayeredWater<Real>& water,
                              const std::vector<Real>& surface_before, const LayeredParams& params, int x, int y,
                              ImpactTally<Real>& tally) {
  PipeLoads<Real> loads{};
  const std::size_t c = ground.cell(x, y);
  const auto scale = static_cast<Real>(params.impact_rate * params.time_step /
                                       (ground.cell_size_x * ground.cell_size_y));
  for (int k = 0; k < water_pipe_count; ++k) {
    const auto n = layered_neighbour(ground, params.border, x, y, k);
    if (!n) continue;
    const int nx = int(*n % std::size_t(ground.width)), ny = int(*n / std::size_t(ground.width));
    const Real speed = speed_toward(ground, water, params, nx, ny, k);
    if (!(speed > Real(0))) continue;
    const auto face = static_cast<Real>(k < 2 ? ground.cell_size_y : ground.cell_size_x);
    const Real water_top = surface_before[*n] + water.water[*n];
    const Real water_bottom = surface_before[*n];
    Real top = ground.surface[c];
    const auto erode_if_touched = [&](Real thickness, auto erode) {
      const Real bottom = top - thickness;
      const Real contact = face * std::max(std::min(top, water_top) - std::max(bottom, water_bottom), Real(0));
      if (contact > Real(0)) erode(scale * speed * contact);
      top = bottom;
    };
    for (int layer = 0; layer < soil_layer_count; ++layer) {
      const Real thickness = ground.soil_thickness(layer, c);
      if (!(thickness > Real(0))) continue;
      erode_if_touched(thickness, [&](Real strength) {
        erode_soil_layer(ground, c, layer, strength, params, loads[std::size_t(k)], tally);
      });
    }
    for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
      const Real thickness = ground.bedrock_at(layer, c);
      if (!(thickness > Real(0))) continue;
      erode_if_touched(thickness, [&](Real strength) {
        erode_bedrock_layer(ground, c, layer, strength, params, loads[std::size_t(k)], tally);
      });
      break;
    }
  }
  return loads;
}

template <class Real>
void count(const ImpactTally<Real>& tally, double area, LayeredConversions& conversions) {
  for (std::size_t i = 0; i < fragment_size_count; ++i) {
    for (std::size_t j = i + 1; j < fragment_size_count; ++j) {
      if (!(tally.broken[j][i] > Real(0))) continue;
      conversions.broken_from[j + 1] += static_cast<double>(tally.broken[j][i]) * area;
      conversions.broken_into[i + 1] += static_cast<double>(tally.broken[j][i]) * area;
    }
    if (!(tally.bedrock[i] > Real(0))) continue;
    conversions.bedrock_eroded_from.at(std::size_t(tally.bedrock_type)) += static_cast<double>(tally.bedrock[i]) * area;
    conversions.bedrock_eroded_into[i + 1] += static_cast<double>(tally.bedrock[i]) * area;
  }
}

}  // namespace

template <class Real>
void impact_erosion_step(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                         LayeredConversions& conversions) {
  if (params.impact_rate <= 0.0) return;
  conversions.fit_types(params.bedrock_types.size());
  const double area = ground.cell_size_x * ground.cell_size_y;
  const std::vector<Real> surface_before = ground.surface;
  std::vector<PipeLoads<Real>> loads(ground.cells());
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      ImpactTally<Real> tally;
      loads[ground.cell(x, y)] = impact_column(ground, water, surface_before, params, x, y, tally);
      count(tally, area, conversions);
    }
  }
  if (mutant_active("erosion.layered.impact_never_delivered")) return;  // mutant: the pipes are never emptied
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t n = ground.cell(x, y);
      for (int k = 0; k < water_pipe_count; ++k) {
        const auto from = layered_neighbour(ground, params.border, x, y, k);
        if (!from) continue;
        for (int kind = 0; kind < soil_component_count; ++kind) {
          water.carried_at(suspended_kind(kind), n) += loads[*from][std::size_t(k ^ 1)][std::size_t(kind)];
        }
      }
    }
  }
}

template void impact_erosion_step(LayeredGround<float>&, LayeredWater<float>&, const LayeredParams&,
                                  LayeredConversions&);
template void impact_erosion_step(LayeredGround<double>&, LayeredWater<double>&, const LayeredParams&,
                                  LayeredConversions&);

}  // namespace gt::reference
