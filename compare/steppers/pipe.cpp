// The pipe model's state and steppers (see pipe.hpp).
#include "compare/steppers/pipe.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "gpu/erosion/pipes.hpp"

namespace gt {
namespace {

// PipeState's grids in the order pipe_fields declares them (outflow, last, apart).
template <class Real>
std::array<const Grid<Real>*, 6> pipe_grids(const PipeState<Real>& pipe) {
  return {&pipe.terrain, &pipe.water, &pipe.sediment, &pipe.regolith, &pipe.velocity_x, &pipe.velocity_y};
}

template <class Real>
std::array<Grid<Real>*, 6> pipe_grids(PipeState<Real>& pipe) {
  return {&pipe.terrain, &pipe.water, &pipe.sediment, &pipe.regolith, &pipe.velocity_x, &pipe.velocity_y};
}



// The ledger's totals by name, the same as PipeLedgerEntry's members.
constexpr std::pair<const char*, double PipeLedgerEntry::*> ledger_totals[] = {
    {"water", &PipeLedgerEntry::water},
    {"terrain", &PipeLedgerEntry::terrain},
    {"sediment", &PipeLedgerEntry::sediment},
    {"regolith", &PipeLedgerEntry::regolith},
    {"rain_in", &PipeLedgerEntry::rain_in},
    {"source_in", &PipeLedgerEntry::source_in},
    {"water_added", &PipeLedgerEntry::water_added},
    {"evaporated", &PipeLedgerEntry::evaporated},
    {"boundary_out_water", &PipeLedgerEntry::boundary_out_water},
    {"boundary_out_sediment", &PipeLedgerEntry::boundary_out_sediment},
    {"boundary_out_regolith", &PipeLedgerEntry::boundary_out_regolith},
    {"max_cfl", &PipeLedgerEntry::max_cfl}};



// ref<Real> as a stepper: loading a state starts a new run (and ledger) from it.
template <class Real>
class PipeReferenceStepper : public Stepper {
 public:
  PipeReferenceStepper(const PipeConstants& constants, const HydraulicForcing& forcing)
      : constants_(constants), forcing_(forcing) {}
  void set_state(const State& state, int) override {
    erosion_.emplace(pipe_state_of<Real>(state, pipes()), constants_, forcing_);
  }
  void update(int count) override { erosion_->run(count); }
  State get_state() override { return pipe_state(erosion_->state(), pipes()); }
  std::vector<LedgerRecord> ledger() override { return records_of(erosion_->ledger()); }

 private:
  int pipes() const { return constants_.pipe_count; }
  PipeConstants constants_;
  HydraulicForcing forcing_;
  std::optional<reference::PipeErosion<Real>> erosion_;
};

// The GPU twin as a stepper; keep_ledger = false for timing (no downloads between steps).
class PipeGpuStepper : public Stepper {
 public:
  PipeGpuStepper(const PipeState<double>& initial, const PipeConstants& constants, const HydraulicForcing& forcing,
                 bool keep_ledger)
      : pipes_(constants.pipe_count), erosion_(initial, constants, forcing, keep_ledger) {}
  void set_state(const State& state, int) override { erosion_.upload(pipe_state_of<double>(state, pipes_)); }
  void update(int count) override { erosion_.run(count); }
  State get_state() override { return pipe_state(erosion_.state(), pipes_); }
  std::vector<LedgerRecord> ledger() override { return records_of(erosion_.ledger()); }

 private:
  int pipes_;
  gpu::PipeErosion erosion_;
};

}  // namespace

// The state as the runner sees it: each field of PipeState, outflow with a component per pipe in use.
StateDecl pipe_fields(const PipeConstants& constants) {
  std::vector<std::string> pipes;
  for (int pipe = 0; pipe < constants.pipe_count; ++pipe) pipes.emplace_back(pipe_name(pipe));
  StateDecl fields{{.name = "terrain", .unit = "m", .meaning = "terrain height b", .conserved = true,
           .standard_name = "topographic__elevation"},
          {.name = "water", .unit = "m", .meaning = "water depth d", .conserved = true,
           .standard_name = "surface_water__depth"},
          {.name = "sediment", .unit = "m", .meaning = "suspended sediment s, as material over the cell", .conserved = true},
          {.name = "regolith", .unit = "m", .meaning = "loosened bed material r (seed 001 §3.9)", .conserved = true},
          {.name = "velocity_x", .unit = "m/s", .meaning = "water velocity u, +x"},
          {.name = "velocity_y", .unit = "m/s", .meaning = "water velocity v, +y"},
          {.name = "outflow",
           .unit = "m³/s",
           .meaning = "flux f through each pipe (L, R, T, B, then the diagonals)",
           .extent = Extent::cell_pipe,
           .components = constants.pipe_count,
           .component_names = pipes}};
  for (int k = 1; k <= constants.layer_count; ++k) {
    fields.push_back({.name = fmt::format("layer_{}", k),
                      .unit = "m",
                      .meaning = fmt::format("thickness b_{} of layer {} of {} on the bedrock (Šťava 2008; part of the "
                                             "terrain height, layer {} on top)",
                                             k, k, constants.layer_count, constants.layer_count)});
  }
  return fields;
}

template <class Real>
State pipe_state(const PipeState<Real>& pipe, int pipes) {
  State state{StateGrid::of(pipe.terrain), {}};
  for (const Grid<Real>* grid : pipe_grids(pipe)) state.fields.emplace_back(grid->values.begin(), grid->values.end());
  std::vector<double> outflow;
  outflow.reserve(pipe.outflow.size() * static_cast<std::size_t>(pipes));
  for (const auto& cell : pipe.outflow) outflow.insert(outflow.end(), cell.begin(), cell.begin() + pipes);
  state.fields.push_back(std::move(outflow));
  for (const auto& layer : pipe.layers) state.fields.emplace_back(layer.values.begin(), layer.values.end());
  return state;
}

template State pipe_state(const PipeState<double>& pipe, int pipes);
template State pipe_state(const PipeState<float>& pipe, int pipes);

template <class Real>
PipeState<Real> pipe_state_of(const State& state, int pipes) {
  PipeState<Real> pipe;
  std::size_t f = 0;
  for (Grid<Real>* grid : pipe_grids(pipe)) {
    *grid = state.grid.blank<Real>(Real(0), "m");
    grid->values.assign(state.fields[f].begin(), state.fields[f].end());
    ++f;
  }
  pipe.outflow.assign(state.grid.cells(), {});
  const auto& outflow = state.fields[f];
  for (std::size_t cell = 0; cell < pipe.outflow.size(); ++cell) {
    for (int k = 0; k < pipes; ++k) pipe.outflow[cell][k] = static_cast<Real>(outflow[cell * pipes + k]);
  }
  // The fields after the outflow are the layers, bottom first.
  for (std::size_t layer = f + 1; layer < state.fields.size(); ++layer) {
    Grid<Real>& thickness = pipe.layers.emplace_back(state.grid.blank<Real>(Real(0), "m"));
    thickness.values.assign(state.fields[layer].begin(), state.fields[layer].end());
  }
  return pipe;
}

template PipeState<double> pipe_state_of(const State& state, int pipes);
template PipeState<float> pipe_state_of(const State& state, int pipes);

std::vector<LedgerRecord> records_of(const std::vector<PipeLedgerEntry>& ledger) {
  std::vector<LedgerRecord> records;
  for (const auto& entry : ledger) {
    LedgerRecord record{.step = entry.step};
    for (const auto& [name, member] : ledger_totals) record.totals[name] = entry.*member;
    records.push_back(std::move(record));
  }
  return records;
}

std::vector<PipeLedgerEntry> entries_of(const std::vector<LedgerRecord>& records) {
  std::vector<PipeLedgerEntry> ledger;
  for (const auto& record : records) {
    PipeLedgerEntry entry{.step = record.step};
    for (const auto& [name, member] : ledger_totals) entry.*member = record.totals.at(name);
    ledger.push_back(entry);
  }
  return ledger;
}

template <class Real>
std::unique_ptr<Stepper> pipe_reference_stepper(const PipeConstants& constants, const HydraulicForcing& forcing) {
  return std::make_unique<PipeReferenceStepper<Real>>(constants, forcing);
}
template std::unique_ptr<Stepper> pipe_reference_stepper<double>(const PipeConstants&, const HydraulicForcing&);
template std::unique_ptr<Stepper> pipe_reference_stepper<float>(const PipeConstants&, const HydraulicForcing&);

std::unique_ptr<Stepper> pipe_gpu_stepper(const PipeState<double>& initial, const PipeConstants& constants,
                                          const HydraulicForcing& forcing, bool keep_ledger) {
  return std::make_unique<PipeGpuStepper>(initial, constants, forcing, keep_ledger);
}

}  // namespace gt
