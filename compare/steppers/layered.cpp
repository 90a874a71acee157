// The layered ground's state and steppers (see layered.hpp).
#include "compare/steppers/layered.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>

#include <fmt/format.h>

#include "core/params/layered.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/iteration.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"
#include "reference/erosion/layered/iteration.hpp"

namespace gt {
namespace {

// The fields in declaration order; the water's five exist only when the setup gives water.
enum Field : std::size_t {
  terrain_field, soil_field, bedrock_field, bedrock_type_field, vegetation_field,
  water_field, previous_water_field, water_flux_field, carried_field, wetness_field
};

std::vector<std::string> numbered(int count) {
  std::vector<std::string> names;
  for (int k = 0; k < count; ++k) names.push_back(std::to_string(k));
  return names;
}


// A model's per-kind planes (plane k: values k·cells .. (k+1)·cells) as the state's interleaved
// values (cell·planes + k), and back.
template <class Real>
std::vector<double> interleaved(const std::vector<Real>& planes, std::size_t cells) {
  const std::size_t count = cells == 0 ? 0 : planes.size() / cells;
  std::vector<double> values(planes.size());
  for (std::size_t k = 0; k < count; ++k) {
    for (std::size_t c = 0; c < cells; ++c) values[c * count + k] = static_cast<double>(planes[k * cells + c]);
  }
  return values;
}

template <class Real>
void deinterleave(const std::vector<double>& values, std::size_t cells, std::vector<Real>& planes) {
  const std::size_t count = cells == 0 ? 0 : values.size() / cells;
  planes.resize(values.size());
  for (std::size_t k = 0; k < count; ++k) {
    for (std::size_t c = 0; c < cells; ++c) planes[k * cells + c] = static_cast<Real>(values[c * count + k]);
  }
}

// The water's vectors in the declared fields' order, water_field onward.
template <class Water>
auto water_members(Water& water) {
  return std::array{&water.water, &water.previous_water, &water.water_flux, &water.carried, &water.wetness};
}

template <class Real>
State state_of(const LayeredGround<Real>& ground, const LayeredWater<Real>* water, const StateGrid& grid) {
  const std::size_t cells = ground.cells();
  State state{grid, {interleaved(ground.surface, cells), interleaved(ground.soil, cells),
                     interleaved(ground.bedrock, cells), interleaved(ground.bedrock_type, cells),
                     interleaved(ground.vegetation, cells)}};
  if (water == nullptr) return state;
  for (const auto* member : water_members(*water)) state.fields.push_back(interleaved(*member, cells));
  return state;
}

template <class Real>
void load_water(const State& state, LayeredWater<Real>& water) {
  std::size_t field = water_field;
  for (auto* member : water_members(water)) deinterleave(state.fields[field++], state.grid.cells(), *member);
}

// Loads `state` into a ground (and water) of its shape.
template <class Real>
void load(const State& state, LayeredGround<Real>& ground, LayeredWater<Real>* water) {
  const std::size_t cells = ground.cells();
  deinterleave(state.fields[terrain_field], cells, ground.surface);
  deinterleave(state.fields[soil_field], cells, ground.soil);
  deinterleave(state.fields[bedrock_field], cells, ground.bedrock);
  deinterleave(state.fields[bedrock_type_field], cells, ground.bedrock_type);
  deinterleave(state.fields[vegetation_field], cells, ground.vegetation);
  if (water != nullptr) load_water(state, *water);
}



std::map<std::string, double> conversion_totals(const LayeredConversions& conversions, std::size_t types) {
  std::map<std::string, double> totals;
  double out = 0.0, in = 0.0, sunk = 0.0;
  for (int component = 0; component < soil_component_count; ++component) {
    const double sunk_here = conversions.sunk[std::size_t(component)];
    totals[layered_converted_key(std::size_t(component))] =
        conversions.converted_into(component) - conversions.converted_from(component) - sunk_here;
    out += conversions.converted_from(component);
    in += conversions.converted_into(component);
    sunk += sunk_here;
  }
  for (std::size_t type = 0; type < types; ++type) {
    totals[layered_converted_key(soil_component_count + type)] = -conversions.bedrock_converted(type);
    out += conversions.bedrock_converted(type);
  }
  totals["converted_out"] = out;
  totals["converted_in"] = in;
  totals["sunk"] = sunk;
  totals["water_added"] = conversions.water_added;
  totals["water_sunk"] = conversions.water_sunk;
  return totals;
}

// Every material's volume, m³: the 5 components (in the ground and in the water), then each bedrock type.
template <class Real>
std::vector<double> material_volumes(const LayeredGround<Real>& ground, const LayeredWater<Real>* water, std::size_t types) {
  const LayeredLedger in_ground = layered_ledger(ground, types);
  const auto in_water = water ? layered_water_ledger(*water, ground.cell_size_x * ground.cell_size_y) : LayeredWaterLedger{};
  std::vector<double> volumes;
  for (std::size_t i = 0; i < in_ground.components.size(); ++i) volumes.push_back(in_ground.components[i] + in_water.carried[i]);
  volumes.insert(volumes.end(), in_ground.bedrock.begin(), in_ground.bedrock.end());
  return volumes;
}


// What every backend keeps while it steps: the iteration count, the conversions since the load and
// a record a step.
class LayeredBook {
 public:
  explicit LayeredBook(std::size_t types) : types_(types) {}
  // Starts counting from a state with `done` iterations behind it; returns record 0.
  LedgerRecord& reset(int done) {
    done_ = done;
    conversions_ = no_conversions(types_);
    records_ = {{0, conversion_totals(conversions_, types_)}};
    return records_.front();
  }
  std::uint32_t next() const { return static_cast<std::uint32_t>(done_); }
  LedgerRecord& advance() {
    ++done_;
    records_.push_back({static_cast<int>(records_.size()), conversion_totals(conversions_, types_)});
    return records_.back();
  }
  LayeredConversions& conversions() { return conversions_; }
  const std::vector<LedgerRecord>& records() const { return records_; }
  std::size_t types() const { return types_; }

 private:
  std::size_t types_;
  int done_ = 0;
  LayeredConversions conversions_;
  std::vector<LedgerRecord> records_;
};

template <class Real>
class LayeredReferenceStepper : public Stepper {
 public:
  explicit LayeredReferenceStepper(const LayeredSetup& setup)
      : params_(setup.params),
        grid_(StateGrid::of(setup.surface)),
        ground_(make_layered_ground<Real>(setup.surface, setup.columns, setup.params)),
        book_(setup.params.bedrock_types.size()) {
    if (has_water(params_)) water_ = make_layered_water<Real>(ground_.cells(), params_.initial_water);
  }
  void set_state(const State& state, int done) override {
    load(state, ground_, water());
    add_volumes(book_.reset(done));
  }
  void update(int count) override {
    for (int i = 0; i < count; ++i) {
      reference::layered_iteration(ground_, params_, book_.next(), book_.conversions(), water());
      add_volumes(book_.advance());
    }
  }
  State get_state() override { return state_of(ground_, water(), grid_); }
  std::vector<LedgerRecord> ledger() override { return book_.records(); }

 private:
  LayeredWater<Real>* water() { return water_ ? &*water_ : nullptr; }
  void add_volumes(LedgerRecord& record) {
    const auto volumes = material_volumes(ground_, water(), book_.types());
    for (std::size_t m = 0; m < volumes.size(); ++m) record.totals[layered_volume_key(m)] = volumes[m];
    if (!water_) return;
    const Real deepest = water_->water.empty() ? Real(0) : *std::max_element(water_->water.begin(), water_->water.end());
    record.totals["deepest_water"] = static_cast<double>(deepest);
  }

  LayeredParams params_;
  StateGrid grid_;
  LayeredGround<Real> ground_;
  std::optional<LayeredWater<Real>> water_;
  LayeredBook book_;
};

// The GPU twin; update() waits for the device each step (the conversions are read back).
class LayeredGpuStepper : public Stepper {
 public:
  explicit LayeredGpuStepper(const LayeredSetup& setup)
      : grid_(StateGrid::of(setup.surface)),
        buffers_(make_layered_ground<float>(setup.surface, setup.columns, setup.params), setup.params),
        iteration_(has_water(setup.params)),
        book_(setup.params.bedrock_types.size()) {
    if (has_water(setup.params)) {
      water_.emplace(buffers_, make_layered_water<float>(buffers_.shape().cells(), setup.params.initial_water));
    }
  }
  void set_state(const State& state, int done) override {
    LayeredGround<float> ground = buffers_.shape();
    std::optional<LayeredWater<float>> water;
    if (water_) water = water_->download();
    load(state, ground, water ? &*water : nullptr);
    buffers_.upload(ground);
    if (water_) water_->upload(*water);
    book_.reset(done);
  }
  void update(int count) override {
    for (int i = 0; i < count; ++i) {
      iteration_.step(buffers_, book_.next(), book_.conversions(), water_ ? &*water_ : nullptr);
      book_.advance();
    }
  }
  State get_state() override {
    const LayeredGround<float> ground = buffers_.download();
    if (!water_) return state_of<float>(ground, nullptr, grid_);
    const LayeredWater<float> water = water_->download();
    return state_of(ground, &water, grid_);
  }
  std::vector<LedgerRecord> ledger() override { return book_.records(); }

 private:
  StateGrid grid_;
  gpu::LayeredGroundBuffers buffers_;
  gpu::LayeredIteration iteration_;
  std::optional<gpu::LayeredWaterBuffers> water_;
  LayeredBook book_;
};

}  // namespace

StateDecl layered_fields(int bedrock_layers, bool wet) {
  std::vector<std::string> soil_names, carried_names;
  for (const char* layer : {"topsoil", "subsoil"}) {
    for (int component = 0; component < soil_component_count; ++component) {
      soil_names.push_back(fmt::format("{}_{}", layer, soil_component_name(component)));
    }
  }
  for (int kind = 0; kind < carried_kind_count; ++kind) {
    carried_names.push_back(fmt::format("{}_{}", kind < soil_component_count ? "suspended" : "regolith",
                                        soil_component_name(carried_component(kind))));
  }
  StateDecl fields = {
      {.name = "terrain", .unit = "m", .meaning = "ground surface h, the top of the column",
       .standard_name = "topographic__elevation"},
      {.name = "soil", .unit = "m", .meaning = "thickness of each soil component in topsoil and subsoil",
       .extent = Extent::cell_layer, .components = 2 * soil_component_count, .component_names = soil_names},
      {.name = "bedrock", .unit = "m", .meaning = "thickness of each bedrock layer, top down",
       .extent = Extent::cell_layer, .components = bedrock_layers, .component_names = numbered(bedrock_layers)},
      {.name = "bedrock_type", .unit = "1", .meaning = "each bedrock layer's type (an index into the case's types)",
       .extent = Extent::cell_layer, .components = bedrock_layers, .component_names = numbered(bedrock_layers)},
      {.name = "vegetation", .unit = "1", .meaning = "vegetation density in [0, 1]"}};
  if (!wet) return fields;
  fields.push_back({.name = "water", .unit = "m", .meaning = "water depth w", .standard_name = "surface_water__depth"});
  fields.push_back({.name = "previous_water", .unit = "m", .meaning = "water depth before the step's flow"});
  fields.push_back({.name = "water_flux", .unit = "m³/s", .meaning = "outflow F of each pipe (L, R, T, B)",
                    .extent = Extent::cell_pipe, .components = water_pipe_count,
                    .component_names = {"L", "R", "T", "B"}});
  fields.push_back({.name = "carried", .unit = "m", .meaning = "material the water carries, suspended or as regolith",
                    .extent = Extent::cell_layer, .components = carried_kind_count, .component_names = carried_names});
  fields.push_back({.name = "wetness", .unit = "m·s", .meaning = "wetness (eq. 3.12)"});
  return fields;
}

State layered_start_state(const LayeredSetup& setup) {
  const auto ground = make_layered_ground<double>(setup.surface, setup.columns, setup.params);
  if (!has_water(setup.params)) return state_of<double>(ground, nullptr, StateGrid::of(setup.surface));
  const auto water = make_layered_water<double>(ground.cells(), setup.params.initial_water);
  return state_of(ground, &water, StateGrid::of(setup.surface));
}

LayeredGround<double> layered_ground_of(const State& state, int bedrock_layers) {
  LayeredGround<double> ground{.width = state.grid.width, .height = state.grid.height,
                               .cell_size_x = state.grid.cell_size_x, .cell_size_y = state.grid.cell_size_y,
                               .bedrock_layer_count = bedrock_layers};
  load<double>(state, ground, nullptr);
  return ground;
}

std::optional<LayeredWater<double>> layered_water_of(const State& state) {
  if (state.fields.size() <= water_field) return std::nullopt;
  LayeredWater<double> water;
  load_water(state, water);
  return water;
}

std::vector<double> layered_volumes(const State& state, int bedrock_layers, std::size_t types) {
  const LayeredGround<double> ground = layered_ground_of(state, bedrock_layers);
  const auto water = layered_water_of(state);
  return material_volumes(ground, water ? &*water : nullptr, types);
}

double layered_water_volume(const State& state) {
  const auto water = layered_water_of(state);
  return water ? layered_water_ledger(*water, state.grid.cell_size_x * state.grid.cell_size_y).water : 0.0;
}

std::string layered_converted_key(std::size_t material) { return fmt::format("converted.{}", material); }
std::string layered_volume_key(std::size_t material) { return fmt::format("volume.{}", material); }

template <class Real>
std::unique_ptr<Stepper> layered_reference_stepper(const LayeredSetup& setup) {
  return std::make_unique<LayeredReferenceStepper<Real>>(setup);
}
template std::unique_ptr<Stepper> layered_reference_stepper<double>(const LayeredSetup& setup);
template std::unique_ptr<Stepper> layered_reference_stepper<float>(const LayeredSetup& setup);

std::unique_ptr<Stepper> layered_gpu_stepper(const LayeredSetup& setup) {
  return std::make_unique<LayeredGpuStepper>(setup);
}

}  // namespace gt
