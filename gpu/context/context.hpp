// Headless OpenGL 4.5 core contexts for the GPU twins: EGL (a hardware device when there is one,
// else Mesa's surfaceless platform, i.e. llvmpipe) or OSMesa (llvmpipe).
//
// Conventions: GlContext::create makes the context current on the calling thread and loads the GL
// function pointers (glad, process-wide) through that context's own get-proc-address. Because the
// pointers are process-wide, at most one GlContext may be alive at a time; create() throws
// std::logic_error when another one is. Every failure to obtain a working context is reported as
// gt::GpuUnavailable naming the step that failed; nothing here aborts the process.
// This header does not include GL: the GL-facing headers (buffer.hpp, shader_program.hpp) do.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace gt {

enum class GlBackend { egl, osmesa };

// "egl" or "osmesa"; anything else throws gt::InputError.
GlBackend parse_gl_backend(const std::string& name);

struct GlInfo {
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;   // GL_VERSION
  std::string vendor;    // GL_VENDOR
  std::string platform;  // "egl-device", "egl-surfaceless" or "osmesa"
  // The attempts made before the one that gave this context, each with why it gave none, e.g.
  // "hardware device 0: ..." when a GPU's EGL device failed and the surfaceless platform worked;
  // empty when the first attempt worked (a platform with nothing to try is not an attempt).
  std::vector<std::string> passed_over;
};

class GlContext {
 public:
  // A current GL 4.5 core context, checked to run a compute shader, with debug output routed to
  // stderr (without notifications, and without shader-compiler messages: ComputeProgram reports
  // those with the original file and line). Throws gt::GpuUnavailable on any failure, and
  // std::logic_error while another GlContext is alive.
  static std::unique_ptr<GlContext> create(GlBackend backend);

  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  virtual ~GlContext();

  const GlInfo& info() const;

  // The GL errors since the last call: error messages of the debug output (KHR_debug, core since
  // 4.3) and the flags glGetError still holds, each as one line. The driver calls it after every
  // case: any error makes that case `error`, whatever its checks say.
  std::vector<std::string> take_errors();

 protected:
  using GlProc = void (*)();
  using GlProcLoader = GlProc (*)(const char* name);

  explicit GlContext(std::string platform, std::vector<std::string> passed_over = {});

  // Loads GL through the context's get-proc-address, fills info(), checks 4.5 core, installs
  // debug output and runs the compute probe; throws gt::GpuUnavailable. The last statement of a
  // backend's constructor, once its context is current.
  void load_and_check_gl(GlProcLoader loader);

 private:
  GlInfo info_;
};

namespace detail {
// Backend factories (egl.cpp, osmesa.cpp): a current context that passed load_and_check_gl.
std::unique_ptr<GlContext> create_egl_context();
std::unique_ptr<GlContext> create_osmesa_context();
}  // namespace detail

}  // namespace gt
