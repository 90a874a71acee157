// OSMesa backend of GlContext: Mesa's off-screen library (llvmpipe), no window system at all.
//
// The context renders into a small client-side RGBA buffer that only exists because
// OSMesaMakeCurrent needs one; compute work never touches it. OSMesa has no error query, so a
// failure names the call that returned null/false. This file must not include glad (osmesa.h
// brings the system GL/gl.h); it needs no GL function beyond OSMesa's own.
#include <cstddef>
#include <memory>
#include <vector>

#include <GL/osmesa.h>

#include "core/errors.hpp"
#include "gpu/context/context.hpp"

namespace gt {
namespace {

constexpr int buffer_side = 16;
constexpr std::size_t buffer_bytes = 4 * buffer_side * buffer_side;  // RGBA8

struct OsMesaContextDeleter {
  void operator()(osmesa_context* context) const {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context);
  }
};
using OsMesaHandle = std::unique_ptr<osmesa_context, OsMesaContextDeleter>;

OsMesaHandle create_core_45_context() {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                            OSMESA_DEPTH_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 4,
                            OSMESA_CONTEXT_MINOR_VERSION, 5,
                            0};
  OsMesaHandle context(OSMesaCreateContextAttribs(attributes, nullptr));
  if (!context) throw GpuUnavailable("osmesa: OSMesaCreateContextAttribs(OpenGL 4.5 core) returned null");
  return context;
}

class OsMesaGlContext final : public GlContext {
 public:
  OsMesaGlContext()
      : GlContext("osmesa"),
        color_buffer_(buffer_bytes),
        context_(create_core_45_context()) {
    if (!OSMesaMakeCurrent(context_.get(), color_buffer_.data(), GL_UNSIGNED_BYTE, buffer_side, buffer_side)) {
      throw GpuUnavailable("osmesa: OSMesaMakeCurrent failed");
    }
    load_and_check_gl(OSMesaGetProcAddress);
  }

 private:
  std::vector<unsigned char> color_buffer_;
  OsMesaHandle context_;
};

}  // namespace

std::unique_ptr<GlContext> detail::create_osmesa_context() {
  return std::make_unique<OsMesaGlContext>();
}

}  // namespace gt
