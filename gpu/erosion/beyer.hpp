// Droplet hydraulic erosion after Beyer 2015 (seed 000 §2.7, eqs. 2.35-2.45; digest 000 §3.7), GPU twin.
//
// BeyerErosion(width, height, constants) compiles gpu/shaders/erosion/beyer_droplets.comp (and
//   beyer_apply.comp for the batch ordering) and allocates the buffers.
// load(heights, iterations_done) uploads a float heightfield and its mask and sets the droplet counter
//   to the iterations behind those heights (0: a run's start; a state resumed mid-run numbers its
//   droplets as the whole run would).
// run() dispatches constants.iterations outer iterations, each spacing² passes of one droplet per
//   spacing x spacing block (Algorithm 7), without synchronisation (bracket with glFinish to time it).
// step(count) dispatches `count` outer iterations from the current state, the droplets numbered on
//   from the previous call's (so load + step(a) + step(b) equals load + run() for a + b iterations);
//   with c_b > 0 each iteration ends with eq. 2.43's blend (gpu/erosion/blur_blend.hpp), applied in
//   batch ordering as one more delta.
// result() downloads.
// Orderings as core/params/droplets.hpp: race and disjoint run the droplets of a pass in place on one
// height buffer; batch freezes the heights during a pass and applies the droplets' fixed-point delta
// when it ends.
//
// Inputs:  width, height and constants (core/params/beyer.hpp); heights: Grid<float> of that size with
//          its mask (Grid::valid, empty = all valid; masked samples are never read or written: a
//          droplet whose cell touches one is off the map, the brush skips them). Needs a current GlContext.
// Outputs: result(): the heights, with the geometry, units and mask of the last load.
// Units:   positions in texels, heights in the caller's units.
// Throws:  std::invalid_argument for a spacing below 1, a batch ordering without a quantum > 0 and a
//          load of another size; std::runtime_error when a shader does not compile or link, lacks
//          pass_offset or pass_number, or its block does not match the C++ mirror.
// Twin:    reference/erosion/beyer.hpp.
#pragma once

#include <cstdint>
#include <optional>

#include "core/grid.hpp"
#include "core/params/beyer.hpp"
#include "gpu/buffer.hpp"
#include "gpu/erosion/blur_blend.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class BeyerErosion {
 public:
  BeyerErosion(int width, int height, const BeyerConstants& constants);
  // heights and mask (Grid::valid, empty = all valid), with `iterations_done` iterations behind them
  void load(const Grid<float>& heights, int iterations_done = 0);
  void run();                              // constants.iterations outer iterations
  void step(int count);                    // `count` outer iterations from the current state
  Grid<float> result() const;              // download, geometry/units/mask of the last load

 private:
  bool batch() const { return apply_program_.has_value(); }
  void bind() const;
  // One draw of Algorithm 7: every droplet of the pass with offset (offset_x, offset_y), numbered
  // from `pass_number` (iteration·S² + offset_y·S + offset_x), then (batch) the delta applied.
  void run_pass(int offset_x, int offset_y, std::uint32_t pass_number) const;
  // Eq. 2.43 after an iteration (c_b > 0), then (batch) its delta applied.
  void blend_with_blur();

  int iterations_;
  int spacing_;
  int droplets_x_;  // ceil(width / spacing)
  int droplets_y_;  // ceil(height / spacing)
  std::uint32_t iterations_done_ = 0;  // outer iterations behind the heights (droplet numbering)
  Grid<float> layout_;  // geometry, units and mask of the loaded field, values unused
  ComputeProgram droplets_program_;
  std::optional<ComputeProgram> apply_program_;  // batch ordering only
  GLint offset_location_;                        // `pass_offset` of beyer_droplets.comp
  GLint pass_number_location_;                   // `pass_number` of beyer_droplets.comp
  UniformBuffer block_;
  StorageBuffer heights_;
  StorageBuffer valid_;
  StorageBuffer delta_;  // batch: one int per cell; otherwise 16 unused bytes
  std::optional<BlurBlend> blur_blend_;  // c_b > 0 only
};

}  // namespace gt::gpu
