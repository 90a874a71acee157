// One iteration of the layered ground in the code's order (digest 001 §4; see iteration.hpp).
#include "reference/erosion/layered/iteration.hpp"

#include "reference/erosion/layered/creep.hpp"
#include "reference/erosion/layered/talus.hpp"
#include "reference/erosion/layered/vegetation.hpp"
#include "reference/erosion/layered/weathering.hpp"

namespace gt::reference {

template <class Real>
void layered_iteration(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                       LayeredConversions& conversions) {
  creep_step(ground, params, step, conversions);
  talus_step(ground, params, step, conversions);
  vegetation_step(ground, params, step, conversions);
  weathering_step(ground, params, step, conversions);
}

template void layered_iteration(LayeredGround<float>&, const LayeredParams&, std::uint32_t, LayeredConversions&);
template void layered_iteration(LayeredGround<double>&, const LayeredParams&, std::uint32_t, LayeredConversions&);

}  // namespace gt::reference
