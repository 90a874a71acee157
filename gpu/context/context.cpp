// Backend-independent part of GlContext: backend choice, loading GL through the context's own
// get-proc-address, the version/profile check, debug output to stderr and the compute probe.
//
// The probe runs one tiny compute shader that writes a known word into a storage buffer and reads
// it back: a context that reports 4.5 but cannot run compute is reported as unavailable here
// rather than as a wrong result later.
#include "gpu/context/context.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <glad/gl.h>

#include "core/errors.hpp"

namespace gt {
namespace {

// The one live context (GL function pointers are process-wide), or nullptr.
std::atomic<const GlContext*> live_context{nullptr};

constexpr std::uint32_t probe_word = 0x600df00du;
constexpr const char* probe_source = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Word { uint word; };
void main() { word = 0x600df00du; }
)";

std::string_view gl_string(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text ? std::string_view(text) : std::string_view("(null)");
}

std::string_view debug_type_name(GLenum type) {
  switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
  }
}

std::string_view debug_severity_name(GLenum severity) {
  switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH: return "high";
    case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
    default: return "low";
  }
}

// Error messages of the debug output since the last GlContext::take_errors (one context at a time).
std::vector<std::string>& recorded_errors() {
  static std::vector<std::string> errors;
  return errors;
}

// The GL debug-output log: one line on stderr per message; errors are also kept for take_errors.
void GLAD_API_PTR log_gl_debug_message(GLenum /*source*/, GLenum type, GLuint id, GLenum severity,
                                       GLsizei length, const GLchar* message, const void* /*user*/) {
  const std::string_view text(message, static_cast<std::size_t>(length));
  fmt::print(stderr, "[gl] {} ({} severity, id {}): {}\n", debug_type_name(type), debug_severity_name(severity), id,
             text);
  if (type == GL_DEBUG_TYPE_ERROR) recorded_errors().emplace_back(text);
}

std::string_view gl_error_name(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    default: return "unknown GL error";
  }
}

// Notifications are dropped; so are shader-compiler messages, which ComputeProgram reports from
// the info log with the lines mapped back to the original files.
void install_debug_output() {
  glEnable(GL_DEBUG_OUTPUT);
  glDebugMessageCallback(log_gl_debug_message, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
  glDebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
}

void require_core_45(int glad_version) {
  const int major = GLAD_VERSION_MAJOR(glad_version);
  const int minor = GLAD_VERSION_MINOR(glad_version);
  if (major < 4 || (major == 4 && minor < 5)) {
    throw GpuUnavailable(fmt::format("OpenGL {}.{} context, 4.5 needed (GL_VERSION \"{}\")", major, minor,
                                     gl_string(GL_VERSION)));
  }
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  if ((profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
    throw GpuUnavailable(fmt::format("OpenGL context is not a core profile (GL_VERSION \"{}\")",
                                     gl_string(GL_VERSION)));
  }
}

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log;
}

// Compiles and links probe_source; 0 when that fails.
GLuint link_probe_program() {
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &probe_source, nullptr);
  glCompileShader(shader);
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (!compiled) {
    const std::string log = shader_log(shader);
    glDeleteShader(shader);
    throw GpuUnavailable("compute probe: the compute shader does not compile: " + log);
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (!linked) {
    glDeleteProgram(program);
    throw GpuUnavailable("compute probe: the compute program does not link");
  }
  return program;
}

void require_working_compute() {
  const GLuint program = link_probe_program();
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  const std::uint32_t zero = 0;
  glNamedBufferStorage(buffer, sizeof zero, &zero, GL_DYNAMIC_STORAGE_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  glUseProgram(program);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t word = 0;
  glGetNamedBufferSubData(buffer, 0, sizeof word, &word);
  glUseProgram(0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glDeleteBuffers(1, &buffer);
  glDeleteProgram(program);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR || word != probe_word) {
    throw GpuUnavailable(fmt::format("compute probe: dispatch wrote {:#010x} (expected {:#010x}), GL error {:#06x}",
                                     word, probe_word, error));
  }
}

}  // namespace

GlBackend parse_gl_backend(const std::string& name) {
  if (name == "egl") return GlBackend::egl;
  if (name == "osmesa") return GlBackend::osmesa;
  throw InputError(fmt::format("unknown GL backend \"{}\" (expected \"egl\" or \"osmesa\")", name));
}

std::unique_ptr<GlContext> GlContext::create(GlBackend backend) {
  if (live_context.load() != nullptr) {
    throw std::logic_error("GlContext::create: another GlContext is alive (GL pointers are process-wide)");
  }
  return backend == GlBackend::egl ? detail::create_egl_context() : detail::create_osmesa_context();
}

GlContext::GlContext(std::string platform, std::vector<std::string> passed_over) {
  info_.platform = std::move(platform);
  info_.passed_over = std::move(passed_over);
  live_context.store(this);
}

GlContext::~GlContext() { live_context.store(nullptr); }

const GlInfo& GlContext::info() const { return info_; }

std::vector<std::string> GlContext::take_errors() {
  std::vector<std::string> errors = std::move(recorded_errors());
  recorded_errors().clear();
  // glGetError keeps one flag per kind; a bounded loop, since a lost context may keep answering.
  for (int flag = 0; flag < 16; ++flag) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) break;
    errors.push_back(fmt::format("glGetError: {} (0x{:04x})", gl_error_name(error), error));
  }
  return errors;
}

void GlContext::load_and_check_gl(GlProcLoader loader) {
  const int version = gladLoadGL(loader);
  if (version == 0) {
    throw GpuUnavailable(fmt::format("{}: glad could not load OpenGL through the context's get-proc-address",
                                     info_.platform));
  }
  info_.renderer = gl_string(GL_RENDERER);
  info_.version = gl_string(GL_VERSION);
  info_.vendor = gl_string(GL_VENDOR);
  try {
    require_core_45(version);
    install_debug_output();
    require_working_compute();
  } catch (const GpuUnavailable& failure) {
    throw GpuUnavailable(fmt::format("{} ({}): {}", info_.platform, info_.renderer, failure.what()));
  }
}

}  // namespace gt
