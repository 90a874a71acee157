// Host side of the water's sources, sinks and pipe flow on the layered ground (see water.hpp).
#include "gpu/erosion/layered/water.hpp"

#include <cmath>
#include <cstddef>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

constexpr std::size_t source_record_floats = 8;  // water.comp's record: the water, then 7 carried kinds

// What a sink column took, from its record: its water and the carried kinds.
void count_sink(const float* record, double area, LayeredConversions& conversions) {
  conversions.water_sunk += static_cast<double>(record[0]) * area;
  for (int kind = 0; kind < carried_kind_count && !mutant_active("erosion.layered.sinks_uncounted"); ++kind) {
    conversions.sunk[static_cast<std::size_t>(carried_component(kind))] += static_cast<double>(record[1 + kind]) * area;
  }
}

// The drain's records, every column in column order, as the reference counts them.
void count_drain(const LayeredWaterBuffers& water, const LayeredGround<float>& shape, LayeredConversions& conversions) {
  const double area = shape.cell_size_x * shape.cell_size_y;
  const auto records = water.records(source_record_floats);
  const double water_sunk_before = conversions.water_sunk;
  for (std::size_t c = 0; c < shape.cells(); ++c) count_sink(records.data() + c * source_record_floats, area, conversions);
  // Mutant (both twins): the drain's water is not booked.
  if (mutant_active("erosion.layered.drain_water_uncounted")) conversions.water_sunk = water_sunk_before;
}

// The reference's counting (water_sources): the rain once for all columns, the river's source, then
// the sink rows in column order.
void count(const LayeredWaterBuffers& water, const LayeredGround<float>& shape, bool raining,
           LayeredConversions& conversions) {
  const LayeredWaterBlock& block = water.block();
  const double area = shape.cell_size_x * shape.cell_size_y;
  if (raining && !mutant_active("erosion.layered.rain_uncounted")) {
    conversions.water_added += static_cast<double>(block.rain_depth) * area * static_cast<double>(shape.cells());
  }
  if (block.river == 0) return;
  const auto records = water.records(source_record_floats);
  const auto source = static_cast<std::size_t>(block.river_source);
  const double change = static_cast<double>(block.river_depth) - static_cast<double>(records[source * source_record_floats]);
  (change >= 0.0 ? conversions.water_added : conversions.water_sunk) += std::abs(change) * area;
  for (int y = block.sink_row_start; y < shape.height; ++y) {
    for (int x = 0; x < shape.width; ++x) count_sink(records.data() + shape.cell(x, y) * source_record_floats, area, conversions);
  }
}

}  // namespace

LayeredWaterFlow::LayeredWaterFlow()
    : sources_(layered_water_program("erosion/layered/water_sources.comp")),
      drain_(layered_water_program("erosion/layered/water_sources.comp", {"DRAIN_ALL"})),
      flux_(layered_water_program("erosion/layered/water_flux.comp")),
      move_(layered_water_program("erosion/layered/water_move.comp")) {}

void LayeredWaterFlow::sources(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
                               LayeredConversions& conversions) const {
  if (drains(ground.params(), step)) {
    water.bind();
    ground.dispatch_pass(drain_, step);
    count_drain(water, ground.shape(), conversions);
  }
  // Mutant erosion.layered.gpu_rain_past_its_steps (this twin alone, with water_sources.comp): rain on
  // every step, past rain_steps.
  const bool raining = water.block().rain_depth > 0.0f &&
                       (rains(ground.params(), step) || mutant_active("erosion.layered.gpu_rain_past_its_steps"));
  if (!raining && water.block().river == 0) return;
  water.bind();
  ground.dispatch_pass(sources_, step);
  count(water, ground.shape(), raining, conversions);
}

void LayeredWaterFlow::flow(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step) const {
  water.bind();
  ground.dispatch_pass(flux_, step);
  water.snapshot();
  ground.dispatch_pass(move_, step);
}

}  // namespace gt::gpu
