// Seed 002's "Earth-like" planet generator on the GPU (digest 002 §4.4, §9), GPU twin.
//
// Follows the step-by-step spec of core/params/planet.hpp with the synchronous plate rule and Jacobi
// (or no) smoothing. The legacy plate rule and legacy smoothing are sequential and CPU only: the
// constructor refuses them.
// Passes (gpu/shaders/planet/, one invocation per region unless said; buffers and shared helpers
// in planet.glsl):
//   1   jitter.comp              offsets and positions
//   2   plate_seeds.comp         one invocation: rates and seeds in plate order (duplicates rejected)
//       per cycle c: plate_expansions.comp (per plate), then max_expansions sub-steps of
//       plate_claim.comp (ping-pong plate buffers); the host reads the assigned-region counter after
//       each cycle and stops when it reaches N (the cycles counted as the reference counts them)
//   3   plate_edges.comp         is_edge
//   4   centre_sums.comp         exact 64-bit fixed-point sums per plate (planet/fixed_point.glsl)
//   4–6 plate_motion.comp        (per plate) centre, shift, base
//   7   elevation_noise.comp     E0
//   8   elevation_collision.comp E1
//   9   elevation_smooth.comp    E2
// The neighbour table is CubeSphere's, uploaded once (§9.1).
// PlanetGenerator(sphere, params) compiles the passes and uploads the neighbour table.
// jitter() and grow_plates() run their steps and download.
// elevation(positions, partition) uploads given positions (3 per region) and partition (plate and
//   is_edge) and runs steps 4–9 (the driver's shadow parity: the GPU fed the reference's state).
// run() runs steps 1–9 on the GPU with no download between steps (it reads one counter per
//   plate-growth cycle; bracket it with glFinish to time it), after which elevation_result() and
//   partition_result() download its output.
// run_jitter(), run_plate_growth(), run_elevation(): the steps of run() one at a time (for timing
//   each; each needs the ones before it to have run): step 1, steps 2–3 (reads one counter per
//   cycle), steps 4–9.
//
// Inputs:  sphere (CubeSphere of the params' resolution), params (PlanetParams); positions, partition.
//          Needs a current GlContext.
// Outputs: JitteredRegions<float>, PlatePartition, PlanetElevation<float> (core/planet/planet_state.hpp).
// Units:   as the reference: offsets in cells, positions dimensionless, elevations in generator units.
// Throws:  gt::InputError for a legacy mode, a resolution other than the cube sphere's or plates
//          outside 1..6R²; std::invalid_argument for inputs of the wrong size; std::runtime_error if
//          plate growth stalls (see generator.cpp) and when a shader does not compile or link or a
//          block does not match its C++ mirror.
// Twin:    reference/planet/jitter.hpp, plates.hpp and elevation.hpp.
#pragma once

#include <array>
#include <vector>

#include "core/params/planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/planet/planet_state.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class PlanetGenerator {
 public:
  PlanetGenerator(const CubeSphere& sphere, const PlanetParams& params);

  JitteredRegions<float> jitter();
  PlatePartition grow_plates();
  PlanetElevation<float> elevation(const std::vector<float>& positions, const PlatePartition& partition);

  void run();
  // The steps of run() one at a time (for timing each; each needs the ones before it to have run):
  // step 1, steps 2–3 (reads one counter per cycle), steps 4–9.
  void run_jitter() const;
  void run_plate_growth();
  void run_elevation() const;
  PlanetElevation<float> elevation_result() const;
  PlatePartition partition_result() const;

 private:
  struct Programs {
    ComputeProgram jitter, plate_seeds, plate_expansions, plate_claim, plate_edges;
    ComputeProgram centre_sums, plate_motion, elevation_noise, elevation_collision, elevation_smooth;
  };

  void bind_buffers() const;
  void dispatch_regions(const ComputeProgram& program) const;
  void dispatch_plates(const ComputeProgram& program) const;
  void run_growth_cycle(int cycle);

  PlanetParams params_;
  int region_count_;
  int max_expansions_;
  int cycles_ = 0;
  Programs programs_;
  UniformBuffer block_;
  StorageBuffer neighbours_;
  StorageBuffer offsets_;
  StorageBuffer positions_;
  std::array<StorageBuffer, 2> plate_buffers_;  // plate_buffers_[current_plate_]: the partition
  int current_plate_ = 0;
  StorageBuffer permutation_;
  StorageBuffer is_edge_;
  StorageBuffer plates_;
  StorageBuffer assigned_count_;
  StorageBuffer centre_sums_;
  StorageBuffer noisy_;
  StorageBuffer collided_;
  StorageBuffer smoothed_;
};

}  // namespace gt::gpu
