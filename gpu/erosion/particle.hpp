// Particle (droplet) water erosion of seed 000 (Hydra; digest 000 §4.4, Appendix A, Algorithms 4-7), GPU twin.
//
// ParticleErosion(width, height, constants, transport_colour = false) compiles
//   gpu/shaders/erosion/particle_droplets.comp (and particle_apply.comp for the batch ordering) and
//   allocates the buffers.
// load(heights) uploads a float heightfield and its mask and zeroes the side maps.
// load_colour(colour) uploads the colour map to transport (after each load(); needs transport_colour).
// run() dispatches constants.iterations outer iterations, each spacing² passes of one droplet per
//   spacing x spacing block (Algorithm 7), without synchronisation (bracket with glFinish to time it);
//   step(count) dispatches `count` outer iterations from the current state.
// result(), colour_result(), eroded_at_droplet(), deposited_at_droplet() download.
// Orderings as core/params/particle.hpp: race and disjoint run the droplets of a pass in place on one
// height buffer; batch freezes the heights during a pass and applies the droplets' fixed-point delta
// when it ends.
// Colour (§4.5): constructed with transport_colour = true, the kernel is compiled with PARTICLE_COLOUR
// and transports the colour map given by load_colour(). Constructed without it the kernel holds no
// colour code. Batch: colour frozen during a pass, the deposits' weighted mean applied at its end
// (gpu/shaders/erosion/particle_apply.comp). Buffer bindings: 0 parameter block, 1 heights, 2 valid,
// 3 batch delta, 4 eroded_at_droplet, 5 deposited_at_droplet, 6 colour (vec4), 7 batch colour sums
// (5 int per cell).
//
// Inputs:  width, height and constants (core/params/particle.hpp); heights: Grid<float> of that size
//          with its mask (Grid::valid, empty = all valid; masked cells read as 0 and are never
//          written, as cells off the grid); colour: ColourMap<float> (RGBA per texel, linear: the same
//          type as reference::ColourMap<float>) of the same size. Needs a current GlContext.
// Outputs: the heights and the transported colour, with the geometry, units and mask of the last load;
//          side maps: what the droplets eroded and deposited at the texel they stood on, summed over
//          the run since the last load() (no contrast): float sums (race, disjoint) or int32 counts of
//          quanta returned as float(count)·quantum (batch).
// Units:   positions in texels, heights in the caller's units.
// Throws:  std::invalid_argument for a spacing below 1, a batch ordering without a quantum > 0 and a
//          load or load_colour of another size; std::logic_error for load_colour() or colour_result()
//          without transport_colour, and for run() or step() with transport_colour but no load_colour()
//          since the last load(); std::runtime_error when a shader does not compile or link, lacks
//          pass_offset, or its block does not match the C++ mirror.
// Twin:    reference/erosion/particle.hpp.
#pragma once

#include <array>
#include <optional>

#include "core/grid.hpp"
#include "core/params/particle.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// RGBA per texel, linear: the same type as reference::ColourMap<float> (reference/erosion/droplets.hpp).
template <class Real>
using ColourMap = Grid<std::array<Real, 4>>;

class ParticleErosion {
 public:
  ParticleErosion(int width, int height, const ParticleConstants& constants, bool transport_colour = false);
  void load(const Grid<float>& heights);  // heights and mask (Grid::valid, empty = all valid); zeroes the side maps
  void load_colour(const ColourMap<float>& colour);  // after load(); needs transport_colour
  void run();                              // constants.iterations outer iterations
  void step(int count);                    // `count` outer iterations from the current state
  Grid<float> result() const;              // download, geometry/units/mask of the last load
  ColourMap<float> colour_result() const;  // the transported colour, geometry/units/mask of the last load
  Grid<float> eroded_at_droplet() const;    // side map: eroded by the droplets standing on each texel
  Grid<float> deposited_at_droplet() const;  // side map: deposited by the droplets standing on each texel

 private:
  bool batch() const { return apply_program_.has_value(); }
  void bind() const;
  Grid<float> side_map(const StorageBuffer& buffer) const;
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
  StorageBuffer eroded_;     // side map: one float (batch: int quanta) per cell
  StorageBuffer deposited_;  // side map: one float (batch: int quanta) per cell
  StorageBuffer colour_;       // transport_colour: one vec4 per cell; otherwise 16 unused bytes
  StorageBuffer colour_sums_;  // transport_colour and batch: 5 int per cell; otherwise 16 unused bytes
  float quantum_;              // batch: the quantum as the shader has it
  bool transport_colour_;
  bool colour_loaded_ = false;  // load_colour() since the last load()
};

}  // namespace gt::gpu
