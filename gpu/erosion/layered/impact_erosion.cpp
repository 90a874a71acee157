// Host side of impact erosion on the layered ground (digest 001 §3.14; see impact_erosion.hpp).
#include "gpu/erosion/layered/impact_erosion.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace gt::gpu {
namespace {

// RECORD of impact_erosion.comp: breakdown at [20 + 4j + i], bedrock at [36 + i], one type at [40].
constexpr ErosionRecordLayout record_layout{48, 20, 36, 40, 0};

}  // namespace

LayeredImpactErosion::LayeredImpactErosion()
    : erode_(layered_water_program("erosion/layered/impact_erosion.comp")),
      gather_(layered_water_program("erosion/layered/impact_erosion.comp",
                                    std::vector<std::string>{"IMPACT_GATHER"})) {}

void LayeredImpactErosion::step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
                                LayeredConversions& conversions) const {
  if (ground.params().impact_rate <= 0.0) return;
  water.snapshot_surface(ground);
  water.bind();
  ground.dispatch_pass(erode_, step);
  ground.dispatch_pass(gather_, step);
  conversions.fit_types(ground.params().bedrock_types.size());
  count_erosion_records(water.records(record_layout.floats), ground.shape().cells(),
                        ground.shape().cell_size_x * ground.shape().cell_size_y, record_layout, true, conversions);
}

}  // namespace gt::gpu
