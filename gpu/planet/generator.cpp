// Host side of the GPU Earth-like planet generator: the std140 parameter block, the storage buffers,
// the pass order and the plate-growth loop. See generator.hpp; formulas and float decisions in the
// shaders (gpu/shaders/planet/) and core/params/planet.hpp.
//
// Growth stops when every region has a plate. A cycle can legitimately add nothing (every plate
// drew no extra ring), but each plate's rate is >= 1/256, so while a region still lacks a plate a
// cycle adds one with probability >= 1/256: 16,384 cycles in a row without progress have
// probability <= (255/256)^16384 < e^−64, and mean a broken pass rather than bad luck.
#include "gpu/planet/generator.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/noise/permutation.hpp"
#include "core/params/noise_fractal.hpp"
#include "gpu/noise/fractal_terms_layout.hpp"

namespace gt::gpu {
namespace {

// Mirror of `PlanetBlock` in gpu/shaders/planet/planet.glsl (std140; the struct member aligned to 16).
struct PlanetBlock {
  std::int32_t face_rows[18][4];
  std::int32_t region_count;
  std::int32_t plate_count;
  std::uint32_t seed;
  std::int32_t resolution;
  float jitter;
  float warp_angle;
  float tan_warp_angle;
  float rate_low;
  float rate_high;
  float elevation_range;
  float collision_strength;
  float perlin_frequency;
  float perlin_strength;
  float ocean_share;
  float padding[2];
  FractalTerms<float> fractal_terms;
  float padding_end;
};

// Mirror of `PlateRecord` in planet.glsl (std430).
struct PlateRecord {
  float centre[4];
  float shift[4];
  float base;
  float rate;
  std::int32_t expansions;
  std::int32_t seed_region;
};

constexpr int region_local_size = 256, plate_local_size = 64;
constexpr int stalled_cycle_limit = 16384;
constexpr GLuint block_binding = 0;
// Storage bindings of planet.glsl.
enum Binding : GLuint {
  neighbours_binding = 0,
  offsets_binding = 1,
  positions_binding = 2,
  plate_binding = 3,
  plate_next_binding = 4,
  permutation_binding = 5,
  is_edge_binding = 6,
  plates_binding = 7,
  assigned_binding = 8,
  centre_sums_binding = 9,
  noisy_binding = 10,
  collided_binding = 11,
  smoothed_binding = 12,
};

// params, once checked: what the GPU twin cannot run is refused.
const PlanetParams& supported(const CubeSphere& sphere, const PlanetParams& params) {
  if (params.plate_rule != PlateRule::synchronous) {
    throw InputError(fmt::format("planet on the GPU: plate_rule '{}' (the seed code's sequential fill) is CPU only; "
                                 "use 'synchronous'",
                                 plate_rule_name(params.plate_rule)));
  }
  if (params.smoothing == Smoothing::legacy) {
    throw InputError("planet on the GPU: smoothing 'legacy' (the seed code's in-place blend) is CPU only; "
                     "use 'jacobi' or 'off'");
  }
  if (params.resolution != sphere.resolution()) {
    throw InputError(fmt::format("planet on the GPU: resolution {} differs from the cube sphere's {}",
                                 params.resolution, sphere.resolution()));
  }
  if (params.plates < 1 || params.plates > params.region_count()) {
    throw InputError(fmt::format("planet on the GPU: plates = {} is outside 1..{} (6R²)", params.plates,
                                 params.region_count()));
  }
  return params;
}

std::string stream_define(const char* name, std::uint32_t stream) {
  return fmt::format("PLANET_STREAM_{}={:#x}u", name, stream);
}

std::vector<std::string> program_defines(const PlanetParams& params) {
  std::vector<std::string> defines = {
      stream_define("JITTER", planet_stream_jitter),       stream_define("PLATE_SEED", planet_stream_plate_seed),
      stream_define("RATE", planet_stream_rate),           stream_define("EXPANSION", planet_stream_expansion),
      stream_define("SHIFT", planet_stream_shift),         stream_define("ELEVATION", planet_stream_elevation)};
  if (params.centre == PlateCentre::edge_sum) defines.emplace_back("PLANET_CENTRE_EDGE_SUM");
  if (params.noise) defines.emplace_back("PLANET_NOISE");
  if (params.plate_bases == PlateBases::bimodal) defines.emplace_back("PLANET_BIMODAL_BASES");
  if (params.collisions) defines.emplace_back("PLANET_COLLISIONS");
  if (params.pressure == PressureFormula::thesis) defines.emplace_back("PLANET_PRESSURE_THESIS");
  if (params.smooths()) defines.emplace_back("PLANET_SMOOTHS");
  return defines;
}

// The pass `name` (planet/NAME.comp), its PlanetBlock and its PlateRecord checked against their mirrors.
ComputeProgram planet_program(const char* name, const PlanetParams& params) {
  ComputeProgram program = ComputeProgram::load(fmt::format("planet/{}.comp", name), program_defines(params));
  BlockLayout layout = {{"face_rows", offsetof(PlanetBlock, face_rows)},
                        {"region_count", offsetof(PlanetBlock, region_count)},
                        {"plate_count", offsetof(PlanetBlock, plate_count)},
                        {"seed", offsetof(PlanetBlock, seed)},
                        {"resolution", offsetof(PlanetBlock, resolution)},
                        {"jitter", offsetof(PlanetBlock, jitter)},
                        {"warp_angle", offsetof(PlanetBlock, warp_angle)},
                        {"tan_warp_angle", offsetof(PlanetBlock, tan_warp_angle)},
                        {"rate_low", offsetof(PlanetBlock, rate_low)},
                        {"rate_high", offsetof(PlanetBlock, rate_high)},
                        {"elevation_range", offsetof(PlanetBlock, elevation_range)},
                        {"collision_strength", offsetof(PlanetBlock, collision_strength)},
                        {"perlin_frequency", offsetof(PlanetBlock, perlin_frequency)},
                        {"perlin_strength", offsetof(PlanetBlock, perlin_strength)},
                        {"ocean_share", offsetof(PlanetBlock, ocean_share)}};
  const auto terms = fractal_terms_layout("fractal_terms", offsetof(PlanetBlock, fractal_terms));
  layout.insert(layout.end(), terms.begin(), terms.end());
  program.check_block("PlanetBlock", sizeof(PlanetBlock), layout);
  program.check_block("Plates", sizeof(PlateRecord),
                      {{"plates[0].centre", offsetof(PlateRecord, centre)},
                       {"plates[0].shift", offsetof(PlateRecord, shift)},
                       {"plates[0].base", offsetof(PlateRecord, base)},
                       {"plates[0].rate", offsetof(PlateRecord, rate)},
                       {"plates[0].expansions", offsetof(PlateRecord, expansions)},
                       {"plates[0].seed_region", offsetof(PlateRecord, seed_region)}});
  return program;
}

UniformBuffer block_buffer(const PlanetParams& params) {
  PlanetBlock block{};
  for (int face = 0; face < cube_face_count; ++face) {
    const FaceMatrix& matrix = face_matrix(static_cast<CubeFace>(face));
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 3; ++column) block.face_rows[3 * face + row][column] = matrix[row][column];
    }
  }
  const PlateRateBounds rates = plate_rate_bounds(params);
  block.region_count = params.region_count();
  block.plate_count = params.plates;
  block.seed = params.seed;
  block.resolution = params.resolution;
  block.jitter = static_cast<float>(params.jitter);
  const CubeWarp warp = cube_warp(params.warp);
  block.warp_angle = static_cast<float>(warp.angle);
  block.tan_warp_angle = static_cast<float>(std::tan(warp.angle));
  block.rate_low = rates.low;
  block.rate_high = rates.high;
  block.elevation_range = static_cast<float>(params.elevation_range);
  block.collision_strength = static_cast<float>(params.collision_strength);
  block.perlin_frequency = static_cast<float>(params.perlin_frequency);
  block.perlin_strength = static_cast<float>(params.perlin_strength);
  block.ocean_share = static_cast<float>(params.ocean_share);
  block.fractal_terms = fractal_terms<float>(
      FractalParams{.octaves = static_cast<double>(params.perlin_octaves), .lacunarity = 2.0, .gain = 0.5});
  return UniformBuffer::from(block);
}

std::size_t region_bytes(const PlanetParams& params, std::size_t per_region) {
  return static_cast<std::size_t>(params.region_count()) * per_region;
}

void fill_int(const StorageBuffer& buffer, std::int32_t value) {
  glClearNamedBufferData(buffer.id(), GL_R32I, GL_RED_INTEGER, GL_INT, &value);
}

void fill_uint(const StorageBuffer& buffer, std::uint32_t value) {
  glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

void storage_barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

void download_barrier() { glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); }

Vector3<float> xyz(const float (&vector)[4]) { return {vector[0], vector[1], vector[2]}; }

void check_size(const char* what, std::size_t size, std::size_t expected) {
  if (size != expected) {
    throw std::invalid_argument(fmt::format("planet on the GPU: {} has {} values, expected {}", what, size, expected));
  }
}

}  // namespace

PlanetGenerator::PlanetGenerator(const CubeSphere& sphere, const PlanetParams& params)
    : params_(supported(sphere, params)),
      region_count_(params.region_count()),
      max_expansions_(plate_rate_bounds(params).max_expansions),
      programs_{planet_program("jitter", params),           planet_program("plate_seeds", params),
                planet_program("plate_expansions", params), planet_program("plate_claim", params),
                planet_program("plate_edges", params),      planet_program("centre_sums", params),
                planet_program("plate_motion", params),     planet_program("elevation_noise", params),
                planet_program("elevation_collision", params), planet_program("elevation_smooth", params)},
      block_(block_buffer(params)),
      neighbours_(StorageBuffer::from(sphere.neighbour_table())),
      offsets_(region_bytes(params, 2 * sizeof(float))),
      positions_(region_bytes(params, 4 * sizeof(float))),
      plate_buffers_{StorageBuffer(region_bytes(params, sizeof(std::int32_t))),
                     StorageBuffer(region_bytes(params, sizeof(std::int32_t)))},
      permutation_(StorageBuffer::from(doubled_permutation(seeded_permutation(params.seed)))),
      is_edge_(region_bytes(params, sizeof(std::uint32_t))),
      plates_(static_cast<std::size_t>(params.plates) * sizeof(PlateRecord)),
      assigned_count_(sizeof(std::uint32_t)),
      centre_sums_(static_cast<std::size_t>(params.plates) * 6 * sizeof(std::uint32_t)),
      noisy_(region_bytes(params, sizeof(float))),
      collided_(region_bytes(params, sizeof(float))),
      smoothed_(region_bytes(params, sizeof(float))) {}

void PlanetGenerator::bind_buffers() const {
  block_.bind(block_binding);
  neighbours_.bind(neighbours_binding);
  offsets_.bind(offsets_binding);
  positions_.bind(positions_binding);
  plate_buffers_[current_plate_].bind(plate_binding);
  plate_buffers_[1 - current_plate_].bind(plate_next_binding);
  permutation_.bind(permutation_binding);
  is_edge_.bind(is_edge_binding);
  plates_.bind(plates_binding);
  assigned_count_.bind(assigned_binding);
  centre_sums_.bind(centre_sums_binding);
  noisy_.bind(noisy_binding);
  collided_.bind(collided_binding);
  smoothed_.bind(smoothed_binding);
}

void PlanetGenerator::dispatch_regions(const ComputeProgram& program) const {
  program.dispatch(region_count_, 1, region_local_size, 1);
  storage_barrier();
}

void PlanetGenerator::dispatch_plates(const ComputeProgram& program) const {
  program.dispatch(params_.plates, 1, plate_local_size, 1);
  storage_barrier();
}

void PlanetGenerator::run_jitter() const {
  bind_buffers();
  dispatch_regions(programs_.jitter);
}

void PlanetGenerator::run_growth_cycle(int cycle) {
  const ComputeProgram& expansions = programs_.plate_expansions;
  glProgramUniform1i(expansions.id(), expansions.uniform("cycle"), cycle);
  dispatch_plates(expansions);
  const ComputeProgram& claim = programs_.plate_claim;
  for (int sub_step = 0; sub_step < max_expansions_; ++sub_step) {
    glProgramUniform1i(claim.id(), claim.uniform("sub_step"), sub_step);
    dispatch_regions(claim);
    current_plate_ = 1 - current_plate_;
    bind_buffers();
  }
}

void PlanetGenerator::run_plate_growth() {
  current_plate_ = 0;
  fill_int(plate_buffers_[current_plate_], -1);
  bind_buffers();
  programs_.plate_seeds.dispatch(1, 1, 1, 1);
  storage_barrier();
  download_barrier();
  std::uint32_t assigned = assigned_count_.download<std::uint32_t>(1)[0];
  int stalled = 0;
  // Mutant: the cycle count, which keys the expansion draws, carries on from the last run.
  for (cycles_ = mutant_active("planet.plates.gpu_cycles_carried_over") ? cycles_ : 0; assigned < static_cast<std::uint32_t>(region_count_); ++cycles_) {
    run_growth_cycle(cycles_);
    download_barrier();
    const std::uint32_t before = assigned;
    assigned = assigned_count_.download<std::uint32_t>(1)[0];
    stalled = assigned == before ? stalled + 1 : 0;
    if (stalled == stalled_cycle_limit) {
      throw std::runtime_error(fmt::format("planet on the GPU: plate growth added no region in {} cycles ({} of {} "
                                           "regions assigned)",
                                           stalled_cycle_limit, assigned, region_count_));
    }
  }
  dispatch_regions(programs_.plate_edges);
}

void PlanetGenerator::run_elevation() const {
  bind_buffers();
  fill_uint(centre_sums_, 0);
  dispatch_regions(programs_.centre_sums);
  dispatch_plates(programs_.plate_motion);
  dispatch_regions(programs_.elevation_noise);
  dispatch_regions(programs_.elevation_collision);
  dispatch_regions(programs_.elevation_smooth);
}

JitteredRegions<float> PlanetGenerator::jitter() {
  run_jitter();
  download_barrier();
  JitteredRegions<float> regions;
  regions.offsets = offsets_.download<float>(2 * static_cast<std::size_t>(region_count_));
  const auto padded = positions_.download<float>(4 * static_cast<std::size_t>(region_count_));
  regions.positions.reserve(3 * static_cast<std::size_t>(region_count_));
  for (std::size_t region = 0; region < static_cast<std::size_t>(region_count_); ++region) {
    for (std::size_t axis = 0; axis < 3; ++axis) regions.positions.push_back(padded[4 * region + axis]);
  }
  return regions;
}

PlatePartition PlanetGenerator::grow_plates() {
  run_plate_growth();
  return partition_result();
}

PlanetElevation<float> PlanetGenerator::elevation(const std::vector<float>& positions, const PlatePartition& partition) {
  const auto count = static_cast<std::size_t>(region_count_);
  check_size("positions", positions.size(), 3 * count);
  check_size("partition.plate", partition.plate.size(), count);
  check_size("partition.is_edge", partition.is_edge.size(), count);
  std::vector<float> padded(4 * count, 0.0f);
  for (std::size_t region = 0; region < count; ++region) {
    for (std::size_t axis = 0; axis < 3; ++axis) padded[4 * region + axis] = positions[3 * region + axis];
  }
  positions_.upload(padded.data(), padded.size() * sizeof(float));
  plate_buffers_[current_plate_].upload(partition.plate.data(), count * sizeof(std::int32_t));
  const std::vector<std::uint32_t> is_edge(partition.is_edge.begin(), partition.is_edge.end());
  is_edge_.upload(is_edge.data(), count * sizeof(std::uint32_t));
  cycles_ = partition.cycles;
  run_elevation();
  return elevation_result();
}

void PlanetGenerator::run() {
  run_jitter();
  run_plate_growth();
  run_elevation();
}

PlanetElevation<float> PlanetGenerator::elevation_result() const {
  download_barrier();
  const auto count = static_cast<std::size_t>(region_count_);
  PlanetElevation<float> result;
  for (const PlateRecord& record : plates_.download<PlateRecord>(static_cast<std::size_t>(params_.plates))) {
    result.motion.centre.push_back(xyz(record.centre));
    result.motion.shift.push_back(xyz(record.shift));
    result.motion.base.push_back(record.base);
  }
  result.noisy = noisy_.download<float>(count);
  result.collided = collided_.download<float>(count);
  result.smoothed = smoothed_.download<float>(count);
  return result;
}

PlatePartition PlanetGenerator::partition_result() const {
  download_barrier();
  const auto count = static_cast<std::size_t>(region_count_);
  PlatePartition partition;
  partition.plate = plate_buffers_[current_plate_].download<std::int32_t>(count);
  const auto is_edge = is_edge_.download<std::uint32_t>(count);
  partition.is_edge.assign(is_edge.begin(), is_edge.end());
  // Mutant: the count includes the cycle whose claims found the last regions already taken.
  partition.cycles = cycles_ + (mutant_active("planet.plates.gpu_cycle_count_off_by_one") ? 1 : 0);
  return partition;
}

}  // namespace gt::gpu
