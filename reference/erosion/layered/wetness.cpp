// Wetness of the layered ground (digest 001 §3.15, eq. 3.12; see wetness.hpp).
#include "reference/erosion/layered/wetness.hpp"

#include <cmath>

namespace gt::reference {

template <class Real>
void wetness_step(LayeredWater<Real>& water, const LayeredParams& params) {
  const auto time_step = static_cast<Real>(params.time_step);
  const auto drying = static_cast<Real>(std::pow(params.drying, params.time_step));
  for (std::size_t c = 0; c < water.water.size(); ++c) {
    const Real depth = water.water[c];
    const Real wetness = depth > Real(0) ? water.wetness[c] + time_step * depth : water.wetness[c] * drying;
    water.wetness[c] = wetness < static_cast<Real>(negligible_amount) ? Real(0) : wetness;
  }
}

template void wetness_step(LayeredWater<float>&, const LayeredParams&);
template void wetness_step(LayeredWater<double>&, const LayeredParams&);

}  // namespace gt::reference
