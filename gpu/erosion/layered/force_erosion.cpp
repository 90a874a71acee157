// Host side of force erosion on the layered ground (digest 001 §3.12; see force_erosion.hpp).
#include "gpu/erosion/layered/force_erosion.hpp"

#include <cstddef>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

constexpr std::size_t record_floats = 24;  // RECORD of force_erosion.comp
constexpr std::size_t bedrock_at = 16, type_at = 20;

// The reference's counting (erode_into_size): per column, for each result size i, the larger
// sources j broken into it, then the bedrock eroded into it.
void count(const std::vector<float>& records, std::size_t cells, double area, LayeredConversions& conversions) {
  for (std::size_t c = 0; c < cells; ++c) {
    const float* record = records.data() + c * record_floats;
    for (std::size_t i = 0; i < fragment_size_count; ++i) {
      for (std::size_t j = i + 1; j < fragment_size_count; ++j) {
        const float taken = record[fragment_size_count * j + i];
        if (!(taken > 0.0f) || mutant_active("erosion.layered.breakdown_uncounted")) continue;
        conversions.broken_from[j + 1] += static_cast<double>(taken) * area;
        conversions.broken_into[i + 1] += static_cast<double>(taken) * area;
      }
      const float eroded = record[bedrock_at + i];
      if (!(eroded > 0.0f)) continue;
      conversions.bedrock_eroded_from.at(static_cast<std::size_t>(record[type_at + i])) +=
          static_cast<double>(eroded) * area;
      conversions.bedrock_eroded_into[i + 1] += static_cast<double>(eroded) * area;
    }
  }
}

}  // namespace

LayeredForceErosion::LayeredForceErosion() : program_(ComputeProgram::load("erosion/layered/force_erosion.comp")) {}

void LayeredForceErosion::step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
                               LayeredConversions& conversions) const {
  water.snapshot_surface(ground);
  water.bind();
  ground.dispatch_pass(program_, step);
  conversions.fit_types(ground.params().bedrock_types.size());
  count(water.records(record_floats), ground.shape().cells(),
        ground.shape().cell_size_x * ground.shape().cell_size_y, conversions);
}

}  // namespace gt::gpu
