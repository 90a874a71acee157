// Compute and graphics (vertex + fragment) programs loaded from the shader tree, with #include expansion and error messages that
// point at the original files.
//
// Conventions:
// - Shader paths are relative to a root: shader_root() (GT_SHADER_DIR, the source gpu/shaders
//   folder) or an explicit one (load_from). `#include "family/file.glsl"` lines are resolved
//   against that same root, recursively; a cycle or a missing file is an error naming the
//   including file and line.
// - A drop-in folder (set_shader_overlay; `groundtruth run --gpu-shaders DIR`) lies over every
//   root: a path found under it is read from there, anything else from the root, #include lines
//   alike. A user's variant of one pass is one file in it (docs/gpu-shader-drop-ins.md).
//   Included files are pasted verbatim, so a file included twice needs #ifndef guards.
// - Defines ("NAME", "NAME=VALUE" or "NAME(a)=VALUE") become `#define` lines right after #version.
// - Both kinds go through the same expansion, compilation and linking; a graphics program's
//   defines apply to both of its stages.
// - Compile and link failures throw std::runtime_error with the driver's log rewritten so that
//   Mesa's "0:LINE(COL): " and NVIDIA's "0(LINE) : " prefixes read
//   "tests/data/shaders/lib/broken.glsl:LINE:COL: " (paths relative to the project when inside it).
// - Compiler warnings of a program that builds are printed to stderr, rewritten the same way.
// - A current GlContext is needed for everything except expand_shader, shader_root and
//   nested_layout.
//
// C++ mirrors of GLSL blocks: a host file that fills a uniform or storage block from a C++ struct
// states the struct's layout once, after loading each program that declares the block, with
// GlProgram::check_block(block, sizeof(Struct), {{"member", offsetof(Struct, member)}, ...}). The
// program's own layout is read by program interface queries (GL 4.3+): the block's
// GL_BUFFER_DATA_SIZE and each member's GL_OFFSET (and GL_BLOCK_INDEX, so that a member of another
// block does not count). Member names are those of the program interface (GL 4.5 §7.3.1.1): in a
// block with an instance name (`uniform Block { ... } instance;`) "Block.member" (the block's name,
// not the instance's), in one without just the member's name, as in:
//   "talus_limit"               a plain member;
//   "flux_gain" / "flux_gain[0]" an array (its first element; both spellings resolve);
//   "fractal_terms.remainder"   a member of a struct member;
//   "bedrock_types[0].soil_rate" a member of a storage block's array of structs (for a block whose
//                               only member is an unsized array, GL_BUFFER_DATA_SIZE is that of one
//                               element, so `size` is the record's sizeof).
// A member the GLSL text declares but the linker did not keep (inactive: optimised away, or inside
// an #ifdef the program's defines leave out) is skipped, not reported; std140 and std430 keep every
// member of a declared block active, and the block itself even where the program never reads it
// (the spec's rule for uniform blocks, Mesa's practice for storage blocks too), so in practice
// skipping happens only with `packed` blocks. Whether
// an inactive name is declared at all is judged from the program's expanded source text: the first
// part of the name must appear in the block's braces and any later part (a struct field) somewhere
// in the source. Everything else is a mismatch: the block not active in the program at all, its
// size differing from `size`, a member at another offset, a name declared nowhere, a name that is a
// member of another block. check_block throws one std::runtime_error listing every mismatch, each
// naming the shader file(s), the block, the member, the C++ offset and (when the member exists) the
// GLSL offset, e.g. "gpu/shaders/erosion/thermal_requests.comp: the C++ mirror of uniform block
// ThermalBlock does not match the GLSL layout: member clamp_unit: C++ offset 56, GLSL offset 60".
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glad/gl.h>

namespace gt {

std::filesystem::path shader_root();

// The drop-in folder over the shader roots (empty: none) for the rest of the process.
void set_shader_overlay(const std::filesystem::path& folder);
std::filesystem::path shader_overlay();

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
  std::vector<std::string> drop_ins;  // display paths of the files read from the drop-in folder

  // The info log with line prefixes of the expanded source replaced by "file:line[:col]: ".
  std::string locate_info_log(const std::string& info_log) const;
};

// Throws std::runtime_error (unreadable file, include cycle, no #version line) or
// std::invalid_argument (a define that does not start with an identifier).
ExpandedShader expand_shader(const std::filesystem::path& root, const std::string& relative_path,
                             const std::vector<std::string>& defines = {});

// One member of a C++ mirror of a GLSL block: its program-interface name (see the top of this file)
// and its offset in the C++ struct (offsetof).
struct BlockMember {
  std::string name;
  std::size_t offset;
};
using BlockLayout = std::vector<BlockMember>;

// `members` (the layout of a C++ struct) as they sit in an enclosing mirror: each name preceded by
// `prefix` and each offset increased by `offset`. For a GLSL struct member "fractal_terms" the
// prefix is "fractal_terms."; for a C++ struct whose fields the GLSL block declares one by one (a
// shared head), it is "".
BlockLayout nested_layout(const std::string& prefix, std::size_t offset, const BlockLayout& members);

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
  // The same for a uniform the host must set: std::runtime_error naming the program when it is not
  // active (a shader that lost it, or the compiler optimised it away).
  GLint required_uniform(const char* name) const;
  // The shader files of the program as messages name them (with their defines), " + " between stages.
  const std::string& description() const { return description_; }

  // Checks the C++ mirror of the uniform or shader storage block `block_name` — its sizeof `size`
  // and its members — against the linked program (see the top of this file); std::runtime_error
  // naming every mismatch.
  void check_block(const char* block_name, std::size_t size, const BlockLayout& members) const;

 protected:
  GlProgram(GLuint id, std::string description, std::string source)
      : id_(id), description_(std::move(description)), source_(std::move(source)) {}

 private:
  GLuint id_ = 0;
  std::string description_;
  std::string source_;  // the expanded sources of the stages, for check_block's inactive members
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
  ComputeProgram(GLuint id, std::string description, std::string source);

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
  GraphicsProgram(GLuint id, std::string description, std::string source)
      : GlProgram(id, std::move(description), std::move(source)) {}
};

}  // namespace gt
