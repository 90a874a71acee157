// Steppers for twins whose whole state is one cell field, the terrain (the thermal models).
//
// Inputs:  a step function (reference: heights, first iteration's number, count -> heights) or a
//          GPU object's load / step / download.
// Outputs: compare/stepper.hpp's Stepper over the state {terrain}.
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
  explicit HeightStepper(Step step) : step_(std::move(step)) {}
  void set_state(const State& state, int done) override {
    heights_ = heights_of<Real>(state);
    done_ = done;
  }
  void update(int count) override {
    heights_ = step_(heights_, done_, count);
    done_ += count;
  }
  State get_state() override { return height_state(heights_.template cast<double>()); }

 private:
  Step step_;
  Grid<Real> heights_;
  int done_ = 0;
};

// A GPU twin of one float height field.
class GpuHeightStepper : public Stepper {
 public:
  GpuHeightStepper(std::function<void(const Grid<float>&)> load, std::function<void(int first, int count)> step,
                   std::function<Grid<float>()> download)
      : load_(std::move(load)), step_(std::move(step)), download_(std::move(download)) {}
  void set_state(const State& state, int done) override {
    load_(heights_of<float>(state));
    done_ = done;
  }
  void update(int count) override {
    step_(done_, count);
    done_ += count;
  }
  State get_state() override { return height_state(download_().cast<double>()); }

 private:
  std::function<void(const Grid<float>&)> load_;
  std::function<void(int, int)> step_;
  std::function<Grid<float>()> download_;
  int done_ = 0;
};

}  // namespace gt
