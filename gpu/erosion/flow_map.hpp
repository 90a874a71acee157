// The flow map of seed 000 (Hydra, §4.7, eqs. 4.12-4.13), GPU twin.
//
// FlowMap(width, height, constants) compiles gpu/shaders/erosion/flow_map_droplets.comp and
//   flow_map_plug.comp (with FLOW_BATCH in the batch ordering) and allocates the buffers.
// load(heights) uploads the heights (read only) and their mask and clears the map.
// run() dispatches the spacing² passes of one droplet per spacing x spacing block, then the plug pass
//   (bracket with glFinish to time it).
// result() downloads the concentration after the plug pass.
// Race and disjoint leave eq. 4.12 in place (racing where paths cross, as upstream); batch counts
// weights by atomicAdd (order-independent). Buffer bindings: 0 parameter block, 1 heights, 2 valid,
// 3 concentration (float; batch: int weight counts), 4 after the plug pass.
//
// Inputs:  width, height and constants (core/params/particle.hpp's FlowConstants); heights:
//          Grid<float> of that size with its mask (Grid::valid, empty = all valid). Needs a current
//          GlContext.
// Outputs: the concentration after the plug pass, in [0, 1], with the heights' geometry and mask.
// Units:   heights in the caller's units; concentration dimensionless.
// Throws:  std::invalid_argument for a spacing below 1 and a load of another size; std::runtime_error
//          when a shader does not compile or link, lacks pass_offset, or its block does not match the
//          C++ mirror.
// Twin:    reference/erosion/flow_map.hpp.
#pragma once

#include "core/grid.hpp"
#include "core/params/particle.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class FlowMap {
 public:
  FlowMap(int width, int height, const FlowConstants& constants);
  void load(const Grid<float>& heights);  // heights and mask (Grid::valid, empty = all valid); clears the map
  void run() const;                       // every pass of one flow map, then the plug pass
  Grid<float> result() const;             // the concentration after the plug pass

 private:
  int spacing_;
  int droplets_x_;  // ceil(width / spacing)
  int droplets_y_;  // ceil(height / spacing)
  Grid<float> layout_;  // geometry, units and mask of the loaded field, values unused
  ComputeProgram droplets_program_;
  ComputeProgram plug_program_;
  GLint offset_location_;  // `pass_offset` of flow_map_droplets.comp
  UniformBuffer block_;
  StorageBuffer heights_;
  StorageBuffer valid_;
  StorageBuffer flow_;     // one float (batch: int weight count) per cell
  StorageBuffer plugged_;  // one float per cell
};

}  // namespace gt::gpu
