// Hydraulic erosion with virtual pipes (Mei, Decaudin, Hu 2007; digest 000 §3.4), GPU twin.
//
// The same stages as the reference over 4 or 8 pipes (with seed 001's regolith and sediment
// diffusion and Jákó & Tóth's thermal step when the constants ask for them), the same float
// operations in the same order, the same boundary and 0/0 rules (listed in
// reference/erosion/pipes.cpp), on compute shaders gpu/shaders/erosion/pipes_*.comp. See
// gpu/erosion/pipes.cpp for the passes, the buffers and the ledger.
// PipeErosion(initial, constants, forcing = {}, keep_ledger = true): uploads `initial` (each value
//   rounded to float once), the forcing and the constants. No-data cells hold no water, sediment,
//   regolith, flux or velocity. keep_ledger = true: every step() downloads the state, appends a
//   PipeLedgerEntry summed in double exactly as the reference's (the same float quantities, the same
//   compensated sums and order) and checks the state. keep_ledger = false: steps download nothing
//   (for timing); the ledger keeps entry 0 only.
// upload(state): starts over from `state` (below).
// step(), run(steps): one step is passes_per_step() dispatches (not synchronised: the caller
//   brackets timing with glFinish).
// state(), ledger(), passes_per_step(), steps_done(): below.
//
// Inputs:  initial, state: PipeState<double> (terrain b, water d, sediment s, regolith, flux,
//          velocity, Šťava's layers); constants from pipe_constants(); forcing: rain map and point sources. Needs a
//          current GlContext.
// Outputs: state(): downloaded (waits for the GPU); terrain reconstructed in double as b0 + Δb (an
//          exact sum unless |Δb| < 2^-29·|b0|, then within 2^-53 of b). ledger(): entry 0 describes the
//          initial state, entry n the state after step n (only with keep_ledger).
//          passes_per_step(): compute dispatches per step: 4, +1 with point sources, +1 with
//          MacCormack, +1 with sediment diffusion, +2 with the thermal step.
// Units:   as the reference: b, d, s in metres, flux in m³/s, velocity in m/s; ledger volumes in m³.
// Throws:  InputError, the reference's messages: the constructor refuses grids of another size than
//          the terrain, a mask without a valid cell, non-finite values (also after rounding to float),
//          negative water, sediment, regolith or flux on valid cells, a diagonal flux other than 0 with
//          4 pipes, a rain map of another size or with negative or non-finite rates, and sources off
//          the grid, on no-data cells or with a negative or non-finite rate; upload() refuses the same
//          and a state whose grid, cell size or mask differs from the constructor's (the rain and the
//          pipes' borders were derived from those); step() with keep_ledger on NaN, infinities and
//          negative water/sediment/regolith/flux, naming the step and cell. std::runtime_error when a
//          shader does not compile or link or its block does not match the C++ mirror.
// Twin:    reference/erosion/pipes.hpp.
// Decisions: the one deliberate difference from ref<float>, the float trap: the terrain is stored as
//          the initial height b0 (float, never written) plus a float change Δb that starts at 0, and
//          height differences are formed as (b0_a − b0_b) + (Δb_a − Δb_b). An erosion amount far below
//          the float spacing of b (3e-5 m at 500 m) then still lands in Δb, so material is conserved to
//          the rounding of Δb and s, not of b; ref<float>, which stores b, creates or destroys material
//          there. upload() makes the terrain's floats the base b0 and starts Δb at 0, the ledger at
//          entry 0 and steps_done() at 0, as if constructed from the state, with the same constants,
//          forcing and compiled passes; the driver's shadow steps load ref<float>'s state this way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/params/hydraulic.hpp"
#include "core/sum.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class PipeErosion {
 public:
  // Uploads `initial` (each value rounded to float once), the forcing and the constants. Refuses
  // (InputError, the reference's messages) grids of another size than the terrain, a mask without
  // a valid cell, non-finite values (also after rounding to float), negative water, sediment,
  // regolith or flux on valid cells, a diagonal flux other than 0 with 4 pipes, a rain map of
  // another size or with negative or non-finite rates, and sources off the grid, on no-data cells
  // or with a negative or non-finite rate.
  // No-data cells hold no water, sediment, regolith, flux or velocity.
  // keep_ledger = true: every step() downloads the state, appends a PipeLedgerEntry summed in double
  // exactly as the reference's (the same float quantities, the same compensated sums and order) and
  // checks the state (NaN, infinities, negative water/sediment/regolith/flux -> InputError naming
  // the step and cell, the reference's message). keep_ledger = false: steps download nothing (for
  // timing); the ledger keeps entry 0 only.
  PipeErosion(const PipeState<double>& initial, const PipeConstants& constants, const HydraulicForcing& forcing = {},
              bool keep_ledger = true);

  // Starts over from `state` with the same constants, forcing and compiled passes, as if constructed
  // from it: the terrain's floats become the base b0 and the change Δb starts at 0, the ledger
  // restarts at entry 0 and steps_done() at 0. Refuses what the constructor refuses and a state
  // whose grid, cell size or mask differs from the constructor's (the rain and the pipes' borders
  // were derived from those). The driver's shadow steps load ref<float>'s state this way.
  void upload(const PipeState<double>& state);

  // One step (passes_per_step() dispatches); not synchronised: the caller brackets timing with
  // glFinish.
  void step();
  void run(int steps);

  // Downloaded (waits for the GPU); terrain reconstructed in double as b0 + Δb (an exact sum unless
  // |Δb| < 2^-29·|b0|, then within 2^-53 of b).
  PipeState<double> state() const;
  // Entry 0 describes the initial state; entry n the state after step n (only with keep_ledger).
  const std::vector<PipeLedgerEntry>& ledger() const { return ledger_; }
  // Compute dispatches per step: 4, +1 with point sources, +1 with MacCormack, +1 with sediment
  // diffusion, +2 with the thermal step.
  int passes_per_step() const;
  int steps_done() const { return steps_done_; }

 private:
  struct Download;
  // Floats per cell of the outflow and sent buffers: 4, or 8 with the diagonal pipes.
  std::size_t pipe_values_per_cell() const;
  // Floats per cell of the layers buffer: Šťava's layer count (0 without layers).
  std::size_t layer_values_per_cell() const;
  Download download() const;
  void bind() const;
  void record_step();
  void check_state(const Download& fields) const;
  void record_ledger(const Download& fields);

  int width_;
  int height_;
  PipeConstants constants_;
  HydraulicForcing forcing_;           // for upload()'s refusals
  bool keep_ledger_;
  std::vector<float> rain_depth_;      // Δt·(r + r_map) as uploaded, 0 on no-data cells
  std::vector<std::pair<std::size_t, float>> source_depths_;  // cell, rate·Δt/(l_x·l_y), in the order given
  std::vector<float> base_;            // b0 as uploaded
  std::vector<float> water_before_;    // d at the start of the next step (for the ledger's water_added)
  std::vector<std::uint32_t> flags_;   // bits 0-7 exterior pipes, bit 8 valid
  Grid<double> layout_;                // geometry, units and mask of the terrain
  double base_volume_ = 0.0;           // Σ b0·l_x·l_y over valid cells
  std::size_t source_cell_count_ = 0;

  ComputeProgram water_program_;
  std::optional<ComputeProgram> sources_program_;  // only with point sources
  ComputeProgram outflow_program_;
  ComputeProgram flow_program_;
  ComputeProgram sediment_program_;
  std::optional<ComputeProgram> maccormack_program_;  // only with MacCormack transport
  std::optional<ComputeProgram> diffusion_program_;  // only with sediment diffusion
  std::optional<ComputeProgram> thermal_outflow_program_;  // only with the thermal step
  std::optional<ComputeProgram> thermal_gather_program_;
  UniformBuffer block_;
  StorageBuffer cells_;
  StorageBuffer delta_;
  StorageBuffer delta_next_;
  StorageBuffer water_;
  StorageBuffer outflow_;
  StorageBuffer velocity_;
  StorageBuffer sediment_;
  StorageBuffer staying_;
  StorageBuffer sent_;
  StorageBuffer regolith_;
  StorageBuffer regolith_staying_;  // 16 bytes unless the regolith stage runs
  StorageBuffer regolith_sent_;     // likewise
  StorageBuffer thermal_outflows_;  // 8 per cell with the thermal step, else 16 bytes
  StorageBuffer corrected_;           // MacCormack's s, swapped with sediment_; else 16 bytes
  StorageBuffer regolith_corrected_;  // likewise for r
  StorageBuffer source_cells_;
  StorageBuffer source_list_;
  StorageBuffer layers_;              // Šťava's b_1..b_N per cell (with layers), else 16 bytes

  PipeFlows flows_;
  int steps_done_ = 0;
  std::vector<PipeLedgerEntry> ledger_;
};

}  // namespace gt::gpu
