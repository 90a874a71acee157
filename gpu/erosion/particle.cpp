// Host side of seed 000's particle erosion on the GPU (digest 000 §4.4, Appendix A, Algorithms
// 4-7): buffers, the std140 parameter block and Algorithm 7's dispatch loop. The kernel, its
// decisions (truncation toward zero in erode4 as upstream, off-grid and masked texels read 0 and
// ignore writes, the batch fixed-point rule) and its mutants are described in
// gpu/shaders/erosion/particle_droplets.comp; the CPU reference is reference/erosion/particle.cpp.
//
// Per outer iteration, for oy, ox in [0, S)²: one dispatch of particle_droplets.comp over the
// ceil(W/S) x ceil(H/S) droplets with pass_offset = (ox, oy) (glProgramUniform2i), then a storage
// barrier. Race and disjoint: the droplets work in place on `heights`. Batch (compiled with
// PARTICLE_BATCH): the droplets read `heights` and atomically add integer quanta into `delta`;
// particle_apply.comp then adds delta·quantum to each valid cell and clears delta, followed by
// another barrier. Constants are rounded to float once here (quantum and 1/quantum are powers of
// two, so both are exact). Mutants (compare/mutants/particle.cpp) live in the shader only.
// Side maps (bindings 4, 5) are always written: float sums in place, or (batch) int quanta by
// atomicAdd, converted on download as float(count)·quantum. Colour (transport_colour: PARTICLE_COLOUR
// in both programs): the vec4 map at binding 6, and in batch the 5-int-per-cell sums at binding 7
// that particle_apply.comp turns into the weighted mean and clears. load() zeroes the side maps and
// the colour sums; the colour itself comes from load_colour().
#include "gpu/erosion/particle.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/erosion/droplet_host.hpp"

namespace gt::gpu {
namespace {

// Mirror of `ParticleBlock` in gpu/shaders/erosion/particle_block.glsl (std140).
struct ParticleBlock {
  DropletBlockHead head;
  std::uint32_t interpolated_erosion;
  float acceleration;
  float bite;
  float release;
  float max_velocity;
  float drag;
  float capacity_factor;
  float max_jump;
  float quantum;
  float inverse_quantum;
  float colour_mixing;
  std::uint32_t interpolated_colour;
  std::uint32_t tail_padding[2];  // the std140 block's size rounded up to 16 bytes
};

enum Binding : GLuint {
  block_binding = 0,
  heights_binding = 1,
  valid_binding = 2,
  delta_binding = 3,
  eroded_binding = 4,
  deposited_binding = 5,
  colour_binding = 6,
  colour_sums_binding = 7
};
constexpr int colour_sums_per_cell = 5;  // Σ factor, Σ factor·r, ·g, ·b, ·a

bool is_batch(const ParticleConstants& constants) { return constants.ordering == DropletOrdering::batch; }

std::vector<std::string> program_defines(const ParticleConstants& constants, bool transport_colour) {
  std::vector<std::string> defines;
  if (is_batch(constants)) defines.push_back("PARTICLE_BATCH");
  if (transport_colour) defines.push_back("PARTICLE_COLOUR");
  return defines;
}

// A program of particle_block.glsl, its ParticleBlock checked against the mirror.
ComputeProgram particle_program(const char* shader, const ParticleConstants& constants, bool transport_colour) {
  ComputeProgram program = ComputeProgram::load(shader, program_defines(constants, transport_colour));
  program.check_block("ParticleBlock", sizeof(ParticleBlock),
                      droplet_block_layout(offsetof(ParticleBlock, head),
                                           {{"interpolated_erosion", offsetof(ParticleBlock, interpolated_erosion)},
                                            {"acceleration", offsetof(ParticleBlock, acceleration)},
                                            {"bite", offsetof(ParticleBlock, bite)},
                                            {"release", offsetof(ParticleBlock, release)},
                                            {"max_velocity", offsetof(ParticleBlock, max_velocity)},
                                            {"drag", offsetof(ParticleBlock, drag)},
                                            {"capacity_factor", offsetof(ParticleBlock, capacity_factor)},
                                            {"max_jump", offsetof(ParticleBlock, max_jump)},
                                            {"quantum", offsetof(ParticleBlock, quantum)},
                                            {"inverse_quantum", offsetof(ParticleBlock, inverse_quantum)},
                                            {"colour_mixing", offsetof(ParticleBlock, colour_mixing)},
                                            {"interpolated_colour", offsetof(ParticleBlock, interpolated_colour)}}));
  return program;
}

std::optional<ComputeProgram> apply_program(const ParticleConstants& constants, bool transport_colour) {
  if (!is_batch(constants)) return std::nullopt;
  return particle_program("erosion/particle_apply.comp", constants, transport_colour);
}

// Each constant rounded to float once from double, as the reference does.
ParticleBlock make_block(const ParticleConstants& constants, int width, int height) {
  ParticleBlock block{};
  block.head = droplet_block_head(width, height, constants.spacing, constants.lifetime, "ParticleErosion");
  block.interpolated_erosion = constants.interpolate ? 1u : 0u;
  block.acceleration = static_cast<float>(constants.acceleration);
  block.bite = static_cast<float>(constants.bite);
  block.release = static_cast<float>(constants.release);
  block.max_velocity = static_cast<float>(constants.max_velocity);
  block.drag = static_cast<float>(constants.drag);
  block.capacity_factor = static_cast<float>(constants.capacity_factor);
  block.max_jump = static_cast<float>(constants.max_jump);
  block.colour_mixing = static_cast<float>(constants.colour_mixing);
  block.interpolated_colour = constants.interpolate_colour ? 1u : 0u;
  if (is_batch(constants)) {
    if (!(constants.quantum > 0.0)) throw std::invalid_argument("ParticleErosion: batch ordering needs a quantum > 0");
    block.quantum = static_cast<float>(constants.quantum);
    block.inverse_quantum = static_cast<float>(1.0 / constants.quantum);
  }
  return block;
}

// One int per cell for the batch delta; a 16-byte placeholder (never bound) otherwise.
std::size_t delta_bytes(const ParticleConstants& constants, int width, int height) {
  return is_batch(constants) ? cell_count(width, height) * sizeof(std::int32_t) : 16;
}

// The colour map: one vec4 per cell when transported, a 16-byte placeholder (never bound) otherwise.
std::size_t colour_bytes(bool transport_colour, int width, int height) {
  return transport_colour ? cell_count(width, height) * 4 * sizeof(float) : 16;
}

// The batch colour sums: 5 ints per cell when colour is transported in batch, a placeholder otherwise.
std::size_t colour_sums_bytes(const ParticleConstants& constants, bool transport_colour, int width, int height) {
  return transport_colour && is_batch(constants)
             ? cell_count(width, height) * colour_sums_per_cell * sizeof(std::int32_t)
             : 16;
}

}  // namespace

ParticleErosion::ParticleErosion(int width, int height, const ParticleConstants& constants, bool transport_colour)
    : iterations_(constants.iterations),
      spacing_(checked_droplet_spacing(constants.spacing, "ParticleErosion")),
      droplets_x_(droplet_count(width, spacing_)),
      droplets_y_(droplet_count(height, spacing_)),
      layout_(empty_layout(width, height)),
      droplets_program_(particle_program("erosion/particle_droplets.comp", constants, transport_colour)),
      apply_program_(apply_program(constants, transport_colour)),
      offset_location_(droplets_program_.required_uniform("pass_offset")),
      block_(UniformBuffer::from(make_block(constants, width, height))),
      heights_(cell_count(width, height) * sizeof(float)),
      valid_(cell_count(width, height) * sizeof(GLuint)),
      delta_(delta_bytes(constants, width, height)),
      eroded_(cell_count(width, height) * sizeof(float)),
      deposited_(cell_count(width, height) * sizeof(float)),
      colour_(colour_bytes(transport_colour, width, height)),
      colour_sums_(colour_sums_bytes(constants, transport_colour, width, height)),
      quantum_(is_batch(constants) ? static_cast<float>(constants.quantum) : 0.0f),
      transport_colour_(transport_colour) {}

void ParticleErosion::load(const Grid<float>& heights) {
  layout_ = load_heightfield(heights, layout_.width, layout_.height, heights_, valid_, "ParticleErosion");
  // float 0 and int 0 share their bits: one zero vector serves every side map and sum.
  const std::vector<std::int32_t> zeros(heights.size() * (transport_colour_ && batch() ? colour_sums_per_cell : 1), 0);
  if (batch()) delta_.upload(zeros.data(), heights.size() * sizeof(std::int32_t));
  eroded_.upload(zeros.data(), heights.size() * sizeof(std::int32_t));
  deposited_.upload(zeros.data(), heights.size() * sizeof(std::int32_t));
  if (transport_colour_ && batch()) colour_sums_.upload(zeros.data(), zeros.size() * sizeof(std::int32_t));
  colour_loaded_ = false;
}

void ParticleErosion::load_colour(const ColourMap<float>& colour) {
  if (!transport_colour_) {
    throw std::logic_error("ParticleErosion::load_colour: constructed without transport_colour");
  }
  if (colour.width != layout_.width || colour.height != layout_.height ||
      colour.values.size() != cell_count(layout_.width, layout_.height)) {
    throw std::invalid_argument("ParticleErosion::load_colour: grid size differs from the constructor's");
  }
  static_assert(sizeof(std::array<float, 4>) == 4 * sizeof(float));
  colour_.upload(colour.values.data(), colour.values.size() * sizeof(std::array<float, 4>));
  colour_loaded_ = true;
}

void ParticleErosion::run() { step(iterations_); }

void ParticleErosion::step(int count) {
  if (transport_colour_ && !colour_loaded_) {
    throw std::logic_error("ParticleErosion: constructed with transport_colour: call load_colour() after load()");
  }
  bind();
  for (int iteration = 0; iteration < count; ++iteration) {
    for (int offset_y = 0; offset_y < spacing_; ++offset_y) {
      for (int offset_x = 0; offset_x < spacing_; ++offset_x) run_pass(offset_x, offset_y);
    }
  }
}

Grid<float> ParticleErosion::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  Grid<float> heights = layout_;
  heights.values = heights_.download<float>(cell_count(layout_.width, layout_.height));
  return heights;
}

ColourMap<float> ParticleErosion::colour_result() const {
  if (!transport_colour_) {
    throw std::logic_error("ParticleErosion::colour_result: constructed without transport_colour");
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  ColourMap<float> colour;
  colour.width = layout_.width;
  colour.height = layout_.height;
  colour.cell_size_x = layout_.cell_size_x;
  colour.cell_size_y = layout_.cell_size_y;
  colour.horizontal_unit = layout_.horizontal_unit;
  colour.vertical_unit = layout_.vertical_unit;
  colour.valid = layout_.valid;
  colour.values = colour_.download<std::array<float, 4>>(cell_count(layout_.width, layout_.height));
  return colour;
}

Grid<float> ParticleErosion::eroded_at_droplet() const { return side_map(eroded_); }

Grid<float> ParticleErosion::deposited_at_droplet() const { return side_map(deposited_); }

// Race and disjoint: the float sums. Batch: the int32 counts as float(count)·quantum, the conversion
// rounded to nearest and the product exact (a power of two), as the reference converts them.
Grid<float> ParticleErosion::side_map(const StorageBuffer& buffer) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::size_t cells = cell_count(layout_.width, layout_.height);
  Grid<float> map = layout_;
  if (!batch()) {
    map.values = buffer.download<float>(cells);
    return map;
  }
  const std::vector<std::int32_t> counts = buffer.download<std::int32_t>(cells);
  map.values.resize(cells);
  for (std::size_t i = 0; i < cells; ++i) map.values[i] = static_cast<float>(counts[i]) * quantum_;
  return map;
}

void ParticleErosion::bind() const {
  block_.bind(block_binding);
  heights_.bind(heights_binding);
  valid_.bind(valid_binding);
  if (batch()) delta_.bind(delta_binding);
  eroded_.bind(eroded_binding);
  deposited_.bind(deposited_binding);
  if (transport_colour_) colour_.bind(colour_binding);
  if (transport_colour_ && batch()) colour_sums_.bind(colour_sums_binding);
}

void ParticleErosion::run_pass(int offset_x, int offset_y) const {
  dispatch_droplet_pass(droplets_program_, offset_location_, offset_x, offset_y, droplets_x_, droplets_y_);
  if (apply_program_) dispatch_cell_pass(*apply_program_, layout_.width, layout_.height);
}

}  // namespace gt::gpu
