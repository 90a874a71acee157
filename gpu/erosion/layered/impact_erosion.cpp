// Host side of impact erosion on the layered ground (digest 001 §3.14; see impact_erosion.hpp).
#include "gpu/erosion/layered/impact_erosion.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace gt::gpu {
namespace {

constexpr std::size_t record_floats = 48;  // RECORD of impact_erosion.comp
constexpr std::size_t broken_at = 20, rock_at = 36, rock_type_at = 40;

// The reference's counting (impact_erosion.cpp's count): per column, for each result size i, the
// larger sizes j broken into it, then the bedrock eroded into it.
void count(const std::vector<float>& records, std::size_t cells, double area, LayeredConversions& conversions) {
  for (std::size_t c = 0; c < cells; ++c) {
    const float* record = records.data() + c * record_floats;
    for (std::size_t i = 0; i < fragment_size_count; ++i) {
      for (std::size_t j = i + 1; j < fragment_size_count; ++j) {
        const float broken = record[broken_at + fragment_size_count * j + i];
        if (!(broken > 0.0f)) continue;
        conversions.broken_from[j + 1] += static_cast<double>(broken) * area;
        conversions.broken_into[i + 1] += static_cast<double>(broken) * area;
      }
      const float eroded = record[rock_at + i];
      if (!(eroded > 0.0f)) continue;
      conversions.bedrock_eroded_from.at(static_cast<std::size_t>(record[rock_type_at])) +=
          static_cast<double>(eroded) * area;
      conversions.bedrock_eroded_into[i + 1] += static_cast<double>(eroded) * area;
    }
  }
}

}  // namespace

LayeredImpactErosion::LayeredImpactErosion()
    : erode_(ComputeProgram::load("erosion/layered/impact_erosion.comp")),
      gather_(ComputeProgram::load("erosion/layered/impact_erosion.comp", std::vector<std::string>{"IMPACT_GATHER"})) {}

void LayeredImpactErosion::step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
                                LayeredConversions& conversions) const {
  if (ground.params().impact_rate <= 0.0) return;
  water.snapshot_surface(ground);
  water.bind();
  ground.dispatch_pass(erode_, step);
  ground.dispatch_pass(gather_, step);
  conversions.fit_types(ground.params().bedrock_types.size());
  count(water.records(record_floats), ground.shape().cells(), ground.shape().cell_size_x * ground.shape().cell_size_y,
        conversions);
}

}  // namespace gt::gpu
