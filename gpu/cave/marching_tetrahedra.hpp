// Marching tetrahedra of the endless cave on the GPU (seed 004 digest §2.6), GPU twin.
//
// The same mesh as the reference triangle by triangle, the same vertex numbering and edge keys, the
// same position bits (on llvmpipe; see gpu/shaders/cave/lattice.glsl for the division on other GPUs).
//
// Two sources of the density, one mesher (the source is a constructor argument; every later pass
// is shared):
//   MarchingTetrahedra(params[, placement]): the seed's cave. The density pass computes
//     reference/cave/density.hpp's float density over the block params describes (origin, size,
//     solid, scale, threshold, kernel, seed); the twin of marching_tetrahedra<float> applied to
//     cave_density<float>(params).
//   MarchingTetrahedra(density, threshold, solid, lattice_origin[, placement]): any scalar volume
//     (e.g. core/io/volume_io.hpp's, converted to float). Its samples are uploaded into
//     the density buffer once, sample (0, 0, 0) at global lattice point lattice_origin, and run()
//     skips the density pass; the twin of marching_tetrahedra<float>(density, threshold, solid,
//     lattice_origin, placement). density.origin and density.spacing are ignored, as by the
//     reference.
// Either constructor compiles the programs, allocates the per-sample and per-cube buffers and
// tabulates the 256 rock patterns of a cube (gpu/shaders/cave/cube_cases.comp). run() executes the
// passes on the GPU:
//   1. density   gpu/shaders/cave/density.comp   one invocation per sample, (size + 1)³ (noise only)
//   2. count     gpu/shaders/cave/count.comp     one per cube (+1): rock corners, triangles and
//                                                own vertices
//   3. scan      gpu/cave/exclusive_scan.hpp     both counts -> offsets and totals
//   4. emit      gpu/shaders/cave/emit.comp      one per cube: triangles, positions, edge keys
// (workgroups of 256 invocations throughout, spread over two dimensions: linear_dispatch.hpp)
// Between 3 and 4 it reads the two totals back to size the outputs (a wait for the GPU); after 4
// it does not synchronise (bracket with glFinish to time it). Outputs larger than
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE (a 256³ block's 457 MB of triangles on llvmpipe's 128 MiB) are
// emitted in chunks of cubes, each through windows of the output buffers (glBindBufferRange).
// result() downloads the mesh: positions in global lattice coordinates (world units), triangles
// counter-clockwise seen from the air, edge_keys one per vertex. An all-air or all-rock block
// (open) gives an empty mesh.
//
// The placement mirrors reference::EdgePlacement (CaveParams has no field for it): linear, the
// seed's "shifting along the edge", or midpoint, its first version.
// move_to(origin): the same block shape at another lattice origin (the endless cave's slabs): rewrites
//   the parameter block only, no recompilation or reallocation. The noise is computed at the new
//   origin; an uploaded volume keeps its samples, placed there.
// limit_output_windows(bytes): emits outputs through windows of at most `bytes` each instead of the
//   driver's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (tests split small blocks this way).
//
// Inputs:  params (CaveParams: origin, size, solid, scale, threshold, kernel, seed) or a scalar volume
//          (Volume<float>, threshold, solid, lattice_origin); placement. Needs a current GlContext.
// Outputs: result(): TriangleMesh<float> with positions, triangles and edge_keys (above).
// Units:   world units (global lattice coordinates).
// Throws:  gt::InputError for a block below 1 cell (2 samples) per axis (which the reference meshes
//          as nothing, or a cap), a block (pad included) outside the edge keys' range or, for an
//          uploaded volume, a non-finite sample (both as the reference), and a block with more cubes
//          than 32-bit triangle offsets allow (move_to() like the constructor); std::invalid_argument
//          for a volume whose values are not nx·ny·nz samples, and from limit_output_windows() when a
//          window could not hold one cube's worst case; std::runtime_error when a per-sample or per-cube
//          buffer would exceed GL_MAX_SHADER_STORAGE_BLOCK_SIZE (about 320³ cells), and when a shader
//          does not compile or link or its block does not match the C++ mirror.
// Twin:    reference/cave/marching_tetrahedra.hpp (marching_tetrahedra<float>; with the seed's cave,
//          applied to reference/cave/density.hpp's cave_density<float>(params)).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.hpp"
#include "core/params/cave.hpp"
#include "core/volume.hpp"
#include "gpu/buffer.hpp"
#include "gpu/cave/exclusive_scan.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

enum class EdgePlacement { linear, midpoint };

class MarchingTetrahedra {
 public:
  explicit MarchingTetrahedra(const CaveParams& params, EdgePlacement placement = EdgePlacement::linear);
  MarchingTetrahedra(const Volume<float>& density, float threshold, bool solid,
                     const std::array<int, 3>& lattice_origin, EdgePlacement placement = EdgePlacement::linear);
  // The same block shape at another lattice origin (the endless cave's slabs): rewrites the
  // parameter block only, no recompilation or reallocation. Throws InputError like the constructor.
  // The noise is computed at the new origin; an uploaded volume keeps its samples, placed there.
  void move_to(const std::array<int, 3>& origin);
  // Emits outputs through windows of at most `bytes` each instead of the driver's
  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE (tests split small blocks this way). Throws
  // std::invalid_argument when a window could not hold one cube's worst case.
  void limit_output_windows(std::size_t bytes);
  void run();
  TriangleMesh<float> result() const;

 private:
  enum class DensitySource { noise, upload };
  // The density pass of the seed's cave: its permutation table and program.
  struct NoisePass {
    StorageBuffer permutation;
    ComputeProgram program;
  };
  static NoisePass noise_pass(std::uint32_t seed);

  // Checks the block, then allocates and tabulates; an upload is left to the caller.
  MarchingTetrahedra(const CaveParams& block, EdgePlacement placement, DensitySource source);
  // A run of cubes emitted by one dispatch, and the windows of the outputs it writes (in elements:
  // triangles, vertices; bases aligned for glBindBufferRange).
  struct EmitChunk {
    std::size_t first_cube, end_cube;
    std::size_t triangle_base, triangle_end;
    std::size_t vertex_base, vertex_end;
  };
  void compute_density();
  std::vector<EmitChunk> emit_chunks() const;
  void emit();

  std::size_t sample_total_;
  std::size_t cube_total_;
  std::int64_t storage_block_limit_;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE in bytes
  std::size_t output_window_limit_;   // bytes an output window may span: the above unless limited
  std::size_t offset_alignment_;      // GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT in bytes
  CaveParams params_;  // the block; for an uploaded volume its noise fields (scale, kernel, seed) are unused
  EdgePlacement placement_;
  UniformBuffer block_;
  std::optional<NoisePass> noise_;  // empty for an uploaded volume
  StorageBuffer density_;
  StorageBuffer triangle_offsets_;  // per cube + 1: counts, then their exclusive scan
  StorageBuffer vertex_offsets_;
  StorageBuffer cube_rock_;   // per cube: bit c set iff corner c is rock
  StorageBuffer cube_cases_;  // tables of gpu/shaders/cave/cube_cases.glsl, filled by the constructor
  ComputeProgram count_program_;
  ComputeProgram emit_program_;
  ExclusiveScan scan_;
  std::uint32_t triangle_total_ = 0;
  std::uint32_t vertex_total_ = 0;
  std::optional<StorageBuffer> triangles_;  // sized by run() from the totals, reused when big enough
  std::optional<StorageBuffer> positions_;
  std::optional<StorageBuffer> edge_keys_;
};

}  // namespace gt::gpu
