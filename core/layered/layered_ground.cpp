// Construction, checks, neighbours and ledger of the layered ground (see layered_ground.hpp).
#include "core/layered/layered_ground.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/params/hydraulic.hpp"
#include "core/sum.hpp"

namespace gt {
namespace {

constexpr const char* algorithm_name = "erosion.layered";
// A topsoil may exceed its maximum by the rounding of reserve-then-deposit, never by more.
constexpr double topsoil_rounding = 1e-6;

// `what` is the message, or a function making it: the per-cell checks run every step, so their
// messages are only formatted when one fails.
template <class Message>
void require(bool condition, const Message& what) {
  if (condition) return;
  if constexpr (std::is_invocable_v<Message>) {
    throw InputError(fmt::format("{}: {}", algorithm_name, what()));
  } else {
    throw InputError(fmt::format("{}: {}", algorithm_name, what));
  }
}

template <class Real, class Name>
void require_thickness(Real value, const Name& what, std::size_t c) {
  require(std::isfinite(static_cast<double>(value)) && value >= Real(0), [&] {
    return fmt::format("{} of cell {} is {}: it must be finite and >= 0", what(), c, static_cast<double>(value));
  });
}

template <class Real>
void check_sizes(const LayeredGround<Real>& ground) {
  require(ground.width > 0 && ground.height > 0, "the ground needs at least one cell");
  require(ground.bedrock_layer_count > 0, "the ground needs at least one bedrock layer");
  const std::size_t cells = ground.cells();
  const auto bedrock_cells = cells * static_cast<std::size_t>(ground.bedrock_layer_count);
  require(ground.surface.size() == cells && ground.vegetation.size() == cells &&
              ground.soil.size() == cells * soil_layer_count * soil_component_count &&
              ground.bedrock.size() == bedrock_cells && ground.bedrock_type.size() == bedrock_cells,
          "the ground's arrays do not match its size");
  for (double size : {ground.cell_size_x, ground.cell_size_y}) {
    require(std::isfinite(size) && size >= 1e-9 && size <= 1e9,
            fmt::format("cell size {} m is outside [1e-9, 1e9]", size));
  }
}

template <class Real>
void check_column(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c) {
  require(std::isfinite(static_cast<double>(ground.surface[c])), [&] { return fmt::format("surface of cell {} is not finite", c); });
  const double vegetation = static_cast<double>(ground.vegetation[c]);
  require(vegetation >= 0.0 && vegetation <= 1.0,
          [&] { return fmt::format("vegetation of cell {} is {}, not in [0, 1]", c, vegetation); });
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    for (int component = 0; component < soil_component_count; ++component) {
      require_thickness(ground.soil_at(layer, component, c),
                        [&] { return fmt::format("soil layer {} {}", layer, soil_component_name(component)); }, c);
    }
  }
  const double topsoil = static_cast<double>(ground.soil_thickness(0, c));
  require(topsoil <= params.topsoil_max * (1.0 + topsoil_rounding), [&] {
    return fmt::format("topsoil of cell {} is {} m, more than topsoil_max = {} m", c, topsoil, params.topsoil_max);
  });
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    require_thickness(ground.bedrock_at(layer, c), [&] { return fmt::format("bedrock layer {}", layer); }, c);
    const auto type = ground.bedrock_type_at(layer, c);
    require(type >= 0 && static_cast<std::size_t>(type) < params.bedrock_types.size(), [&] {
      return fmt::format("bedrock layer {} of cell {} has type {}, but only {} types are defined", layer, c, type,
                         params.bedrock_types.size());
    });
  }
}

}  // namespace

namespace {

void validate_columns(const Heightmap& surface, const LayeredColumns& columns, const LayeredParams& params) {
  require(!columns.profiles.empty(), "the ground needs at least one profile");
  for (const LayeredProfile& profile : columns.profiles) {
    validate_layered_profile(profile, params);
    require(profile.bedrock.size() == columns.profiles.front().bedrock.size(),
            "every profile needs the same number of bedrock layers");
  }
  const std::size_t cells = surface.size();
  require(columns.profile_of.empty() || columns.profile_of.size() == cells,
          fmt::format("the profile map has {} cells, the surface {}", columns.profile_of.size(), cells));
  for (std::size_t c = 0; c < columns.profile_of.size(); ++c) {
    const auto index = columns.profile_of[c];
    require(index >= 0 && static_cast<std::size_t>(index) < columns.profiles.size(), [&] {
      return fmt::format("the profile map names profile {} at cell {}; there are {}", index, c, columns.profiles.size());
    });
  }
  require(columns.vegetation.size() == 1 || columns.vegetation.size() == cells,
          fmt::format("the vegetation holds {} values: one, or one per cell ({})", columns.vegetation.size(), cells));
  for (std::size_t c = 0; c < columns.vegetation.size(); ++c) {
    const double vegetation = columns.vegetation[c];
    require(vegetation >= 0.0 && vegetation <= 1.0, [&] {
      return fmt::format("vegetation {} at cell {} is not in [0, 1]", vegetation, c);
    });
  }
}

}  // namespace

void validate_layered_inputs(const Heightmap& surface, const LayeredColumns& columns, const LayeredParams& params,
                             std::size_t real_bytes) {
  validate_layered_params(params);
  validate_columns(surface, columns, params);
  require(!surface.has_mask(), "the layered ground takes a surface without no-data cells");
  check_finite(surface, "layered ground surface");
  check_cell_size(surface, "layered ground surface");
  // Per cell: the state (surface, vegetation, 10 soil components, the bedrock thicknesses and
  // types) twice (a step's snapshot) and the 8 outflows of a step.
  const auto bedrock_layers = static_cast<long long>(columns.profiles.front().bedrock.size());
  const auto real = static_cast<long long>(real_bytes);
  const auto state_bytes = real * (2 + soil_layer_count * soil_component_count + bedrock_layers) +
                           static_cast<long long>(sizeof(std::int32_t)) * bedrock_layers;
  check_grid_fits(surface.width, surface.height, 2 * state_bytes + real * layered_neighbour_count, "layered ground");
}

template <class Real>
LayeredGround<Real> make_layered_ground(const Heightmap& surface, const LayeredColumns& columns,
                                        const LayeredParams& params) {
  validate_layered_inputs(surface, columns, params, sizeof(Real));
  LayeredGround<Real> ground;
  ground.width = surface.width;
  ground.height = surface.height;
  ground.cell_size_x = surface.cell_size_x;
  ground.cell_size_y = surface.cell_size_y;
  ground.bedrock_layer_count = static_cast<int>(columns.profiles.front().bedrock.size());
  const std::size_t cells = ground.cells();
  const auto layers = static_cast<std::size_t>(ground.bedrock_layer_count);
  ground.surface.assign(surface.values.begin(), surface.values.end());
  ground.vegetation.resize(cells);
  ground.soil.assign(cells * soil_layer_count * soil_component_count, Real(0));
  ground.bedrock.assign(cells * layers, Real(0));
  ground.bedrock_type.assign(cells * layers, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    const auto& profile = columns.profiles[columns.profile_of.empty() ? 0 : std::size_t(columns.profile_of[c])];
    ground.vegetation[c] = static_cast<Real>(columns.vegetation[columns.vegetation.size() == 1 ? 0 : c]);
    for (int component = 0; component < soil_component_count; ++component) {
      const auto i = static_cast<std::size_t>(component);
      ground.soil_at(0, component, c) = static_cast<Real>(profile.topsoil[i]);
      ground.soil_at(1, component, c) = static_cast<Real>(profile.subsoil[i]);
    }
    for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
      const auto& bedrock = profile.bedrock[static_cast<std::size_t>(layer)];
      ground.bedrock_at(layer, c) = static_cast<Real>(bedrock.thickness);
      ground.bedrock_type[ground.bedrock_index(layer, c)] = bedrock.type;
    }
  }
  return ground;
}

template <class Real>
LayeredGround<Real> make_layered_ground(const Heightmap& surface, const LayeredProfile& profile,
                                        const LayeredParams& params, double vegetation) {
  return make_layered_ground<Real>(surface, LayeredColumns{{profile}, {}, {vegetation}}, params);
}

template <class Real>
void check_layered_ground(const LayeredGround<Real>& ground, const LayeredParams& params) {
  check_sizes(ground);
  require(params.border == LayeredBorder::closed || (ground.width >= 3 && ground.height >= 3),
          fmt::format("a periodic border needs at least 3 × 3 cells, not {} × {}", ground.width, ground.height));
  for (std::size_t c = 0; c < ground.cells(); ++c) check_column(ground, params, c);
}

template <class Real>
std::optional<std::size_t> layered_neighbour(const LayeredGround<Real>& ground, LayeredBorder border, int x, int y,
                                             int k) {
  const auto offset = pipe_offsets[static_cast<std::size_t>(k)];
  int nx = x + offset.dx;
  int ny = y + offset.dy;
  if (border == LayeredBorder::periodic) {
    nx = (nx + ground.width) % ground.width;
    ny = (ny + ground.height) % ground.height;
  } else if (nx < 0 || ny < 0 || nx >= ground.width || ny >= ground.height) {
    return std::nullopt;
  }
  return ground.cell(nx, ny);
}

double layered_neighbour_distance(double cell_size_x, double cell_size_y, int k) {
  if (k < 2) return cell_size_x;
  if (k < 4) return cell_size_y;
  return std::hypot(cell_size_x, cell_size_y);
}

double LayeredLedger::total() const {
  CompensatedSum sum;
  for (double volume : components) sum.add(volume);
  for (double volume : bedrock) sum.add(volume);
  return sum.value();
}

template <class Real>
LayeredLedger layered_ledger(const LayeredGround<Real>& ground, std::size_t bedrock_type_count) {
  const double area = ground.cell_size_x * ground.cell_size_y;
  std::array<CompensatedSum, soil_component_count> components;
  std::vector<CompensatedSum> bedrock(bedrock_type_count);
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    for (int layer = 0; layer < soil_layer_count; ++layer) {
      for (int component = 0; component < soil_component_count; ++component) {
        components[static_cast<std::size_t>(component)].add(static_cast<double>(ground.soil_at(layer, component, c)) * area);
      }
    }
    for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
      bedrock.at(static_cast<std::size_t>(ground.bedrock_type_at(layer, c)))
          .add(static_cast<double>(ground.bedrock_at(layer, c)) * area);
    }
  }
  LayeredLedger ledger;
  for (std::size_t i = 0; i < components.size(); ++i) ledger.components[i] = components[i].value();
  for (const auto& sum : bedrock) ledger.bedrock.push_back(sum.value());
  return ledger;
}

double LayeredConversions::converted_into(int component) const {
  const auto i = static_cast<std::size_t>(component);
  return fragmented_into.at(i) + weathered_into.at(i) + soil_formed_into.at(i) + broken_into.at(i) +
         bedrock_eroded_into.at(i);
}

double LayeredConversions::converted_from(int component) const {
  const auto i = static_cast<std::size_t>(component);
  return weathered_from.at(i) + broken_from.at(i);
}

double LayeredConversions::bedrock_converted(std::size_t type) const {
  double total = 0.0;
  for (const auto* per_type : {&fragmented_from, &soil_formed_from, &bedrock_eroded_from}) {
    if (type < per_type->size()) total += (*per_type)[type];
  }
  return total;
}

void LayeredConversions::fit_types(std::size_t bedrock_type_count) {
  for (auto* per_type : {&fragmented_from, &soil_formed_from, &bedrock_eroded_from}) {
    per_type->resize(std::max(per_type->size(), bedrock_type_count), 0.0);
  }
}

LayeredConversions no_conversions(std::size_t bedrock_type_count) {
  LayeredConversions conversions;
  conversions.fit_types(bedrock_type_count);
  return conversions;
}

#define GT_LAYERED_GROUND_INSTANTIATE(Real)                                                                    \
  template LayeredGround<Real> make_layered_ground(const Heightmap&, const LayeredColumns&, const LayeredParams&); \
  template LayeredGround<Real> make_layered_ground(const Heightmap&, const LayeredProfile&, const LayeredParams&, \
                                                   double);                                                   \
  template void check_layered_ground(const LayeredGround<Real>&, const LayeredParams&);                       \
  template std::optional<std::size_t> layered_neighbour(const LayeredGround<Real>&, LayeredBorder, int, int, int); \
  template LayeredLedger layered_ledger(const LayeredGround<Real>&, std::size_t);
GT_LAYERED_GROUND_INSTANTIATE(float)
GT_LAYERED_GROUND_INSTANTIATE(double)
#undef GT_LAYERED_GROUND_INSTANTIATE

}  // namespace gt
