// Host side of weathering on the layered ground (digest 001 §3.16; see weathering.hpp).
#include "gpu/erosion/layered/weathering.hpp"

#include <cstddef>
#include <vector>

namespace gt::gpu {
namespace {

constexpr std::size_t record_floats = 16;  // RECORD of weathering.comp
constexpr GLuint records_binding = 9;
constexpr std::size_t formed_at = 8, formed_type_at = 9, parts_at = 10;

// The reference's counting (weather_column): per column, the topsoil's then the subsoil's four
// amounts, then the bedrock turned into soil and its parts. Zeros add nothing.
void count(const std::vector<float>& records, std::size_t cells, double area, LayeredConversions& conversions) {
  for (std::size_t c = 0; c < cells; ++c) {
    const float* record = records.data() + c * record_floats;
    for (int layer = 0; layer < soil_layer_count; ++layer) {
      for (std::size_t p = 0; p < fragment_size_count; ++p) {
        const double amount = static_cast<double>(record[static_cast<std::size_t>(layer) * fragment_size_count + p]) * area;
        conversions.weathered_from[p + 1] += amount;
        conversions.weathered_into[p] += amount;
      }
    }
    if (record[formed_at] > 0.0f) {
      conversions.soil_formed_from.at(static_cast<std::size_t>(record[formed_type_at])) +=
          static_cast<double>(record[formed_at]) * area;
      for (std::size_t i = 0; i < soil_component_count; ++i) {
        conversions.soil_formed_into[i] += static_cast<double>(record[parts_at + i]) * area;
      }
    }
  }
}

}  // namespace

LayeredWeathering::LayeredWeathering() : program_(layered_program("erosion/layered/weathering.comp")) {}

void LayeredWeathering::step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions) const {
  const std::size_t cells = ground.shape().cells();
  const std::size_t bytes = cells * record_floats * sizeof(float);
  if (!records_ || records_->size_bytes() != bytes) records_.emplace(bytes);
  records_->bind(records_binding);
  ground.dispatch_pass(program_, step);
  conversions.fit_types(ground.params().bedrock_types.size());
  count(records_->download<float>(cells * record_floats), cells,
        ground.shape().cell_size_x * ground.shape().cell_size_y, conversions);
}

LayeredWeathering layered_weathering() { return {}; }

}  // namespace gt::gpu
