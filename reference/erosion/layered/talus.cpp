// Per-material talus collapse on the layered ground (digest 001 §3.10, eq. 3.1-3.3; decisions and
// units in talus.hpp).
#include "reference/erosion/layered/talus.hpp"

#include <algorithm>
#include <limits>

#include "core/mutant.hpp"
#include "reference/erosion/layered/column.hpp"

namespace gt::reference {
namespace {

template <class Real>
constexpr Real unbounded = std::numeric_limits<Real>::infinity();

// (Σ_i tan φ_i·V_i)/V of soil layer `layer` (eq. 3.1 without the vegetation factor).
template <class Real>
Real layer_repose(const LayeredGround<Real>& ground, const LayeredParams& params, int layer, std::size_t c,
                  Real thickness) {
  Real weighted = 0;
  for (int component = 0; component < soil_component_count; ++component) {
    weighted += static_cast<Real>(params.repose_tan[static_cast<std::size_t>(component)]) *
                ground.soil_at(layer, component, c);
  }
  return weighted / thickness;
}

// The least tan φ of column c's non-empty bedrock layers whose top lies above `lowest_neighbour`.
template <class Real>
Real bedrock_repose(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c,
                    Real lowest_neighbour) {
  Real repose = unbounded<Real>;
  Real layer_top = ground.surface[c];
  for (int layer = 0; layer < ground.bedrock_layer_count && layer_top > lowest_neighbour; ++layer) {
    const Real thickness = ground.bedrock_at(layer, c);
    if (thickness > Real(0)) {
      const auto& type = params.bedrock_types[static_cast<std::size_t>(ground.bedrock_type_at(layer, c))];
      repose = std::min(repose, static_cast<Real>(type.repose_tan));
    }
    layer_top -= thickness;
  }
  return repose;
}

// Δh_k where slope_k ≥ tan φ, else 0.
template <class Real>
NeighbourAmounts<Real> unstable_drops(const LayeredGround<Real>& ground, std::size_t c,
                                      const NeighbourAmounts<Real>& surfaces, Real threshold) {
  NeighbourAmounts<Real> drops{};
  for (int k = 0; k < layered_neighbour_count; ++k) {
    const Real drop = ground.surface[c] - surfaces[static_cast<std::size_t>(k)];
    const auto distance = static_cast<Real>(layered_neighbour_distance(ground.cell_size_x, ground.cell_size_y, k));
    if (drop > Real(0) && drop / distance >= threshold) drops[static_cast<std::size_t>(k)] = drop;
  }
  return drops;
}

// Thesis eq. 3.3: Δt·Δh_k·rand_k/2 per neighbour, then the availability clamp.
template <class Real>
NeighbourAmounts<Real> thesis_amounts(const NeighbourAmounts<Real>& drops, Real available, const LayeredParams& params,
                                      std::size_t c, std::uint32_t step) {
  NeighbourAmounts<Real> amounts{};
  const auto time_step = static_cast<Real>(params.time_step);
  for (int k = 0; k < layered_neighbour_count; ++k) {
    const Real drop = drops[static_cast<std::size_t>(k)];
    if (drop <= Real(0)) continue;
    const Real random = random_factor<Real>(params.talus_random, params.seed, c, step, talus_neighbour_stream(k));
    amounts[static_cast<std::size_t>(k)] = time_step * drop * random * Real(0.5);
  }
  clamp_to_available(amounts, available);
  return amounts;
}

// The code's min(½·max Δh·rand, h_layer) split ∝ Δh_k.
template <class Real>
NeighbourAmounts<Real> code_amounts(const NeighbourAmounts<Real>& drops, Real available, const LayeredParams& params,
                                    std::size_t c, std::uint32_t step) {
  Real largest = 0;
  Real sum = 0;
  for (Real drop : drops) {
    largest = std::max(largest, drop);
    sum += drop;
  }
  NeighbourAmounts<Real> amounts{};
  if (sum <= Real(0)) return amounts;
  const Real random = random_factor<Real>(params.talus_random, params.seed, c, step, talus_cell_stream);
  const Real total = std::min(Real(0.5) * largest * random, available);
  for (std::size_t k = 0; k < amounts.size(); ++k) amounts[k] = total * (drops[k] / sum);
  return amounts;
}

template <class Real>
NeighbourAmounts<Real> column_outflow(const LayeredGround<Real>& ground, const LayeredParams& params, int x, int y,
                                      std::uint32_t step) {
  const std::size_t c = ground.cell(x, y);
  const int layer = top_nonempty_layer(ground, c);
  if (layer < 0) return {};
  const NeighbourAmounts<Real> surfaces = neighbour_surfaces(ground, params.border, x, y);
  const bool soil = layer < soil_layer_count;
  const Real threshold = soil ? soil_repose(ground, params, c)
                              : bedrock_repose(ground, params, c, *std::min_element(surfaces.begin(), surfaces.end()));
  const Real available = soil ? ground.soil_thickness(layer, c) : ground.bedrock_at(layer - soil_layer_count, c);
  const NeighbourAmounts<Real> drops = unstable_drops(ground, c, surfaces, threshold);
  return params.talus_amount == TalusAmount::thesis ? thesis_amounts(drops, available, params, c, step)
                                                    : code_amounts(drops, available, params, c, step);
}

}  // namespace

template <class Real>
Real soil_repose(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c) {
  const Real vegetation_factor = Real(1) + static_cast<Real>(params.vegetation_repose) * ground.vegetation[c];
  // Mutant: every soil layer stands at twice its repose slope.
  Real depth_factor = mutant_active("erosion.layered.repose_doubled") ? Real(2) : Real(1);
  Real least = unbounded<Real>;
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const Real thickness = ground.soil_thickness(layer, c);
    if (thickness > Real(0)) {
      least = std::min(least, depth_factor * layer_repose(ground, params, layer, c, thickness) * vegetation_factor);
    }
    depth_factor *= static_cast<Real>(params.depth_factor);
  }
  return least;
}

template <class Real>
Outflows<Real> talus_outflows(const LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step) {
  Outflows<Real> outflows(ground.cells());
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) outflows[ground.cell(x, y)] = column_outflow(ground, params, x, y, step);
  }
  return outflows;
}

template <class Real>
void talus_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                LayeredConversions& conversions) {
  const Outflows<Real> outflows = talus_outflows(ground, params, step);
  apply_outflows(ground, outflows, params, true, conversions);
}

#define GT_LAYERED_TALUS_INSTANTIATE(Real)                                                              \
  template Real soil_repose(const LayeredGround<Real>&, const LayeredParams&, std::size_t);             \
  template Outflows<Real> talus_outflows(const LayeredGround<Real>&, const LayeredParams&, std::uint32_t); \
  template void talus_step(LayeredGround<Real>&, const LayeredParams&, std::uint32_t, LayeredConversions&);
GT_LAYERED_TALUS_INSTANTIATE(float)
GT_LAYERED_TALUS_INSTANTIATE(double)
#undef GT_LAYERED_TALUS_INSTANTIATE

}  // namespace gt::reference
