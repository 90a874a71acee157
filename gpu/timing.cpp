// gpu_wall_ms and gpu_timer_query_ms (see timing.hpp).
#include "gpu/timing.hpp"

#include <chrono>

#include <glad/gl.h>

namespace gt {
namespace {

// A GL_TIME_ELAPSED query that is active from construction until nanoseconds() ends it; the
// destructor also ends it (when work throws) so that the next query can begin.
class ElapsedQuery {
 public:
  ElapsedQuery() {
    glCreateQueries(GL_TIME_ELAPSED, 1, &id_);
    glBeginQuery(GL_TIME_ELAPSED, id_);
  }
  ElapsedQuery(const ElapsedQuery&) = delete;
  ElapsedQuery& operator=(const ElapsedQuery&) = delete;
  ~ElapsedQuery() {
    if (active_) glEndQuery(GL_TIME_ELAPSED);
    glDeleteQueries(1, &id_);
  }

  GLuint64 nanoseconds() {
    glEndQuery(GL_TIME_ELAPSED);
    active_ = false;
    GLuint64 result = 0;
    glGetQueryObjectui64v(id_, GL_QUERY_RESULT, &result);
    return result;
  }

 private:
  GLuint id_ = 0;
  bool active_ = true;
};

}  // namespace

double gpu_wall_ms(const std::function<void()>& work) {
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  work();
  glFinish();
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(stop - start).count();
}

std::optional<double> gpu_timer_query_ms(const std::function<void()>& work) {
  ElapsedQuery query;
  work();
  const GLuint64 nanoseconds = query.nanoseconds();
  if (nanoseconds == 0) return std::nullopt;
  return static_cast<double>(nanoseconds) * 1e-6;
}

}  // namespace gt
