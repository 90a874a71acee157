// Beyer's blend with a blurred map (seed 000 eq. 2.43), CPU reference; the decisions are in
// reference/erosion/blur_blend.hpp. Each operation is spelled out in the shader's order
// (gpu/shaders/erosion/blur_blend.comp).
#include "reference/erosion/blur_blend.hpp"

#include <cmath>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

// Whether the sample (x, y) takes part in the blend: inside the grid and valid.
template <class Real>
bool open_sample(const Grid<Real>& heights, int x, int y) {
  return heights.inside(x, y) && heights.is_valid(x, y);
}

// The weight of one exchange of the cell (x, y): Real(c_b/9); under the mutant the box blur
// renormalised over the samples it finds, Real(c_b/(1 + open neighbours)).
template <class Real>
Real exchange_weight(const Grid<Real>& heights, int x, int y, double blend, bool renormalised) {
  if (!renormalised) return static_cast<Real>(blend / 9.0);
  int open = 0;
  for (const CellOffset offset : moore_offsets) open += open_sample(heights, x + offset.dx, y + offset.dy) ? 1 : 0;
  return static_cast<Real>(blend / (1.0 + open));
}

// Calls visit(exchange) with w·(h_b - h_a) for each open neighbour b of the open cell (x, y), in
// the order of moore_offsets.
template <class Real, class Visit>
void for_each_exchange(const Grid<Real>& heights, int x, int y, Real weight, Visit visit) {
  const Real own = heights.at(x, y);
  for (const CellOffset offset : moore_offsets) {
    if (!open_sample(heights, x + offset.dx, y + offset.dy)) continue;
    const Real difference = heights.at(x + offset.dx, y + offset.dy) - own;
    visit(weight * difference);
  }
}

bool renormalised_mutant(const std::string& algorithm) {
  return mutant_active(algorithm + ".blur_renormalised_at_border");
}

}  // namespace

template <class Real>
void blur_blend(Grid<Real>& heights, double blend, const std::string& algorithm) {
  if (blend == 0.0) return;
  const bool renormalised = renormalised_mutant(algorithm);
  const Grid<Real> before = heights;
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      if (!open_sample(before, x, y)) continue;
      Real received = 0;
      for_each_exchange(before, x, y, exchange_weight(before, x, y, blend, renormalised),
                        [&](Real exchange) { received = received + exchange; });
      heights.at(x, y) = before.at(x, y) + received;
    }
  }
}

template <class Real>
void blur_blend_quanta(const Grid<Real>& heights, double blend, Real inverse_quantum, BatchDelta<Real>& delta,
                       const std::string& algorithm) {
  if (blend == 0.0) return;
  const bool renormalised = renormalised_mutant(algorithm);
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      if (!open_sample(heights, x, y)) continue;
      long long received = 0;
      for_each_exchange(heights, x, y, exchange_weight(heights, x, y, blend, renormalised), [&](Real exchange) {
        const Real scaled = exchange * inverse_quantum;
        received += static_cast<long long>(std::nearbyint(scaled));
      });
      delta.add(heights.index(x, y), received);
    }
  }
}

template void blur_blend(Grid<double>&, double, const std::string&);
template void blur_blend(Grid<float>&, double, const std::string&);
template void blur_blend_quanta(const Grid<double>&, double, double, BatchDelta<double>&, const std::string&);
template void blur_blend_quanta(const Grid<float>&, double, float, BatchDelta<float>&, const std::string&);

}  // namespace gt::reference
