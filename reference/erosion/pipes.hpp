// Hydraulic erosion with virtual pipes (Mei, Decaudin, Hu 2007; digest 000 §3.4, eqs. 2.10-2.25), CPU reference.
//
// PipeErosion<Real>(initial, constants, forcing) advances a PipeState (core/params/hydraulic.hpp)
// by steps of Δt and keeps a water and material ledger in double, one entry per step:
//   step(), run(steps)  one step / `steps` steps; state() the current state; ledger() entry 0 for the
//                       initial state, entry n for the state after step n.
// Real = double is the truth; Real = float repeats the GPU's arithmetic operation by operation.
//
// Inputs:  initial    terrain b, water d, sediment s, outflow flux f, velocity. No-data cells of the
//                     terrain's mask are walls or sinks (see pipes.cpp) and hold no water, sediment,
//                     flux or velocity: the constructor sets those to 0 there.
//          constants  from pipe_constants() (core/params/hydraulic.hpp), 4 or 8 pipes among them.
//          forcing    rain map and point sources.
// Outputs: state() and ledger() (core/params/hydraulic.hpp's PipeLedgerEntry).
// Units:   b, d, s in metres, flux in m³/s, velocity in m/s; rain map in m/s, point sources in m³/s;
//          ledger volumes in m³.
// Throws:  InputError ("erosion.pipe: ..."): the constructor for the inputs listed at it (those of
//          check_pipe_input); step() naming the step and the cell when a value turns NaN or infinite or
//          water or sediment turns negative (the state is then that of the failed step).
// Twin:    gpu/erosion/pipes.hpp (PipeErosion) with gpu/shaders/erosion/pipes_*.comp, pipes_block.glsl and
//          pipes_thermal.glsl.
// Decisions: the float trap: an erosion or deposition amount below half the float spacing of the
//          terrain height (2^-24·|b|: 3.05e-5 m at 500 m) is lost from the terrain while the sediment
//          keeps all of it, so ref<float> creates or destroys material at high base heights. The float
//          reference shows this honestly (its ledger reports the drift); the GPU twin is to avoid it
//          (heights relative to a base, or compensated storage), not this reference.
#pragma once

#include <vector>

#include "core/params/hydraulic.hpp"
#include "core/sum.hpp"

namespace gt::reference {

template <class Real>
class PipeErosion {
 public:
  // Throws InputError for grids whose size differs from the terrain's, a mask without a valid cell,
  // non-finite values, negative water, sediment or flux on valid cells, a diagonal flux other than 0
  // with 4 pipes, a rain map of another size or with negative or non-finite rates, and sources
  // outside the grid, on no-data cells or with a negative or non-finite rate.
  PipeErosion(PipeState<Real> initial, const PipeConstants& constants, HydraulicForcing forcing = {});

  // One step: water increment, outflow flux, water depth, velocity, erosion/deposition, regolith,
  // sediment and regolith transport, diffusion, evaporation, thermal erosion. Throws InputError naming the step and the cell when a value turns NaN or
  // infinite or water or sediment turns negative (the state is then that of the failed step).
  void step();
  void run(int steps);

  const PipeState<Real>& state() const { return state_; }
  // Entry 0 describes the initial state; entry n the state after step n.
  const std::vector<PipeLedgerEntry>& ledger() const { return ledger_; }

 private:
  using Fluxes = std::array<Real, 8>;  // one value per pipe, as gt::pipe_offsets

  int pipe_count() const { return constants_.pipe_count; }
  bool exterior(std::size_t cell, int pipe) const { return (exterior_pipes_[cell] >> pipe) & 1u; }
  std::size_t neighbour(int x, int y, int pipe) const;
  Fluxes inflows(int x, int y) const;
  Real neighbour_surface(int x, int y, int pipe) const;
  Fluxes carried_shares(std::size_t cell) const;
  Real exterior_share(std::size_t cell, const Fluxes& shares) const;
  Real tilt_sine(int x, int y) const;
  // The bilinear value of `source` at the cell moved by direction·(u, v)·Δt (direction −1: Mei's
  // backtrace; +1: MacCormack's trace forward).
  Real traced_sediment(const std::vector<Real>& source, int x, int y, int direction) const;
  Fluxes diffusion_shares(int x, int y) const;

  void add_water();
  void update_outflow();
  void update_water_depth();
  void update_velocity();
  void erode_and_deposit();
  void regolith_exchange();
  void gather_sent(std::vector<Real>& field, CompensatedSum& boundary_out, int pipes);
  void transport_with_fluxes(std::vector<Real>& field, CompensatedSum& boundary_out);
  void transport_semi_lagrangian(std::vector<Real>& field, CompensatedSum& boundary_out);
  void maccormack_correction(std::vector<Real>& field);
  void transport(std::vector<Real>& field, CompensatedSum& boundary_out);
  void diffuse(std::vector<Real>& field);
  void evaporate();
  void check_state() const;
  void record_ledger();

  PipeState<Real> state_;
  PipeConstants constants_;
  std::vector<Real> rain_depth_;               // Δt·(rain_rate + rain_map) per cell, m
  std::vector<std::pair<std::size_t, Real>> source_depths_;  // cell, Δt·rate/(l_x·l_y), m
  std::vector<unsigned char> exterior_pipes_;  // bit k (all 8 pipes): pipe k leads off the grid or to no data
  std::vector<Real> water_before_flow_;        // d_A of the current step
  std::vector<unsigned char> drained_;         // bit 0: K < 1 this step, the pipes took all of d_A (pipes.cpp)
  std::vector<Real> scratch_;                  // next terrain or sediment of the current step
  std::vector<Real> forward_;                  // MacCormack: the semi-Lagrangian result it corrects
  std::vector<Fluxes> sent_;                   // sediment or regolith leaving through each pipe, m
  PipeFlows flows_;
  double step_max_cfl_ = 0.0;
  int steps_done_ = 0;
  std::vector<PipeLedgerEntry> ledger_;
};

}  // namespace gt::reference
