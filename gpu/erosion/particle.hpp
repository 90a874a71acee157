// Particle (droplet) water erosion of seed 000 (Hydra, digest 000 §4.4, Appendix A, Algorithms
// 4-7), GPU twin of reference/erosion/particle.hpp.
//
// ParticleErosion(width, height, constants) compiles gpu/shaders/erosion/particle_droplets.comp
// (and particle_apply.comp for the batch ordering) and allocates the buffers; load() uploads a
// float heightfield and its mask (masked cells read as 0 and are never written, as cells off the
// grid); run() dispatches constants.iterations outer iterations, each spacing² passes of one
// droplet per spacing x spacing block (Algorithm 7), without synchronisation (bracket with glFinish
// to time it); step(count) dispatches `count` outer iterations from the current state; result()
// downloads. Orderings as core/params/particle.hpp: race and disjoint run the droplets of a pass in
// place on one height buffer; batch freezes the heights during a pass and applies the droplets'
// fixed-point delta when it ends. Positions in texels, heights in the caller's units.
// Needs a current GlContext.
#pragma once

#include <optional>

#include "core/grid.hpp"
#include "core/params/particle.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class ParticleErosion {
 public:
  ParticleErosion(int width, int height, const ParticleConstants& constants);
  void load(const Grid<float>& heights);  // heights and mask (Grid::valid, empty = all valid)
  void run();                              // constants.iterations outer iterations
  void step(int count);                    // `count` outer iterations from the current state
  Grid<float> result() const;              // download, geometry/units/mask of the last load

 private:
  bool batch() const { return apply_program_.has_value(); }
  void bind() const;
  // One draw of Algorithm 7: every droplet of the pass with offset (offset_x, offset_y), then (batch)
  // the delta applied.
  void run_pass(int offset_x, int offset_y) const;

  int iterations_;
  int spacing_;
  int droplets_x_;  // ceil(width / spacing)
  int droplets_y_;  // ceil(height / spacing)
  Grid<float> layout_;  // geometry, units and mask of the loaded field, values unused
  ComputeProgram droplets_program_;
  std::optional<ComputeProgram> apply_program_;  // batch ordering only
  GLint offset_location_;                        // `pass_offset` of particle_droplets.comp
  UniformBuffer block_;
  StorageBuffer heights_;
  StorageBuffer valid_;
  StorageBuffer delta_;  // batch: one int per cell; otherwise 16 unused bytes
};

}  // namespace gt::gpu
