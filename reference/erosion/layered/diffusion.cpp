// Sediment diffusion on the layered ground (digest 001 §3.8; see diffusion.hpp).
#include "reference/erosion/layered/diffusion.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

template <class Real>
using Shares = std::array<Real, water_pipe_count>;
using Neighbours = std::array<std::optional<std::size_t>, water_pipe_count>;

// The edge neighbours L, R, T, B of column (x, y) (none outside a closed border).
template <class Real>
Neighbours edge_neighbours(const LayeredGround<Real>& ground, const LayeredParams& params, int x, int y) {
  Neighbours neighbours;
  for (int k = 0; k < water_pipe_count; ++k) neighbours[std::size_t(k)] = layered_neighbour(ground, params.border, x, y, k);
  return neighbours;
}

// σ_k of column (x, y) toward its edge neighbours.
template <class Real>
Shares<Real> diffusion_shares(const LayeredGround<Real>& ground, const LayeredWater<Real>& water,
                              const LayeredParams& params, int x, int y) {
  Shares<Real> shares{};
  const Neighbours neighbours = edge_neighbours(ground, params, x, y);
  if (params.diffusion_weighting == DiffusionWeighting::uniform) {
    const auto weight = static_cast<Real>(params.sediment_diffusion);
    for (int k = 0; k < water_pipe_count; ++k) shares[std::size_t(k)] = neighbours[std::size_t(k)] ? weight : Real(0);
    return shares;
  }
  Shares<Real> neighbour_weights{};
  Real base = water.water[ground.cell(x, y)];
  for (int k = 0; k < water_pipe_count; ++k) {
    const auto& n = neighbours[std::size_t(k)];
    if (!n) continue;
    neighbour_weights[std::size_t(k)] = Real(0.5) * water.water[*n];
    base += neighbour_weights[std::size_t(k)];
  }
  if (!(base > Real(0))) return shares;
  for (int k = 0; k < water_pipe_count; ++k) shares[std::size_t(k)] = neighbour_weights[std::size_t(k)] / base;
  return shares;
}

}  // namespace

template <class Real>
void diffusion_step(const LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params) {
  if (params.sediment_diffusion <= 0.0) return;
  const std::size_t cells = ground.cells();
  std::vector<Shares<Real>> shares(cells);
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) shares[ground.cell(x, y)] = diffusion_shares(ground, water, params, x, y);
  }
  const std::vector<Real> before = water.carried;
  const int kinds = params.regolith_diffusion ? carried_kind_count : soil_component_count;
  // Mutant: each column sends its shares and keeps them as well.
  const bool sent_leaves = !mutant_active("erosion.layered.diffusion_sent_kept");
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t c = ground.cell(x, y);
      const Neighbours neighbours = edge_neighbours(ground, params, x, y);
      for (int kind = 0; kind < kinds; ++kind) {
        const std::size_t offset = std::size_t(kind) * cells;
        const Real amount = before[offset + c];
        Real sent = 0;
        for (const Real share : shares[c]) sent += amount * share;
        Real result = sent_leaves ? std::max(amount - sent, Real(0)) : amount;
        for (int k = 0; k < water_pipe_count; ++k) {
          const auto& n = neighbours[std::size_t(k)];
          if (n) result += before[offset + *n] * shares[*n][std::size_t(k ^ 1)];
        }
        water.carried[offset + c] = result;
      }
    }
  }
}

template void diffusion_step(const LayeredGround<float>&, LayeredWater<float>&, const LayeredParams&);
template void diffusion_step(const LayeredGround<double>&, LayeredWater<double>&, const LayeredParams&);

}  // namespace gt::reference
