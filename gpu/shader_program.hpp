// Compute and graphics (vertex + fragment) programs loaded from the shader tree, with #include expansion and error messages that
// point at the original files.
//
// Conventions:
// - Shader paths are relative to a root: shader_root() (GT_SHADER_DIR, the source gpu/shaders
//   folder, unless the environment variable GROUNDTRUTH_SHADER_DIR names another) or an explicit
//   one (load_from). `#include "family/file.glsl"` lines are resolved against that same root,
//   recursively; a cycle or a missing file is an error naming the including file and line.
//   Included files are pasted verbatim, so a file included twice needs #ifndef guards.
// - Defines ("NAME", "NAME=VALUE" or "NAME(a)=VALUE") become `#define` lines right after #version.
// - Both kinds go through the same expansion, compilation and linking; a graphics program's
//   defines apply to both of its stages.
// - Compile and link failures throw std::runtime_error with the driver's log rewritten so that
//   Mesa's "0:LINE(COL): " and NVIDIA's "0(LINE) : " prefixes read
//   "tests/data/shaders/lib/broken.glsl:LINE:COL: " (paths relative to the project when inside it).
// - Compiler warnings of a program that builds are printed to stderr, rewritten the same way.
// - A current GlContext is needed for everything except expand_shader and shader_root.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <glad/gl.h>

namespace gt {

std::filesystem::path shader_root();

// Every shader stage this process compiled so far: its description (display path, and defines when
// it has any) -> the SHA-256 of the source the driver was given, after #include expansion and
// define insertion (a report's provenance: which shader code really ran).
std::map<std::string, std::string> compiled_shader_digests();

// A shader after #include expansion and define insertion.
struct ExpandedShader {
  struct Origin {
    std::string file;  // display path of the file, or "<defines>"
    int line;          // 1-based line in that file
  };
  std::string source;
  std::vector<Origin> origins;  // origins[n - 1]: where line n of `source` comes from

  // The info log with line prefixes of the expanded source replaced by "file:line[:col]: ".
  std::string locate_info_log(const std::string& info_log) const;
};

// Throws std::runtime_error (unreadable file, include cycle, no #version line) or
// std::invalid_argument (a define that does not start with an identifier).
ExpandedShader expand_shader(const std::filesystem::path& root, const std::string& relative_path,
                             const std::vector<std::string>& defines = {});

// What both kinds of program share: the linked program, deleted with its owner (move-only).
class GlProgram {
 public:
  GlProgram(GlProgram&& other) noexcept;
  GlProgram& operator=(GlProgram&& other) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  ~GlProgram();

  GLuint id() const { return id_; }
  void use() const;
  // glGetUniformLocation: -1 for a name that is not an active uniform.
  GLint uniform(const char* name) const;

 protected:
  explicit GlProgram(GLuint id) : id_(id) {}

 private:
  GLuint id_ = 0;
};

class ComputeProgram : public GlProgram {
 public:
  static ComputeProgram load(const std::string& relative_path, const std::vector<std::string>& defines = {});
  static ComputeProgram load_from(const std::filesystem::path& root, const std::string& relative_path,
                                  const std::vector<std::string>& defines = {});

  // Uses the program and dispatches ceil(width / local_x) x ceil(height / local_y) x 1 groups.
  // local_x, local_y must equal the shader's declared local size (checked: std::invalid_argument).
  void dispatch(int width, int height, int local_x, int local_y) const;

 private:
  explicit ComputeProgram(GLuint id);

  std::array<GLint, 3> local_size_{};
};

// A vertex and a fragment shader linked into one program.
class GraphicsProgram : public GlProgram {
 public:
  static GraphicsProgram load(const std::string& vertex_path, const std::string& fragment_path,
                              const std::vector<std::string>& defines = {});
  static GraphicsProgram load_from(const std::filesystem::path& root, const std::string& vertex_path,
                                   const std::string& fragment_path, const std::vector<std::string>& defines = {});

 private:
  explicit GraphicsProgram(GLuint id) : GlProgram(id) {}
};

}  // namespace gt
