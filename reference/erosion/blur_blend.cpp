// Beyer's blend with a blurred map (seed 000 eq. 2.43), CPU reference; the decisions are in
// reference/erosion/blur_blend.hpp. Each operation is spelled out in the shader's order
// (gpu/shaders/erosion/blur_blend.comp).
#include "reference/erosion/blur_blend.hpp"

#include <cmath>

#include "core/mutant.hpp"
#include "reference/erosion/moore_pipes.hpp"

namespace gt::reference {
namespace {

// The weight of one exchange of the cell (x, y): Real(c_b/9); under the mutant the box blur
// renormalised over the samples it finds, Real(c_b/(1 + open neighbours)).
template <class Real>
Real exchange_weight(const Grid<Real>& heights, int x, int y, double blend, bool renormalised) {
  if (!renormalised) return static_cast<Real>(blend / 9.0);
  int open = 0;
  for (int k = 0; k < 8; ++k) open += pipe_open(heights, x, y, k) ? 1 : 0;
  return static_cast<Real>(blend / (1.0 + open));
}

// Calls visit(exchange) with w·(h_b - h_a) for each neighbour b of the valid cell (x, y) through
// an open pipe (moore_pipes.hpp: inside the grid and valid), in pipe order.
template <class Real, class Visit>
void for_each_exchange(const Grid<Real>& heights, int x, int y, Real weight, Visit visit) {
  const Real own = heights.at(x, y);
  for (int k = 0; k < 8; ++k) {
    if (!pipe_open(heights, x, y, k)) continue;
    const Real difference = heights.at(x + moore_pipes[k].dx, y + moore_pipes[k].dy) - own;
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
      if (!before.is_valid(x, y)) continue;
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
      if (!heights.is_valid(x, y)) continue;
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
