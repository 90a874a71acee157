// Host side of the GPU marching tetrahedra: block checks, the std140 parameter block, buffer sizes
// against the driver's limit and the order of the passes (see marching_tetrahedra.hpp; the
// algorithm and its welding argument are in gpu/shaders/cave/tetrahedra.glsl).
//
// An uploaded volume is described by the same CaveParams block as the noise (size = samples - 1,
// origin, threshold, solid), so both sources share every check, buffer and pass; the only
// difference is the DensitySource, which decides between a NoisePass (the density dispatch in
// every run()) and one upload in the constructor (glNamedBufferSubData, ordered before later dispatches by GL).
//
// Bindings (all below 8, the GL 4.5 minimum; emit uses all eight): uniform 0 the CaveBlock;
// storage 0 the cube-case tables, 1 density, 2 triangle counts/offsets, 3 vertex counts/offsets,
// 4 triangles, 5 the permutation (noise/permutation.glsl) in the density pass and the per-cube
// rock corners in count and emit, 6 positions, 7 edge keys. The scan uses storage 0 and 1 itself,
// so every pass binds what it reads.
// Buffer sizes for a solid block of 256³ cells (257³ samples, 258³ = 17.2M cubes): density
// 67.9 MB; triangle offsets, vertex offsets and rock corners 68.7 MB each; scan block sums 67 KB;
// cube cases 134 KB. Outputs: 12 bytes per triangle, 12 + 8 per vertex; at scale 10 about 2.3
// triangles and 1.2 vertices per cube: 457 MB of triangles (measured, seed 3: 38.1M) and about
// 400 MB of vertices. That passes llvmpipe's 128 MiB storage-block limit, so the outputs are one
// buffer each, emitted chunk by chunk through windows of at most the limit (emit_chunks); the
// per-cube buffers reach the limit at about 320³ cells.
//
// Memory traffic per voxel (the performance table's floor column, which times an uploaded volume):
// 24 B read + 28 B written = 52 B over the count, two scans and emit passes (density f32 read,
// counts and rock flags u32 written, the two in-place scans 16 B read and written, emit's rock
// flags), plus 12 B per triangle and 20 B per vertex written; the seed's noise adds the density
// pass's 4 B written.
#include "gpu/cave/marching_tetrahedra.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/noise/permutation.hpp"
#include "gpu/cave/linear_dispatch.hpp"

namespace gt::gpu {
namespace {

// Mirror of `CaveBlock` in gpu/shaders/cave/cave_block.glsl (std140).
struct CaveBlock {
  std::int32_t lattice_origin[4];
  std::int32_t sample_counts[4];
  std::int32_t cube_counts[4];
  std::int32_t first_cube;
  float threshold;
  float world_to_noise;
  float kernel_radius_squared;
  std::uint32_t linear_placement;
  std::uint32_t padding[3];
};

// A program of cave_block.glsl, its CaveBlock checked against the mirror.
ComputeProgram cave_program(const char* shader) {
  ComputeProgram program = ComputeProgram::load(shader);
  program.check_block("CaveBlock", sizeof(CaveBlock),
                      {{"lattice_origin", offsetof(CaveBlock, lattice_origin)},
                       {"sample_counts", offsetof(CaveBlock, sample_counts)},
                       {"cube_counts", offsetof(CaveBlock, cube_counts)},
                       {"first_cube", offsetof(CaveBlock, first_cube)},
                       {"threshold", offsetof(CaveBlock, threshold)},
                       {"world_to_noise", offsetof(CaveBlock, world_to_noise)},
                       {"kernel_radius_squared", offsetof(CaveBlock, kernel_radius_squared)},
                       {"linear_placement", offsetof(CaveBlock, linear_placement)}});
  return program;
}

constexpr int local_size = 256;  // local_size_x of density.comp, count.comp and emit.comp
constexpr GLuint block_binding = 0, cube_cases_binding = 0, density_binding = 1, triangle_offsets_binding = 2, vertex_offsets_binding = 3,
                 triangles_binding = 4, permutation_binding = 5, cube_rock_binding = 5, positions_binding = 6, edge_keys_binding = 7;
constexpr std::size_t max_triangles_per_cube = 12;  // 6 tetrahedra, 2 triangles each
constexpr std::size_t max_owned_vertices_per_cube = 7;  // 3 axis, 3 face-diagonal and 1 body edges
constexpr std::size_t triangle_bytes = 3 * sizeof(std::uint32_t), position_bytes = 3 * sizeof(float),
                      key_bytes = 2 * sizeof(std::uint32_t);
constexpr std::size_t rock_patterns = 256, edge_slots = 64, first_axes_patterns = 8;
// Size of `CubeCases` in gpu/shaders/cave/cube_cases.glsl (std430: uint[256], then uvec2 arrays).
constexpr std::size_t cube_cases_bytes =
    rock_patterns * 4 + rock_patterns * 8 + first_axes_patterns * 8 + rock_patterns * edge_slots * 8;

using Counts = std::array<std::size_t, 3>;

Counts sample_counts(const CaveParams& params) {
  return {static_cast<std::size_t>(params.size[0]) + 1, static_cast<std::size_t>(params.size[1]) + 1,
          static_cast<std::size_t>(params.size[2]) + 1};
}

// Solid: one pad layer on every side (samples + 1 cubes); open: samples - 1 (lattice_cubes.hpp).
Counts cube_counts(const CaveParams& params) {
  const Counts samples = sample_counts(params);
  const std::size_t extra_cubes = params.solid ? 1 : 0;
  return {samples[0] - 1 + 2 * extra_cubes, samples[1] - 1 + 2 * extra_cubes, samples[2] - 1 + 2 * extra_cubes};
}

std::size_t product(const Counts& counts) { return counts[0] * counts[1] * counts[2]; }

std::string describe_block(const CaveParams& params) {
  return fmt::format("{}x{}x{} cells at lattice ({}, {}, {}){}", params.size[0], params.size[1], params.size[2],
                     params.origin[0], params.origin[1], params.origin[2], params.solid ? ", solid" : ", open");
}

// The sample count, after refusing blocks the mesher cannot name (the reference's checks).
std::size_t checked_sample_total(const CaveParams& params) {
  for (int axis = 0; axis < 3; ++axis) {
    if (params.size[axis] < 1) {
      throw InputError(fmt::format("GPU marching tetrahedra: block of {} needs at least one cell per axis",
                                   describe_block(params)));
    }
  }
  const std::array<std::int64_t, 3> origin{params.origin[0], params.origin[1], params.origin[2]};
  const std::array<std::int64_t, 3> samples{params.size[0] + 1, params.size[1] + 1, params.size[2] + 1};
  if (!lattice_range_fits(origin, samples, params.solid)) {
    throw InputError(fmt::format("GPU marching tetrahedra: block of {} leaves the edge-key range [{}, {}] per axis",
                                 describe_block(params), lattice_coordinate_min, lattice_coordinate_max));
  }
  return product(sample_counts(params));
}

// The cube count, after refusing blocks whose triangle offsets could pass 2^32.
std::size_t checked_cube_total(const CaveParams& params) {
  const std::size_t cubes = product(cube_counts(params));
  if (cubes * max_triangles_per_cube > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(fmt::format("GPU marching tetrahedra: block of {} has {} cubes, more than 32-bit triangle "
                                 "offsets allow ({} triangles per cube at most)",
                                 describe_block(params), cubes, max_triangles_per_cube));
  }
  return cubes;
}

std::size_t storage_offset_alignment() {
  GLint alignment = 0;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
  return static_cast<std::size_t>(std::max(alignment, 1));
}

// The block's storage for `contents`, named in the refusal as before.
StorageBuffer block_storage(std::size_t bytes, const char* contents, std::int64_t limit) {
  return limited_storage(bytes, fmt::format("GPU marching tetrahedra: the {}", contents), limit);
}

// `buffer` when it holds at least `bytes`, else a new buffer of that size.
void reserve(std::optional<StorageBuffer>& buffer, std::size_t bytes) {
  if (!buffer || buffer->size_bytes() < bytes) buffer.emplace(bytes);
}

CaveBlock block_of(const CaveParams& params, EdgePlacement placement) {
  CaveBlock block{};
  const Counts samples = sample_counts(params);
  const Counts cubes = cube_counts(params);
  for (int axis = 0; axis < 3; ++axis) {
    block.lattice_origin[axis] = params.origin[axis];
    block.sample_counts[axis] = static_cast<std::int32_t>(samples[axis]);
    block.cube_counts[axis] = static_cast<std::int32_t>(cubes[axis]);
  }
  block.sample_counts[3] = static_cast<std::int32_t>(product(samples));
  block.cube_counts[3] = static_cast<std::int32_t>(product(cubes));
  block.first_cube = params.solid ? -1 : 0;
  block.threshold = static_cast<float>(params.threshold);
  block.world_to_noise = static_cast<float>(1.0 / params.scale);
  block.kernel_radius_squared = static_cast<float>(params.kernel_radius_squared);
  block.linear_placement = placement == EdgePlacement::linear ? 1u : 0u;
  return block;
}

// Throws InputError naming the first non-finite sample, as the reference does.
void check_finite(const Volume<float>& density) {
  const auto first = std::find_if(density.values.begin(), density.values.end(),
                                  [](float value) { return !std::isfinite(value); });
  if (first == density.values.end()) return;
  const auto index = static_cast<std::size_t>(first - density.values.begin());
  const std::size_t row = static_cast<std::size_t>(density.nx);
  const std::size_t slice = row * static_cast<std::size_t>(density.ny);
  throw InputError(fmt::format("GPU marching tetrahedra: density sample ({}, {}, {}) is {}; the density must be finite",
                               index % row, index % slice / row, index / slice, *first));
}

// The block of an uploaded volume: its cells at `lattice_origin`, after checking its samples.
CaveParams volume_block(const Volume<float>& density, float threshold, bool solid,
                        const std::array<int, 3>& lattice_origin) {
  const std::size_t samples = static_cast<std::size_t>(density.nx) * static_cast<std::size_t>(density.ny) *
                              static_cast<std::size_t>(density.nz);
  if (density.values.size() != samples) {
    throw std::invalid_argument(fmt::format("GPU marching tetrahedra: a {}x{}x{} volume holds {} values",
                                            density.nx, density.ny, density.nz, density.values.size()));
  }
  check_finite(density);
  CaveParams block;
  block.origin = lattice_origin;
  block.size = {density.nx - 1, density.ny - 1, density.nz - 1};
  block.threshold = threshold;
  block.solid = solid;
  return block;
}

// The uint at `index` of a buffer the GPU wrote (waits for it).
std::uint32_t read_uint(const StorageBuffer& buffer, std::size_t index) {
  std::uint32_t value = 0;
  glGetNamedBufferSubData(buffer.id(), static_cast<GLintptr>(index * sizeof(value)), sizeof(value), &value);
  return value;
}

}  // namespace

MarchingTetrahedra::NoisePass MarchingTetrahedra::noise_pass(std::uint32_t seed) {
  return {StorageBuffer::from(doubled_permutation(seeded_permutation(seed))),
          cave_program("cave/density.comp")};
}

MarchingTetrahedra::MarchingTetrahedra(const CaveParams& params, EdgePlacement placement)
    : MarchingTetrahedra(params, placement, DensitySource::noise) {}

MarchingTetrahedra::MarchingTetrahedra(const Volume<float>& density, float threshold, bool solid,
                                       const std::array<int, 3>& lattice_origin, EdgePlacement placement)
    : MarchingTetrahedra(volume_block(density, threshold, solid, lattice_origin), placement, DensitySource::upload) {
  density_.upload(density.values.data(), sample_total_ * sizeof(float));
}

MarchingTetrahedra::MarchingTetrahedra(const CaveParams& block, EdgePlacement placement, DensitySource source)
    : sample_total_(checked_sample_total(block)),
      cube_total_(checked_cube_total(block)),
      storage_block_limit_(storage_block_limit()),
      output_window_limit_(static_cast<std::size_t>(storage_block_limit_)),
      offset_alignment_(storage_offset_alignment()),
      params_(block),
      placement_(placement),
      block_(UniformBuffer::from(block_of(block, placement))),
      noise_(source == DensitySource::noise ? std::optional(noise_pass(block.seed)) : std::nullopt),
      density_(block_storage(sample_total_ * sizeof(float), "density samples", storage_block_limit_)),
      triangle_offsets_(block_storage((cube_total_ + 1) * sizeof(std::uint32_t), "per-cube triangle offsets",
                                        storage_block_limit_)),
      vertex_offsets_(block_storage((cube_total_ + 1) * sizeof(std::uint32_t), "per-cube vertex offsets",
                                      storage_block_limit_)),
      cube_rock_(block_storage(cube_total_ * sizeof(std::uint32_t), "per-cube rock corners", storage_block_limit_)),
      cube_cases_(cube_cases_bytes),
      count_program_(cave_program("cave/count.comp")),
      emit_program_(cave_program("cave/emit.comp")),
      scan_(cube_total_ + 1) {
  const ComputeProgram cube_cases_program = ComputeProgram::load("cave/cube_cases.comp");
  cube_cases_.bind(cube_cases_binding);
  dispatch_linear(cube_cases_program, rock_patterns, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void MarchingTetrahedra::move_to(const std::array<int, 3>& origin) {
  CaveParams moved = params_;
  moved.origin = origin;
  checked_sample_total(moved);
  params_ = moved;
  block_.upload(block_of(params_, placement_));
}

void MarchingTetrahedra::limit_output_windows(std::size_t bytes) {
  if (bytes / triangle_bytes < offset_alignment_ + max_triangles_per_cube) {
    throw std::invalid_argument(fmt::format("GPU marching tetrahedra: output windows of {} bytes cannot hold one "
                                            "cube's {} triangles past an alignment of {} triangles",
                                            bytes, max_triangles_per_cube, offset_alignment_));
  }
  output_window_limit_ = std::min(bytes, static_cast<std::size_t>(storage_block_limit_));
}

void MarchingTetrahedra::run() {
  block_.bind(block_binding);
  density_.bind(density_binding);
  if (noise_) compute_density();

  cube_cases_.bind(cube_cases_binding);
  triangle_offsets_.bind(triangle_offsets_binding);
  vertex_offsets_.bind(vertex_offsets_binding);
  cube_rock_.bind(cube_rock_binding);
  dispatch_linear(count_program_, cube_total_ + 1, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  scan_.run(triangle_offsets_, cube_total_ + 1);
  scan_.run(vertex_offsets_, cube_total_ + 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

  triangle_total_ = read_uint(triangle_offsets_, cube_total_);
  vertex_total_ = read_uint(vertex_offsets_, cube_total_);
  if (triangle_total_ > 0) emit();
}

void MarchingTetrahedra::compute_density() {
  noise_->permutation.bind(permutation_binding);
  dispatch_linear(noise_->program, sample_total_, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// One chunk when all outputs fit a window; else runs of cubes sized for the worst case (12
// triangles and 7 owned vertices a cube, plus a base aligned down by less than the alignment).
// Reads the chunks' offsets back before any emit dispatch, so that the reads wait only once.
std::vector<MarchingTetrahedra::EmitChunk> MarchingTetrahedra::emit_chunks() const {
  const std::size_t alignment = offset_alignment_;  // elements: their byte offsets are multiples of it
  const bool fits = std::size_t{triangle_total_} * triangle_bytes <= output_window_limit_ &&
                    std::size_t{vertex_total_} * position_bytes <= output_window_limit_;
  const std::size_t cubes_per_chunk =
      fits ? cube_total_ : (output_window_limit_ / triangle_bytes - alignment) / max_triangles_per_cube;
  static_assert(max_owned_vertices_per_cube * position_bytes <= max_triangles_per_cube * triangle_bytes);
  std::vector<EmitChunk> chunks;
  for (std::size_t first = 0; first < cube_total_; first += cubes_per_chunk) {
    const std::size_t end = std::min(first + cubes_per_chunk, cube_total_);
    const std::size_t triangle_first = read_uint(triangle_offsets_, first);
    const std::size_t triangle_end = read_uint(triangle_offsets_, end);
    if (triangle_end == triangle_first) continue;  // no triangles: no vertices either
    const std::size_t vertex_base = read_uint(vertex_offsets_, first) / alignment * alignment;
    // A chunk may own no vertex; its window still spans one (the buffers have that much spare).
    const std::size_t vertex_end = std::max<std::size_t>(read_uint(vertex_offsets_, end), vertex_base + 1);
    chunks.push_back({first, end, triangle_first / alignment * alignment, triangle_end, vertex_base, vertex_end});
  }
  return chunks;
}

void MarchingTetrahedra::emit() {
  const std::size_t spare = offset_alignment_;  // elements past the end: see emit_chunks
  reserve(triangles_, (std::size_t{triangle_total_} + spare) * triangle_bytes);
  reserve(positions_, (std::size_t{vertex_total_} + spare) * position_bytes);
  reserve(edge_keys_, (std::size_t{vertex_total_} + spare) * key_bytes);
  block_.bind(block_binding);
  cube_cases_.bind(cube_cases_binding);
  density_.bind(density_binding);
  triangle_offsets_.bind(triangle_offsets_binding);
  vertex_offsets_.bind(vertex_offsets_binding);
  cube_rock_.bind(cube_rock_binding);
  const GLuint program = emit_program_.id();
  for (const EmitChunk& chunk : emit_chunks()) {
    triangles_->bind_range(triangles_binding, chunk.triangle_base * triangle_bytes,
                           (chunk.triangle_end - chunk.triangle_base) * triangle_bytes);
    positions_->bind_range(positions_binding, chunk.vertex_base * position_bytes,
                           (chunk.vertex_end - chunk.vertex_base) * position_bytes);
    edge_keys_->bind_range(edge_keys_binding, chunk.vertex_base * key_bytes,
                           (chunk.vertex_end - chunk.vertex_base) * key_bytes);
    glProgramUniform1ui(program, emit_program_.uniform("first_emitted_cube"), static_cast<GLuint>(chunk.first_cube));
    glProgramUniform1ui(program, emit_program_.uniform("end_emitted_cube"), static_cast<GLuint>(chunk.end_cube));
    glProgramUniform1ui(program, emit_program_.uniform("triangle_base"), static_cast<GLuint>(chunk.triangle_base));
    glProgramUniform1ui(program, emit_program_.uniform("vertex_base"), static_cast<GLuint>(chunk.vertex_base));
    dispatch_linear(emit_program_, chunk.end_cube - chunk.first_cube, local_size);
  }
}

TriangleMesh<float> MarchingTetrahedra::result() const {
  TriangleMesh<float> mesh;
  if (triangle_total_ == 0) return mesh;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  mesh.triangles = triangles_->download<std::array<std::uint32_t, 3>>(triangle_total_);
  mesh.positions = positions_->download<std::array<float, 3>>(vertex_total_);
  const auto key_words = edge_keys_->download<std::array<std::uint32_t, 2>>(vertex_total_);
  mesh.edge_keys.reserve(key_words.size());
  for (const auto& words : key_words) mesh.edge_keys.push_back(std::uint64_t{words[0]} | std::uint64_t{words[1]} << 32);
  return mesh;
}

}  // namespace gt::gpu
