// Host side of the water's sources, sinks and pipe flow on the layered ground (see water.hpp).
#include "gpu/erosion/layered/water.hpp"

#include <cmath>
#include <cstddef>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

constexpr std::size_t source_record_floats = 8;  // water.comp's record: the water, then 7 carried kinds

// The reference's counting (water_sources): the rain once for all columns, the river's source, then
// the sink rows in column order.
void count(const LayeredWaterBuffers& water, const LayeredGround<float>& shape, LayeredConversions& conversions) {
  const LayeredWaterBlock& block = water.block();
  const double area = shape.cell_size_x * shape.cell_size_y;
  if (block.rain_depth > 0.0f && !mutant_active("erosion.layered.rain_uncounted")) {
    conversions.water_added += static_cast<double>(block.rain_depth) * area * static_cast<double>(shape.cells());
  }
  if (block.river == 0) return;
  const auto records = water.records(source_record_floats);
  const auto source = static_cast<std::size_t>(block.river_source);
  const double change = static_cast<double>(block.river_depth) - static_cast<double>(records[source * source_record_floats]);
  (change >= 0.0 ? conversions.water_added : conversions.water_sunk) += std::abs(change) * area;
  for (int y = block.sink_row_start; y < shape.height; ++y) {
    for (int x = 0; x < shape.width; ++x) {
      const float* record = records.data() + shape.cell(x, y) * source_record_floats;
      conversions.water_sunk += static_cast<double>(record[0]) * area;
      for (int kind = 0; kind < carried_kind_count && !mutant_active("erosion.layered.sinks_uncounted"); ++kind) {
        conversions.sunk[static_cast<std::size_t>(carried_component(kind))] +=
            static_cast<double>(record[1 + kind]) * area;
      }
    }
  }
}

}  // namespace

LayeredWaterFlow::LayeredWaterFlow()
    : sources_(layered_water_program("erosion/layered/water_sources.comp")),
      flux_(layered_water_program("erosion/layered/water_flux.comp")),
      move_(layered_water_program("erosion/layered/water_move.comp")) {}

void LayeredWaterFlow::sources(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
                               LayeredConversions& conversions) const {
  if (water.block().rain_depth <= 0.0f && water.block().river == 0) return;
  water.bind();
  ground.dispatch_pass(sources_, step);
  count(water, ground.shape(), conversions);
}

void LayeredWaterFlow::flow(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step) const {
  water.bind();
  ground.dispatch_pass(flux_, step);
  water.snapshot();
  ground.dispatch_pass(move_, step);
}

}  // namespace gt::gpu
