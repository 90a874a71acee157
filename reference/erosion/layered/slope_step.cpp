// Creep then talus, the code's order (digest 001 §4; see slope_step.hpp).
#include "reference/erosion/layered/slope_step.hpp"

#include "reference/erosion/layered/creep.hpp"
#include "reference/erosion/layered/talus.hpp"

namespace gt::reference {

template <class Real>
void slope_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                LayeredConversions& conversions) {
  creep_step(ground, params, step, conversions);
  talus_step(ground, params, step, conversions);
}

template void slope_step(LayeredGround<float>&, const LayeredParams&, std::uint32_t, LayeredConversions&);
template void slope_step(LayeredGround<double>&, const LayeredParams&, std::uint32_t, LayeredConversions&);

}  // namespace gt::reference
