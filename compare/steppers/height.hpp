// Steppers for twins whose state is one changing cell field, the terrain (the thermal models),
// and any read-only inputs after it (erosion.thermal_jako's hardness map).
//
// Inputs:  a step function (reference: heights, first iteration's number, count -> heights) or a
//          GPU object's load / step / download; optionally `read_inputs`, called on each set_state
//          with the stepper's own copy of the loaded state, which hands the read-only fields to the
//          model (the model's copy: what is left there is what get_state hands back).
// Outputs: compare/stepper.hpp's Stepper over the state {terrain, read-only inputs...}.
// Units:   the heights' own (the terrain field is declared in metres; a normalised input is in 1).
#pragma once

#include <functional>
#include <utility>

#include "compare/stepper.hpp"
#include "core/grid.hpp"

namespace gt {

// The one field such a twin declares.
inline FieldDecl terrain_field(const std::string& unit) {
  return {.name = "terrain",
          .unit = unit,
          .meaning = "terrain height",
          .conserved = true,
          .standard_name = "topographic__elevation"};
}

// A state of one field from a heightmap, and back.
inline State height_state(const Grid<double>& heights) { return {StateGrid::of(heights), {heights.values}}; }

// Hands a loaded state's read-only fields to the model; it may keep (or, mutated, hand back) them.
using ReadInputs = std::function<void(State& loaded)>;

// What a height stepper holds beside the terrain it steps: the loaded state's grid and its other
// fields (the terrain's slot left empty: the stepper keeps the heights in its own type).
class HeldInputs {
 public:
  explicit HeldInputs(ReadInputs read_inputs) : read_inputs_(std::move(read_inputs)) {}
  void load(const State& state) {
    loaded_ = state;
    if (read_inputs_) read_inputs_(loaded_);
    loaded_.fields.at(0).clear();
  }
  // The state with `heights` as its terrain and the inputs as held.
  State with_terrain(const Grid<double>& heights) const {
    State state = loaded_;
    state.fields.at(0) = heights.values;
    return state;
  }

 private:
  ReadInputs read_inputs_;
  State loaded_;
};

template <class Real>
Grid<Real> heights_of(const State& state) {
  Grid<Real> heights = state.grid.blank<Real>(Real(0), "m");
  heights.values.assign(state.fields.at(0).begin(), state.fields.at(0).end());
  return heights;
}

// A reference stepped by a function of the heights; Real = float rounds the loaded state to float.
template <class Real>
class HeightStepper : public Stepper {
 public:
  using Step = std::function<Grid<Real>(const Grid<Real>& heights, int first, int count)>;
  explicit HeightStepper(Step step, ReadInputs read_inputs = {})
      : step_(std::move(step)), inputs_(std::move(read_inputs)) {}
  void set_state(const State& state, int done) override {
    inputs_.load(state);
    heights_ = heights_of<Real>(state);
    done_ = done;
  }
  void update(int count) override {
    heights_ = step_(heights_, done_, count);
    done_ += count;
  }
  State get_state() override { return inputs_.with_terrain(heights_.template cast<double>()); }

 private:
  Step step_;
  HeldInputs inputs_;
  Grid<Real> heights_;
  int done_ = 0;
};

// A GPU twin of one float height field.
class GpuHeightStepper : public Stepper {
 public:
  GpuHeightStepper(std::function<void(const Grid<float>&)> load, std::function<void(int first, int count)> step,
                   std::function<Grid<float>()> download, ReadInputs read_inputs = {})
      : load_(std::move(load)), step_(std::move(step)), download_(std::move(download)), inputs_(std::move(read_inputs)) {}
  void set_state(const State& state, int done) override {
    inputs_.load(state);
    load_(heights_of<float>(state));
    done_ = done;
  }
  void update(int count) override {
    step_(done_, count);
    done_ += count;
  }
  State get_state() override { return inputs_.with_terrain(download_().cast<double>()); }

 private:
  std::function<void(const Grid<float>&)> load_;
  std::function<void(int, int)> step_;
  std::function<Grid<float>()> download_;
  HeldInputs inputs_;
  int done_ = 0;
};

}  // namespace gt
