// Construction, checks, river columns and ledger of the water on the layered ground (see
// layered_water.hpp).
#include "core/layered/layered_water.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/sum.hpp"

namespace gt {
namespace {

template <class Real>
void require_amounts(const std::vector<Real>& values, std::size_t size, const char* name) {
  if (values.size() != size) {
    throw InputError(fmt::format("erosion.layered: the water's {} has {} values, not {}", name, values.size(), size));
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto value = static_cast<double>(values[i]);
    if (!std::isfinite(value) || value < 0.0) {
      throw InputError(fmt::format("erosion.layered: the water's {} at {} is {}: it must be finite and >= 0", name, i,
                                   value));
    }
  }
}

}  // namespace

template <class Real>
LayeredWater<Real> make_layered_water(std::size_t cells, double depth) {
  LayeredWater<Real> water;
  water.water.assign(cells, static_cast<Real>(depth));
  water.previous_water = water.water;
  water.water_flux.assign(cells * water_pipe_count, Real(0));
  water.carried.assign(cells * carried_kind_count, Real(0));
  water.wetness.assign(cells, Real(0));
  return water;
}

template <class Real>
void check_layered_water(const LayeredWater<Real>& water, std::size_t cells) {
  require_amounts(water.water, cells, "depth");
  require_amounts(water.previous_water, cells, "previous depth");
  require_amounts(water.water_flux, cells * water_pipe_count, "flux");
  require_amounts(water.carried, cells * carried_kind_count, "carried material");
  require_amounts(water.wetness, cells, "wetness");
}

std::size_t river_source_cell(int width, int height) {
  return static_cast<std::size_t>(height / 16) * static_cast<std::size_t>(width) + static_cast<std::size_t>(width / 2);
}

bool river_sink_row(int y, int height) { return 16LL * y >= 15LL * height; }

template <class Real>
LayeredWaterLedger layered_water_ledger(const LayeredWater<Real>& water, double cell_area) {
  const std::size_t cells = water.water.size();
  CompensatedSum depth;
  std::array<CompensatedSum, soil_component_count> carried;
  for (std::size_t c = 0; c < cells; ++c) {
    depth.add(static_cast<double>(water.water[c]) * cell_area);
    for (int kind = 0; kind < carried_kind_count; ++kind) {
      carried[static_cast<std::size_t>(carried_component(kind))].add(static_cast<double>(water.carried_at(kind, c)) *
                                                                      cell_area);
    }
  }
  LayeredWaterLedger ledger;
  ledger.water = depth.value();
  for (std::size_t i = 0; i < carried.size(); ++i) ledger.carried[i] = carried[i].value();
  return ledger;
}

#define GT_LAYERED_WATER_INSTANTIATE(Real)                                          \
  template LayeredWater<Real> make_layered_water(std::size_t, double);              \
  template void check_layered_water(const LayeredWater<Real>&, std::size_t);        \
  template LayeredWaterLedger layered_water_ledger(const LayeredWater<Real>&, double);
GT_LAYERED_WATER_INSTANTIATE(float)
GT_LAYERED_WATER_INSTANTIATE(double)
#undef GT_LAYERED_WATER_INSTANTIATE

}  // namespace gt
