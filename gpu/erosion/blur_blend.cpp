// Host side of Beyer's blend with a blurred map (seed 000 eq. 2.43): the shader's uniforms (each
// weight rounded to float once from double, as the reference rounds it), one dispatch over the grid
// and, in place, the copy of the blended heights back over the caller's.
#include "gpu/erosion/blur_blend.hpp"

#include <array>

#include "gpu/erosion/droplet_host.hpp"

namespace gt::gpu {
namespace {

enum Binding : GLuint { heights_binding = 1, valid_binding = 2, delta_binding = 3, blended_binding = 4 };

constexpr const char* shader = "erosion/blur_blend.comp";

ComputeProgram blend_program(bool batch) {
  if (batch) return ComputeProgram::load(shader, {"BLUR_BLEND_BATCH"});
  return ComputeProgram::load(shader);
}

void set_uniforms(const ComputeProgram& program, int width, int height, double blend, double inverse_quantum,
                  bool batch) {
  glProgramUniform2i(program.id(), program.required_uniform("grid_size"), width, height);
  glProgramUniform1f(program.id(), program.required_uniform("weight"), static_cast<float>(blend / 9.0));
  if (batch) {
    glProgramUniform1f(program.id(), program.required_uniform("inverse_quantum"),
                       static_cast<float>(inverse_quantum));
  }
  // Read only under the mutant blur_renormalised_at_border (location -1 otherwise: ignored).
  std::array<float, 9> renormalised{};
  for (int open = 0; open <= 8; ++open) renormalised[open] = static_cast<float>(blend / (1.0 + open));
  glProgramUniform1fv(program.id(), glGetUniformLocation(program.id(), "renormalised_weights"), 9,
                      renormalised.data());
}

}  // namespace

BlurBlend::BlurBlend(int width, int height, double blend, double inverse_quantum)
    : width_(width), height_(height), program_(blend_program(inverse_quantum > 0.0)) {
  if (inverse_quantum <= 0.0) blended_.emplace(cell_count(width, height) * sizeof(float));
  set_uniforms(program_, width, height, blend, inverse_quantum, batch());
}

void BlurBlend::run(StorageBuffer& heights, const StorageBuffer& valid, StorageBuffer* delta) const {
  heights.bind(heights_binding);
  valid.bind(valid_binding);
  if (batch()) {
    delta->bind(delta_binding);
  } else {
    blended_->bind(blended_binding);
  }
  dispatch_cell_pass(program_, width_, height_);
  if (batch()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the copy reads what the shader wrote
  glCopyNamedBufferSubData(blended_->id(), heights.id(), 0, 0, cell_count(width_, height_) * sizeof(float));
}

}  // namespace gt::gpu
