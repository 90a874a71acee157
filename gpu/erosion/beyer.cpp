// Host side of Beyer's particle erosion on the GPU (seed 000 §2.7, digest 000 §3.7): buffers, the
// std140 parameter block and Algorithm 7's dispatch loop. The kernel, its decisions (samples at
// integer points, off-map droplets end, the 8-direction random fallback, the speed sign, the brush
// at the old position renormalised over the open samples, the batch fixed-point rule) and its
// mutants are described in gpu/shaders/erosion/beyer_droplets.comp; the CPU reference is
// reference/erosion/beyer.cpp.
//
// Per outer iteration, for oy, ox in [0, S)²: one dispatch of beyer_droplets.comp over the
// ceil(W/S) x ceil(H/S) droplets with pass_offset = (ox, oy) and pass_number = iteration·S² +
// oy·S + ox (uint32, wrapping; the droplets' RNG counter), then a storage barrier. Race and
// disjoint: the droplets work in place on `heights`. Batch (compiled with BEYER_BATCH): the
// droplets read `heights` and atomically add integer quanta into `delta`; beyer_apply.comp then
// adds delta·quantum to each valid cell and clears delta, followed by another barrier. With c_b > 0
// each iteration ends with blur_blend.comp (eq. 2.43): in place, or its quanta through one more
// beyer_apply.comp in batch. Constants
// are rounded to float once here (quantum and 1/quantum are powers of two, so both are exact);
// 1 - inertia and 1 - evaporation are computed in the shader, as the reference computes them in
// Real. Mutants (compare/mutants/beyer.cpp) live in the shader only.
#include "gpu/erosion/beyer.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/erosion/droplet_host.hpp"

namespace gt::gpu {
namespace {

// Mirror of `BeyerBlock` in gpu/shaders/erosion/beyer_block.glsl (std140).
struct BeyerBlock {
  DropletBlockHead head;
  std::uint32_t seed;
  std::uint32_t printed_speed;
  float inertia;
  float capacity_factor;
  float min_slope;
  float deposition;
  float erosion;
  float gravity;
  float evaporation;
  float radius;
  float initial_speed;
  float initial_water;
  float quantum;
  float inverse_quantum;
};

enum Binding : GLuint { block_binding = 0, heights_binding = 1, valid_binding = 2, delta_binding = 3 };

bool is_batch(const BeyerConstants& constants) { return constants.ordering == DropletOrdering::batch; }

std::vector<std::string> ordering_defines(const BeyerConstants& constants) {
  if (is_batch(constants)) return {"BEYER_BATCH"};
  return {};
}

// A program of beyer_block.glsl, its BeyerBlock checked against the mirror.
ComputeProgram beyer_program(const char* shader, const BeyerConstants& constants) {
  ComputeProgram program = ComputeProgram::load(shader, ordering_defines(constants));
  program.check_block(
      "BeyerBlock", sizeof(BeyerBlock),
      droplet_block_layout(offsetof(BeyerBlock, head), {{"seed", offsetof(BeyerBlock, seed)},
                                                        {"printed_speed", offsetof(BeyerBlock, printed_speed)},
                                                        {"inertia", offsetof(BeyerBlock, inertia)},
                                                        {"capacity_factor", offsetof(BeyerBlock, capacity_factor)},
                                                        {"min_slope", offsetof(BeyerBlock, min_slope)},
                                                        {"deposition", offsetof(BeyerBlock, deposition)},
                                                        {"erosion", offsetof(BeyerBlock, erosion)},
                                                        {"gravity", offsetof(BeyerBlock, gravity)},
                                                        {"evaporation", offsetof(BeyerBlock, evaporation)},
                                                        {"radius", offsetof(BeyerBlock, radius)},
                                                        {"initial_speed", offsetof(BeyerBlock, initial_speed)},
                                                        {"initial_water", offsetof(BeyerBlock, initial_water)},
                                                        {"quantum", offsetof(BeyerBlock, quantum)},
                                                        {"inverse_quantum", offsetof(BeyerBlock, inverse_quantum)}}));
  return program;
}

std::optional<ComputeProgram> apply_program(const BeyerConstants& constants) {
  if (!is_batch(constants)) return std::nullopt;
  return beyer_program("erosion/beyer_apply.comp", constants);
}

// Each constant rounded to float once from double, as the reference does.
BeyerBlock make_block(const BeyerConstants& constants, int width, int height) {
  BeyerBlock block{};
  block.head = droplet_block_head(width, height, constants.spacing, constants.lifetime, "BeyerErosion");
  block.seed = constants.seed;
  block.printed_speed = constants.speed_rule == BeyerSpeedRule::printed ? 1u : 0u;
  block.inertia = static_cast<float>(constants.inertia);
  block.capacity_factor = static_cast<float>(constants.capacity_factor);
  block.min_slope = static_cast<float>(constants.min_slope);
  block.deposition = static_cast<float>(constants.deposition);
  block.erosion = static_cast<float>(constants.erosion);
  block.gravity = static_cast<float>(constants.gravity);
  block.evaporation = static_cast<float>(constants.evaporation);
  block.radius = static_cast<float>(constants.radius);
  block.initial_speed = static_cast<float>(constants.initial_speed);
  block.initial_water = static_cast<float>(constants.initial_water);
  if (is_batch(constants)) {
    if (!(constants.quantum > 0.0)) throw std::invalid_argument("BeyerErosion: batch ordering needs a quantum > 0");
    block.quantum = static_cast<float>(constants.quantum);
    block.inverse_quantum = static_cast<float>(1.0 / constants.quantum);
  }
  return block;
}

std::optional<BlurBlend> blur_blend(int width, int height, const BeyerConstants& constants) {
  if (constants.blur_blend == 0.0) return std::nullopt;
  return BlurBlend(width, height, constants.blur_blend, is_batch(constants) ? 1.0 / constants.quantum : 0.0);
}

// One int per cell for the batch delta; a 16-byte placeholder (never bound) otherwise.
std::size_t delta_bytes(const BeyerConstants& constants, int width, int height) {
  return is_batch(constants) ? cell_count(width, height) * sizeof(std::int32_t) : 16;
}

}  // namespace

BeyerErosion::BeyerErosion(int width, int height, const BeyerConstants& constants)
    : iterations_(constants.iterations),
      spacing_(checked_droplet_spacing(constants.spacing, "BeyerErosion")),
      droplets_x_(droplet_count(width, spacing_)),
      droplets_y_(droplet_count(height, spacing_)),
      layout_(empty_layout(width, height)),
      droplets_program_(beyer_program("erosion/beyer_droplets.comp", constants)),
      apply_program_(apply_program(constants)),
      offset_location_(droplets_program_.required_uniform("pass_offset")),
      pass_number_location_(droplets_program_.required_uniform("pass_number")),
      block_(UniformBuffer::from(make_block(constants, width, height))),
      heights_(cell_count(width, height) * sizeof(float)),
      valid_(cell_count(width, height) * sizeof(GLuint)),
      delta_(delta_bytes(constants, width, height)),
      blur_blend_(blur_blend(width, height, constants)) {}

void BeyerErosion::load(const Grid<float>& heights, int iterations_done) {
  layout_ = load_heightfield(heights, layout_.width, layout_.height, heights_, valid_, "BeyerErosion");
  if (batch()) {
    const std::vector<std::int32_t> zeros(heights.size(), 0);
    delta_.upload(zeros.data(), zeros.size() * sizeof(std::int32_t));
  }
  iterations_done_ = static_cast<std::uint32_t>(iterations_done);
}

void BeyerErosion::run() { step(iterations_); }

void BeyerErosion::step(int count) {
  bind();
  const auto passes = static_cast<std::uint32_t>(spacing_) * static_cast<std::uint32_t>(spacing_);
  for (int iteration = 0; iteration < count; ++iteration, ++iterations_done_) {
    for (int offset_y = 0; offset_y < spacing_; ++offset_y) {
      for (int offset_x = 0; offset_x < spacing_; ++offset_x) {
        const std::uint32_t pass = static_cast<std::uint32_t>(offset_y * spacing_ + offset_x);
        run_pass(offset_x, offset_y, iterations_done_ * passes + pass);
      }
    }
    blend_with_blur();
  }
}

Grid<float> BeyerErosion::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  Grid<float> heights = layout_;
  heights.values = heights_.download<float>(cell_count(layout_.width, layout_.height));
  return heights;
}

void BeyerErosion::bind() const {
  block_.bind(block_binding);
  heights_.bind(heights_binding);
  valid_.bind(valid_binding);
  if (batch()) delta_.bind(delta_binding);
}

void BeyerErosion::run_pass(int offset_x, int offset_y, std::uint32_t pass_number) const {
  glProgramUniform1ui(droplets_program_.id(), pass_number_location_, pass_number);
  dispatch_droplet_pass(droplets_program_, offset_location_, offset_x, offset_y, droplets_x_, droplets_y_);
  if (apply_program_) dispatch_cell_pass(*apply_program_, layout_.width, layout_.height);
}

void BeyerErosion::blend_with_blur() {
  if (!blur_blend_) return;
  blur_blend_->run(heights_, valid_, batch() ? &delta_ : nullptr);
  if (apply_program_) dispatch_cell_pass(*apply_program_, layout_.width, layout_.height);
}

}  // namespace gt::gpu
