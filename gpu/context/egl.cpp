// EGL backend of GlContext: headless, no window system, works with DISPLAY unset.
//
// Order of attempts: every hardware device from EGL_EXT_device_enumeration (a device whose
// extension string lacks EGL_MESA_device_software; on an NVIDIA machine, the GPU) through
// EGL_EXT_platform_device, then Mesa's surfaceless platform (llvmpipe). Each attempt must give a
// current OpenGL 4.5 core context without a surface (EGL_KHR_surfaceless_context) that passes
// GlContext's checks; the first one that does wins and names the platform ("egl-device" or
// "egl-surfaceless"). When none does, GpuUnavailable lists why each attempt failed.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "gpu/context/context.hpp"

namespace gt {
namespace {

std::string_view egl_error_name(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
    default: return "unknown EGL error";
  }
}

[[noreturn]] void fail_egl_call(std::string_view call) {
  throw GpuUnavailable(fmt::format("{} failed with {}", call, egl_error_name(eglGetError())));
}

// Whether a space-separated extension string names `extension`.
bool has_extension(const char* extensions, std::string_view extension) {
  std::string_view rest = extensions ? extensions : "";
  while (!rest.empty()) {
    const auto end = rest.find(' ');
    if (rest.substr(0, end) == extension) return true;
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return false;
}

bool has_client_extension(std::string_view extension) {
  return has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), extension);
}

// An initialised display and, once made, its current context; released in reverse order.
class EglSession {
 public:
  explicit EglSession(EGLDisplay display) : display_(display) {
    if (display_ == EGL_NO_DISPLAY) fail_egl_call("eglGetPlatformDisplay");
    if (!eglInitialize(display_, nullptr, nullptr)) fail_egl_call("eglInitialize");
    initialised_ = true;
  }
  EglSession(const EglSession&) = delete;
  EglSession& operator=(const EglSession&) = delete;
  ~EglSession() {
    if (context_ != EGL_NO_CONTEXT) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
    }
    if (initialised_) eglTerminate(display_);
  }

  void make_current_core_45_context() {
    if (!has_extension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
      throw GpuUnavailable("display lacks EGL_KHR_surfaceless_context");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) fail_egl_call("eglBindAPI(EGL_OPENGL_API)");
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                         EGL_CONTEXT_MINOR_VERSION, 5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    context_ = eglCreateContext(display_, choose_config(), EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) fail_egl_call("eglCreateContext(OpenGL 4.5 core)");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail_egl_call("eglMakeCurrent");
  }

 private:
  EGLConfig choose_config() const {
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                        EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display_, config_attributes, &config, 1, &count)) fail_egl_call("eglChooseConfig");
    if (count == 0) throw GpuUnavailable("eglChooseConfig found no OpenGL-renderable config");
    return config;
  }

  EGLDisplay display_;
  bool initialised_ = false;
  EGLContext context_ = EGL_NO_CONTEXT;
};

class EglGlContext final : public GlContext {
 public:
  EglGlContext(std::string platform, std::vector<std::string> passed_over, std::unique_ptr<EglSession> session)
      : GlContext(std::move(platform), std::move(passed_over)), session_(std::move(session)) {
    load_and_check_gl(eglGetProcAddress);
  }

 private:
  std::unique_ptr<EglSession> session_;
};

std::unique_ptr<GlContext> create_on_display(EGLenum platform, void* native_display, std::string platform_name,
                                             const std::vector<std::string>& passed_over) {
  auto session = std::make_unique<EglSession>(eglGetPlatformDisplay(platform, native_display, nullptr));
  session->make_current_core_45_context();
  return std::make_unique<EglGlContext>(std::move(platform_name), passed_over, std::move(session));
}

// The devices that are not Mesa's software rasteriser; empty when enumeration is unsupported.
std::vector<EGLDeviceEXT> hardware_devices() {
  if (!has_client_extension("EGL_EXT_device_enumeration") || !has_client_extension("EGL_EXT_platform_device")) {
    return {};
  }
  const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  const auto query_device_string =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  EGLint count = 0;
  if (!query_devices || !query_device_string || !query_devices(0, nullptr, &count)) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  query_devices(count, devices.data(), &count);
  devices.resize(static_cast<std::size_t>(count));
  std::erase_if(devices, [&](EGLDeviceEXT device) {
    return has_extension(query_device_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
  });
  return devices;
}

}  // namespace

std::unique_ptr<GlContext> detail::create_egl_context() {
  std::vector<std::string> failures;  // the attempts made that gave no context, each with why
  const auto devices = hardware_devices();
  for (std::size_t index = 0; index < devices.size(); ++index) {
    try {
      return create_on_display(EGL_PLATFORM_DEVICE_EXT, devices[index], "egl-device", failures);
    } catch (const GpuUnavailable& failure) {
      failures.push_back(fmt::format("hardware device {}: {}", index, failure.what()));
    }
  }
  const bool surfaceless = has_client_extension("EGL_MESA_platform_surfaceless");
  if (surfaceless) {
    try {
      return create_on_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "egl-surfaceless", failures);
    } catch (const GpuUnavailable& failure) {
      failures.push_back(fmt::format("surfaceless: {}", failure.what()));
    }
  }
  // Why nothing worked: the failed attempts, and the platforms that could not be tried.
  if (devices.empty()) failures.insert(failures.begin(), "no hardware EGL device");
  if (!surfaceless) failures.emplace_back("surfaceless: EGL_MESA_platform_surfaceless is not supported");
  throw GpuUnavailable(fmt::format("no EGL OpenGL 4.5 core context: {}", fmt::join(failures, "; ")));
}

}  // namespace gt
