// ComputeProgram, GraphicsProgram and the #include expander behind them; conventions are in shader_program.hpp.
#include "gpu/shader_program.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/mutant.hpp"
#include "core/sha256.hpp"

namespace gt {
namespace {

// The path shown in messages: relative to the project when inside it, else absolute.
std::string display_path(const std::filesystem::path& path) {
  const auto absolute = std::filesystem::absolute(path).lexically_normal();
  const auto relative = absolute.lexically_relative(GT_PROJECT_DIR);
  const bool inside_project = !relative.empty() && *relative.begin() != "..";
  return (inside_project ? relative : absolute).generic_string();
}

std::vector<std::string> read_lines(std::ifstream& file) {
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

// "NAME", "NAME=VALUE" or "NAME(a, b)=VALUE" as "#define NAME VALUE" (function-like macros too).
std::string define_line(const std::string& define) {
  static const std::regex define_pattern(R"(([A-Za-z_][A-Za-z0-9_]*(?:\([A-Za-z0-9_, ]*\))?)(=(.*))?)");
  std::smatch match;
  if (!std::regex_match(define, match, define_pattern)) {
    throw std::invalid_argument(fmt::format("shader define \"{}\" is not NAME, NAME=VALUE or NAME(args)=VALUE", define));
  }
  return fmt::format("#define {} {}", match[1].str(), match[3].str());
}

// Pastes a file and, recursively, the files it includes into an ExpandedShader, inserting the
// defines after the top file's #version line.
class IncludeExpander {
 public:
  IncludeExpander(std::filesystem::path root, const std::vector<std::string>& defines)
      : root_(std::move(root)), overlay_(shader_overlay()) {
    std::transform(defines.begin(), defines.end(), std::back_inserter(define_lines_), define_line);
  }

  ExpandedShader expand(const std::string& relative_path) {
    expand_file(relative_path, nullptr);
    if (!version_seen_) throw std::runtime_error(fmt::format("{}: no #version line", display_path(root_ / relative_path)));
    return std::move(result_);
  }

 private:
  // The file of `relative_path`: the drop-in folder's, where it has one, else the root's.
  std::filesystem::path locate(const std::string& relative_path) const {
    std::error_code error;
    if (!overlay_.empty() && std::filesystem::is_regular_file(overlay_ / relative_path, error)) return overlay_ / relative_path;
    return root_ / relative_path;
  }

  void expand_file(const std::string& relative_path, const ExpandedShader::Origin* included_from) {
    const auto path = locate(relative_path);
    const std::string name = display_path(path);
    if (path != root_ / relative_path && std::find(result_.drop_ins.begin(), result_.drop_ins.end(), name) == result_.drop_ins.end()) {
      result_.drop_ins.push_back(name);
    }
    std::ifstream file(path);
    if (!file) throw std::runtime_error(cannot_open_message(relative_path, name, included_from));
    if (std::find(active_.begin(), active_.end(), name) != active_.end()) {
      throw std::runtime_error(fmt::format("{}:{}: #include \"{}\" forms a cycle: {} -> {}", included_from->file,
                                           included_from->line, relative_path, fmt::join(active_, " -> "), name));
    }
    active_.push_back(name);
    const auto lines = read_lines(file);
    for (std::size_t index = 0; index < lines.size(); ++index) {
      expand_line(lines[index], {name, static_cast<int>(index + 1)});
    }
    active_.pop_back();
  }

  void expand_line(const std::string& line, const ExpandedShader::Origin& origin) {
    static const std::regex directive_pattern(R"(\s*#\s*include\b.*)");
    static const std::regex include_pattern(R"re(\s*#\s*include\s+"([^"]+)"\s*(//.*)?)re");
    static const std::regex version_pattern(R"(\s*#\s*version\b.*)");
    std::smatch match;
    if (std::regex_match(line, match, include_pattern)) {
      expand_file(match[1].str(), &origin);
    } else if (std::regex_match(line, directive_pattern)) {
      throw std::runtime_error(
          fmt::format("{}:{}: malformed #include (expected #include \"path/from/shader/root\")", origin.file, origin.line));
    } else {
      append(line, origin);
      if (active_.size() == 1 && !version_seen_ && std::regex_match(line, version_pattern)) append_defines();
    }
  }

  void append_defines() {
    version_seen_ = true;
    for (std::size_t index = 0; index < define_lines_.size(); ++index) {
      append(define_lines_[index], {"<defines>", static_cast<int>(index + 1)});
    }
  }

  void append(const std::string& line, ExpandedShader::Origin origin) {
    result_.source += line;
    result_.source += '\n';
    result_.origins.push_back(std::move(origin));
  }

  std::string cannot_open_message(const std::string& relative_path, const std::string& name,
                                  const ExpandedShader::Origin* included_from) const {
    if (included_from == nullptr) return fmt::format("cannot open shader {}", name);
    return fmt::format("{}:{}: cannot open included file \"{}\" (looked for {})", included_from->file,
                       included_from->line, relative_path, name);
  }

  std::filesystem::path root_;
  std::filesystem::path overlay_;
  std::vector<std::string> define_lines_;
  ExpandedShader result_;
  std::vector<std::string> active_;  // the chain of files being expanded, outermost first
  bool version_seen_ = false;
};

// The info log of a shader (glGetShaderiv, glGetShaderInfoLog) or program (glGetProgram...).
std::string info_log(GLuint object, PFNGLGETSHADERIVPROC get_parameter, PFNGLGETSHADERINFOLOGPROC get_log) {
  GLint length = 0;
  get_parameter(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length), '\0');
  get_log(object, length, nullptr, log.data());
  if (!log.empty() && log.back() == '\0') log.pop_back();
  return log;
}

std::string describe(const std::string& name, const std::vector<std::string>& defines) {
  if (defines.empty()) return name;
  return fmt::format("{} (defines {})", name, fmt::join(defines, ", "));
}

std::mutex digests_mutex;
std::map<std::string, std::string> digests;  // guarded by digests_mutex

void record_digest(const std::string& description, const std::string& source) {
  const std::string digest = sha256_hex(source);
  const std::lock_guard lock(digests_mutex);
  digests[description] = digest;
}

GLuint compile_shader(GLenum stage, const ExpandedShader& shader, const std::string& description) {
  record_digest(description, shader.source);
  const GLuint id = glCreateShader(stage);
  const char* source = shader.source.c_str();
  glShaderSource(id, 1, &source, nullptr);
  glCompileShader(id);
  GLint compiled = GL_FALSE;
  glGetShaderiv(id, GL_COMPILE_STATUS, &compiled);
  const std::string log = shader.locate_info_log(info_log(id, glGetShaderiv, glGetShaderInfoLog));
  if (!compiled) {
    glDeleteShader(id);
    throw std::runtime_error(fmt::format("compiling {} failed:\n{}", description, log));
  }
  if (!log.empty()) fmt::print(stderr, "[gl] compiling {}:\n{}\n", description, log);
  return id;
}

// A stage of a program: its file expanded and its description for messages.
struct StageSource {
  GLenum stage;
  ExpandedShader expanded;
  std::string description;
};

// The program's defines plus the active mutant's (core/mutant.hpp), so that a shader's
// `#ifdef GT_MUTANT_...` switches on while that mutant runs.
std::vector<std::string> with_mutant(const std::vector<std::string>& defines) {
  if (active_mutant().empty()) return defines;
  std::vector<std::string> all = defines;
  all.push_back(mutant_define(active_mutant()));
  return all;
}

StageSource load_stage(GLenum stage, const std::filesystem::path& root, const std::string& relative_path,
                       const std::vector<std::string>& defines) {
  const auto all_defines = with_mutant(defines);
  ExpandedShader expanded = expand_shader(root, relative_path, all_defines);
  // Messages and the report's provenance name the drop-ins a stage was built from.
  std::string name = display_path(root / relative_path);
  if (!expanded.drop_ins.empty()) name += fmt::format(" with drop-ins {}", fmt::join(expanded.drop_ins, ", "));
  return {stage, std::move(expanded), describe(name, all_defines)};
}

// A linked program, its description for messages and its stages' expanded sources.
struct LinkedProgram {
  GLuint id;
  std::string description;
  std::string source;
};

// Compiles the stages and links them into a program; the shaders are deleted whether linking
// succeeds or not. A link log is located in the stage's files when there is one stage; with
// several it names them and is shown as the driver wrote it.
LinkedProgram build_program(const std::vector<StageSource>& stages) {
  std::vector<GLuint> shaders;
  const auto delete_shaders = [&shaders] {
    for (GLuint shader : shaders) glDeleteShader(shader);
  };
  try {
    for (const auto& stage : stages) shaders.push_back(compile_shader(stage.stage, stage.expanded, stage.description));
  } catch (...) {
    delete_shaders();
    throw;
  }
  const GLuint id = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(id, shader);
  glLinkProgram(id);
  for (GLuint shader : shaders) glDetachShader(id, shader);
  delete_shaders();
  std::vector<std::string> names;
  for (const auto& stage : stages) names.push_back(stage.description);
  GLint linked = GL_FALSE;
  glGetProgramiv(id, GL_LINK_STATUS, &linked);
  if (!linked) {
    const std::string raw_log = info_log(id, glGetProgramiv, glGetProgramInfoLog);
    const std::string log = stages.size() == 1 ? stages.front().expanded.locate_info_log(raw_log) : raw_log;
    glDeleteProgram(id);
    throw std::runtime_error(fmt::format("linking {} failed:\n{}", fmt::join(names, " + "), log));
  }
  std::string source;
  for (const auto& stage : stages) source += stage.expanded.source;
  return {id, fmt::format("{}", fmt::join(names, " + ")), std::move(source)};
}

int group_count(int size, int local_size) { return (size + local_size - 1) / local_size; }

// One property of a program resource (glGetProgramResourceiv).
GLint resource_property(GLuint program, GLenum interface, GLuint index, GLenum property) {
  GLint value = -1;
  glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
  return value;
}

bool contains_word(const std::string& text, const std::string& word) {
  if (word.empty()) return false;
  return std::regex_search(text, std::regex("\\b" + word + "\\b"));
}

// The text between the braces of `uniform NAME {` or `buffer NAME {` in `source` (nested braces
// matched), or nullopt when the source declares no such block.
std::optional<std::string> block_body(const std::string& source, const std::string& block_name) {
  std::smatch match;
  if (!std::regex_search(source, match, std::regex("\\b(uniform|buffer)\\s+" + block_name + "\\s*\\{"))) {
    return std::nullopt;
  }
  const auto begin = static_cast<std::size_t>(match.position(0) + match.length(0));
  int depth = 1;
  for (std::size_t at = begin; at < source.size(); ++at) {
    if (source[at] == '{') ++depth;
    if (source[at] == '}' && --depth == 0) return source.substr(begin, at - begin);
  }
  return source.substr(begin);
}

// Whether `member` ("a", "a[0]", "a.b", "a[0].b") is declared in the source text: its first part
// inside the block's braces, each later part (a struct field) anywhere in the source.
bool declared_in_source(const std::string& source, const std::string& body, const std::string& member) {
  static const std::regex part_pattern(R"(([A-Za-z_][A-Za-z0-9_]*)(\[[0-9]*\])*)");
  std::size_t begin = 0;
  bool first = true;
  while (begin <= member.size()) {
    const std::size_t end = std::min(member.find('.', begin), member.size());
    const std::string part = member.substr(begin, end - begin);
    std::smatch match;
    if (!std::regex_match(part, match, part_pattern)) return false;
    if (!contains_word(first ? body : source, match[1].str())) return false;
    first = false;
    begin = end + 1;
  }
  return true;
}

}  // namespace

BlockLayout nested_layout(const std::string& prefix, std::size_t offset, const BlockLayout& members) {
  BlockLayout nested;
  nested.reserve(members.size());
  for (const auto& member : members) nested.push_back({prefix + member.name, offset + member.offset});
  return nested;
}

std::map<std::string, std::string> compiled_shader_digests() {
  const std::lock_guard lock(digests_mutex);
  return digests;
}

std::filesystem::path shader_root() { return GT_SHADER_DIR; }

namespace {
std::mutex overlay_mutex;
std::filesystem::path overlay_folder;
}  // namespace

void set_shader_overlay(const std::filesystem::path& folder) {
  const std::lock_guard lock(overlay_mutex);
  overlay_folder = folder;
}

std::filesystem::path shader_overlay() {
  const std::lock_guard lock(overlay_mutex);
  return overlay_folder;
}

std::string ExpandedShader::locate_info_log(const std::string& info_log) const {
  static const std::regex mesa_prefix(R"(\d+:(\d+)\((\d+)\): (.*))");
  static const std::regex nvidia_prefix(R"(\d+\((\d+)\) : (.*))");
  std::string located;
  std::istringstream lines(info_log);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    const bool mesa = std::regex_match(line, match, mesa_prefix);
    if (mesa || std::regex_match(line, match, nvidia_prefix)) {
      const auto expanded_line = std::stoul(match[1].str());
      if (expanded_line >= 1 && expanded_line <= origins.size()) {
        const Origin& origin = origins[expanded_line - 1];
        line = mesa ? fmt::format("{}:{}:{}: {}", origin.file, origin.line, match[2].str(), match[3].str())
                    : fmt::format("{}:{}: {}", origin.file, origin.line, match[2].str());
      }
    }
    if (!located.empty()) located += '\n';
    located += line;
  }
  return located;
}

ExpandedShader expand_shader(const std::filesystem::path& root, const std::string& relative_path,
                             const std::vector<std::string>& defines) {
  return IncludeExpander(root, defines).expand(relative_path);
}

ComputeProgram ComputeProgram::load(const std::string& relative_path, const std::vector<std::string>& defines) {
  return load_from(shader_root(), relative_path, defines);
}

ComputeProgram ComputeProgram::load_from(const std::filesystem::path& root, const std::string& relative_path,
                                         const std::vector<std::string>& defines) {
  auto linked = build_program({load_stage(GL_COMPUTE_SHADER, root, relative_path, defines)});
  return ComputeProgram(linked.id, std::move(linked.description), std::move(linked.source));
}

GlProgram::GlProgram(GlProgram&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      description_(std::move(other.description_)),
      source_(std::move(other.source_)) {}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
    description_ = std::move(other.description_);
    source_ = std::move(other.source_);
  }
  return *this;
}

GlProgram::~GlProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

void GlProgram::use() const { glUseProgram(id_); }

GLint GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

GLint GlProgram::required_uniform(const char* name) const {
  const GLint location = uniform(name);
  if (location < 0) throw std::runtime_error(fmt::format("{}: no active uniform `{}`", description_, name));
  return location;
}

void GlProgram::check_block(const char* block_name, std::size_t size, const BlockLayout& members) const {
  GLenum block_interface = GL_UNIFORM_BLOCK, member_interface = GL_UNIFORM;
  GLuint block = glGetProgramResourceIndex(id_, block_interface, block_name);
  if (block == GL_INVALID_INDEX) {
    block_interface = GL_SHADER_STORAGE_BLOCK;
    member_interface = GL_BUFFER_VARIABLE;
    block = glGetProgramResourceIndex(id_, block_interface, block_name);
  }
  if (block == GL_INVALID_INDEX) {
    throw std::runtime_error(fmt::format("{}: the C++ mirror of block {} has no counterpart: the program has no active "
                                         "uniform or shader storage block of that name",
                                         description_, block_name));
  }
  std::vector<std::string> mismatches;
  const auto glsl_size = resource_property(id_, block_interface, block, GL_BUFFER_DATA_SIZE);
  if (glsl_size < 0 || static_cast<std::size_t>(glsl_size) != size) {
    mismatches.push_back(fmt::format("block size: C++ {} bytes, GLSL {} bytes", size, glsl_size));
  }
  const auto body = block_body(source_, block_name);
  for (const auto& member : members) {
    const GLuint index = glGetProgramResourceIndex(id_, member_interface, member.name.c_str());
    if (index == GL_INVALID_INDEX) {
      // A block with an instance name prefixes its members with the block name.
      const std::string prefix = std::string(block_name) + ".";
      const std::string declared =
          member.name.starts_with(prefix) ? member.name.substr(prefix.size()) : member.name;
      if (body && declared_in_source(source_, *body, declared)) continue;  // declared, not active
      mismatches.push_back(fmt::format("member {}: C++ offset {}, no such member in the GLSL block", member.name,
                                       member.offset));
      continue;
    }
    if (resource_property(id_, member_interface, index, GL_BLOCK_INDEX) != static_cast<GLint>(block)) {
      mismatches.push_back(fmt::format("member {}: C++ offset {}, but in GLSL it is not a member of this block",
                                       member.name, member.offset));
      continue;
    }
    const auto glsl_offset = resource_property(id_, member_interface, index, GL_OFFSET);
    if (glsl_offset < 0 || static_cast<std::size_t>(glsl_offset) != member.offset) {
      mismatches.push_back(
          fmt::format("member {}: C++ offset {}, GLSL offset {}", member.name, member.offset, glsl_offset));
    }
  }
  if (!mismatches.empty()) {
    throw std::runtime_error(fmt::format("{}: the C++ mirror of {} block {} does not match the GLSL layout: {}",
                                         description_, block_interface == GL_UNIFORM_BLOCK ? "uniform" : "storage",
                                         block_name, fmt::join(mismatches, "; ")));
  }
}

ComputeProgram::ComputeProgram(GLuint id, std::string description, std::string source)
    : GlProgram(id, std::move(description), std::move(source)) {
  glGetProgramiv(id, GL_COMPUTE_WORK_GROUP_SIZE, local_size_.data());
}

void ComputeProgram::dispatch(int width, int height, int local_x, int local_y) const {
  if (local_x != local_size_[0] || local_y != local_size_[1] || local_size_[2] != 1) {
    throw std::invalid_argument(fmt::format("dispatch with local size {}x{}, the shader declares {}x{}x{}", local_x,
                                            local_y, local_size_[0], local_size_[1], local_size_[2]));
  }
  if (width < 0 || height < 0) {
    throw std::invalid_argument(fmt::format("dispatch over a negative extent {}x{}", width, height));
  }
  use();
  glDispatchCompute(static_cast<GLuint>(group_count(width, local_x)), static_cast<GLuint>(group_count(height, local_y)),
                    1);
}

GraphicsProgram GraphicsProgram::load(const std::string& vertex_path, const std::string& fragment_path,
                                      const std::vector<std::string>& defines) {
  return load_from(shader_root(), vertex_path, fragment_path, defines);
}

GraphicsProgram GraphicsProgram::load_from(const std::filesystem::path& root, const std::string& vertex_path,
                                           const std::string& fragment_path, const std::vector<std::string>& defines) {
  auto linked = build_program({load_stage(GL_VERTEX_SHADER, root, vertex_path, defines),
                               load_stage(GL_FRAGMENT_SHADER, root, fragment_path, defines)});
  return GraphicsProgram(linked.id, std::move(linked.description), std::move(linked.source));
}

}  // namespace gt
