// One iteration of the layered ground in the code's order (digest 001 §4; see iteration.hpp).
#include "reference/erosion/layered/iteration.hpp"

#include "reference/erosion/layered/creep.hpp"
#include "reference/erosion/layered/diffusion.hpp"
#include "reference/erosion/layered/dissolution.hpp"
#include "reference/erosion/layered/force_erosion.hpp"
#include "reference/erosion/layered/impact_erosion.hpp"
#include "reference/erosion/layered/talus.hpp"
#include "reference/erosion/layered/vegetation.hpp"
#include "reference/erosion/layered/water.hpp"
#include "reference/erosion/layered/weathering.hpp"
#include "reference/erosion/layered/wetness.hpp"

namespace gt::reference {

template <class Real>
void layered_iteration(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                       LayeredConversions& conversions, LayeredWater<Real>* water) {
  if (water != nullptr) water_sources(ground, *water, params, step, conversions);
  creep_step(ground, params, step, conversions);
  if (params.talus) talus_step(ground, params, step, conversions);
  if (water != nullptr) {
    water_flow(ground, *water, params);
    force_erosion_step(ground, *water, params, conversions);
    impact_erosion_step(ground, *water, params, conversions);
    dissolution_step(ground, *water, params);
    diffusion_step(ground, *water, params);
    wetness_step(*water, params);
  }
  vegetation_step(ground, params, step, conversions, water);
  weathering_step(ground, params, step, conversions);
}

template void layered_iteration(LayeredGround<float>&, const LayeredParams&, std::uint32_t, LayeredConversions&,
                                LayeredWater<float>*);
template void layered_iteration(LayeredGround<double>&, const LayeredParams&, std::uint32_t, LayeredConversions&,
                                LayeredWater<double>*);

}  // namespace gt::reference
