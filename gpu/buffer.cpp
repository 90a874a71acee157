// GlBuffer: creation, upload, download and binding of immutable DSA buffers (see buffer.hpp).
#include "gpu/buffer.hpp"

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace gt {
namespace {

void require_within(std::size_t bytes, std::size_t size_bytes, const char* operation) {
  if (bytes > size_bytes) {
    throw std::out_of_range(fmt::format("{} of {} bytes from a buffer of {} bytes", operation, bytes, size_bytes));
  }
}

}  // namespace

GlBuffer::GlBuffer(std::size_t bytes) : size_bytes_(bytes) {
  if (bytes == 0) throw std::invalid_argument("a GL buffer needs at least one byte");
  glCreateBuffers(1, &id_);
  glNamedBufferStorage(id_, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

GlBuffer::GlBuffer(GlBuffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)), size_bytes_(std::exchange(other.size_bytes_, 0)) {}

GlBuffer& GlBuffer::operator=(GlBuffer&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteBuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
    size_bytes_ = std::exchange(other.size_bytes_, 0);
  }
  return *this;
}

GlBuffer::~GlBuffer() {
  if (id_ != 0) glDeleteBuffers(1, &id_);
}

void GlBuffer::upload(const void* data, std::size_t bytes) {
  require_within(bytes, size_bytes_, "upload");
  glNamedBufferSubData(id_, 0, static_cast<GLsizeiptr>(bytes), data);
}

void GlBuffer::read_bytes(void* destination, std::size_t bytes) const {
  require_within(bytes, size_bytes_, "download");
  glGetNamedBufferSubData(id_, 0, static_cast<GLsizeiptr>(bytes), destination);
}

void GlBuffer::bind_base(GLenum target, GLuint binding) const { glBindBufferBase(target, binding, id_); }

void StorageBuffer::bind_range(GLuint binding, std::size_t offset, std::size_t bytes) const {
  if (bytes == 0 || offset > size_bytes() || bytes > size_bytes() - offset) {
    throw std::out_of_range(fmt::format("binding bytes [{}, {}) of a {}-byte storage buffer", offset, offset + bytes,
                                        size_bytes()));
  }
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding, id(), static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(bytes));
}

std::int64_t storage_block_limit() {
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  return limit;
}

StorageBuffer limited_storage(std::size_t bytes, const std::string& what, std::int64_t limit) {
  if (bytes > static_cast<std::size_t>(limit)) {
    throw std::runtime_error(fmt::format("{} need {} bytes, more than this GL's GL_MAX_SHADER_STORAGE_BLOCK_SIZE of {} "
                                         "bytes; use a smaller block",
                                         what, bytes, limit));
  }
  return StorageBuffer(bytes);
}

}  // namespace gt
