// Host side of force erosion on the layered ground (digest 001 §3.12; see force_erosion.hpp).
#include "gpu/erosion/layered/force_erosion.hpp"

#include <cstddef>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

// RECORD of force_erosion.comp: breakdown at [4j + i], bedrock at [16 + i], its type at [20 + i].
constexpr ErosionRecordLayout record_layout{24, 0, 16, 20, 1};

}  // namespace

LayeredForceErosion::LayeredForceErosion() : program_(layered_water_program("erosion/layered/force_erosion.comp")) {}

void LayeredForceErosion::step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
                               LayeredConversions& conversions) const {
  water.snapshot_surface(ground);
  water.bind();
  ground.dispatch_pass(program_, step);
  conversions.fit_types(ground.params().bedrock_types.size());
  count_erosion_records(water.records(record_layout.floats), ground.shape().cells(),
                        ground.shape().cell_size_x * ground.shape().cell_size_y, record_layout,
                        !mutant_active("erosion.layered.breakdown_uncounted"), conversions);
}

}  // namespace gt::gpu
