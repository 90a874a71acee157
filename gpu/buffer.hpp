// GL buffers for the GPU twins: shader storage buffers (std430 arrays) and uniform buffers (one
// std140 block each).
//
// Conventions: immutable storage of a fixed byte size made with DSA (glCreateBuffers,
// glNamedBufferStorage with GL_DYNAMIC_STORAGE_BIT), so contents change only through upload().
// Move-only RAII; a current GlContext is needed. Element types must be trivially copyable and
// laid out like their GLSL block (each parameter struct is checked against the linked programs
// with GlProgram::check_block, shader_program.hpp).
// Sizes are checked: a zero-byte buffer, or an upload/download past the end, throws
// std::invalid_argument / std::out_of_range. download() waits for the GPU (glGetNamedBufferSubData);
// shaders that wrote the buffer must be followed by the matching glMemoryBarrier first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include <glad/gl.h>

namespace gt {

// What the two buffer kinds share; not used on its own.
class GlBuffer {
 public:
  GlBuffer(GlBuffer&& other) noexcept;
  GlBuffer& operator=(GlBuffer&& other) noexcept;
  GlBuffer(const GlBuffer&) = delete;
  GlBuffer& operator=(const GlBuffer&) = delete;
  ~GlBuffer();

  GLuint id() const { return id_; }
  std::size_t size_bytes() const { return size_bytes_; }

  // Writes `bytes` bytes at the start of the buffer.
  void upload(const void* data, std::size_t bytes);

  template <class T>
  std::vector<T> download(std::size_t count) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<T> values(count);
    read_bytes(values.data(), count * sizeof(T));
    return values;
  }

 protected:
  explicit GlBuffer(std::size_t bytes);
  void bind_base(GLenum target, GLuint binding) const;

 private:
  void read_bytes(void* destination, std::size_t bytes) const;

  GLuint id_ = 0;
  std::size_t size_bytes_ = 0;
};

// A GL_SHADER_STORAGE_BUFFER: an array of T (std430) bound to `layout(binding = N) buffer`.
class StorageBuffer : public GlBuffer {
 public:
  explicit StorageBuffer(std::size_t bytes) : GlBuffer(bytes) {}

  template <class T>
  static StorageBuffer from(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    StorageBuffer buffer(values.size() * sizeof(T));
    buffer.upload(values.data(), values.size() * sizeof(T));
    return buffer;
  }

  void bind(GLuint binding) const { bind_base(GL_SHADER_STORAGE_BUFFER, binding); }
  // Binds bytes [offset, offset + bytes): a window of a buffer larger than the shader may address
  // (GL_MAX_SHADER_STORAGE_BLOCK_SIZE). offset must be a multiple of
  // GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT; an empty or out-of-range window throws
  // std::out_of_range.
  void bind_range(GLuint binding, std::size_t offset, std::size_t bytes) const;
};

// GL_MAX_SHADER_STORAGE_BLOCK_SIZE of the current context: the most bytes one storage block may address.
std::int64_t storage_block_limit();

// A storage buffer of `bytes`, or std::runtime_error when that exceeds `limit` (storage_block_limit()):
// "<what> need <bytes> bytes, more than this GL's GL_MAX_SHADER_STORAGE_BLOCK_SIZE of <limit> bytes; use
// a smaller block", `what` naming the twin and the contents.
StorageBuffer limited_storage(std::size_t bytes, const std::string& what, std::int64_t limit);

// A GL_UNIFORM_BUFFER holding one std140 block, bound to `layout(std140, binding = N) uniform`.
class UniformBuffer : public GlBuffer {
 public:
  explicit UniformBuffer(std::size_t bytes) : GlBuffer(bytes) {}

  template <class Block>
  static UniformBuffer from(const Block& block) {
    UniformBuffer buffer(sizeof(Block));
    buffer.upload(block);
    return buffer;
  }

  using GlBuffer::upload;
  template <class Block>
  void upload(const Block& block) {
    static_assert(std::is_trivially_copyable_v<Block> && !std::is_pointer_v<Block>);
    upload(&block, sizeof(Block));
  }

  void bind(GLuint binding) const { bind_base(GL_UNIFORM_BUFFER, binding); }
};

}  // namespace gt
