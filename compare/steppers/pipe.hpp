// The pipe model's state and steppers (compare/stepper.hpp) over its twins: reference::PipeErosion
// in double and float (reference/erosion/pipes.hpp) and gpu::PipeErosion (gpu/erosion/pipes.hpp).
// The numerical code is theirs.
//
// Inputs:  the model's constants and forcing (core/params/hydraulic.hpp); the GPU also its initial
//          state (its buffers' shape).
// Outputs: the declared state, pipe_fields(constants), in this order:
//            terrain    m     terrain height b (topographic__elevation)
//            water      m     water depth d (surface_water__depth)
//            sediment   m     suspended sediment s, as material over the cell
//            regolith   m     loosened bed material r (seed 001 §3.9)
//            velocity_x, velocity_y   m/s   water velocity u, v
//            outflow    m³/s  the flux through each pipe in use (cell x pipe: L, R, T, B, diagonals)
//            layer_1 .. layer_N   m   with `layers` = N ≥ 1: Šťava's layer thicknesses, bottom first
//          Ledger records, one a step from the load (record 0 the state loaded), PipeLedgerEntry's
//          members by name (records_of, entries_of).
// Conventions: loading a state starts a new run and ledger from it; the model's iteration number
// plays no part (no randomness).
#pragma once

#include <memory>
#include <vector>

#include "compare/stepper.hpp"
#include "core/params/hydraulic.hpp"
#include "reference/erosion/pipes.hpp"

namespace gt {

StateDecl pipe_fields(const PipeConstants& constants);

// The model's state as the runner's, and back.
template <class Real>
State pipe_state(const PipeState<Real>& pipe, int pipes);
template <class Real>
PipeState<Real> pipe_state_of(const State& state, int pipes);

// The model's ledger as records, and back.
std::vector<LedgerRecord> records_of(const std::vector<PipeLedgerEntry>& ledger);
std::vector<PipeLedgerEntry> entries_of(const std::vector<LedgerRecord>& records);

template <class Real>
std::unique_ptr<Stepper> pipe_reference_stepper(const PipeConstants& constants, const HydraulicForcing& forcing);
// Needs a current GL context; keep_ledger = false for timing (no downloads between steps).
std::unique_ptr<Stepper> pipe_gpu_stepper(const PipeState<double>& initial, const PipeConstants& constants,
                                          const HydraulicForcing& forcing, bool keep_ledger);

}  // namespace gt
