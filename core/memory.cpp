#include "core/memory.hpp"

#include <sys/resource.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

double user_limit = 0.0;

// A "Key:   1234 kB" field of a /proc file, in bytes; +inf when absent.
double proc_field_bytes(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key + ":", 0) != 0) continue;
    std::istringstream fields(line.substr(key.size() + 1));
    double kilobytes = 0.0;
    if (fields >> kilobytes) return kilobytes * 1024.0;
  }
  return std::numeric_limits<double>::infinity();
}

// memory.max less memory.current of this process's cgroup (v2); +inf when unlimited or unknown.
double cgroup_memory_left() {
  std::ifstream max_file("/sys/fs/cgroup/memory.max");
  std::ifstream current_file("/sys/fs/cgroup/memory.current");
  double max = 0.0;
  double current = 0.0;
  // "max" (no limit) fails to parse as a number, like a missing file.
  if (!(max_file >> max) || !(current_file >> current)) return std::numeric_limits<double>::infinity();
  return std::max(max - current, 0.0);
}

struct Limit {
  double bytes = std::numeric_limits<double>::infinity();
  std::string source = "no limit known";
};

Limit tightest_limit() {
  Limit limit;
  const auto consider = [&limit](double bytes, std::string source) {
    if (bytes < limit.bytes) limit = {bytes, std::move(source)};
  };
  consider(proc_field_bytes("/proc/meminfo", "MemAvailable"), "MemAvailable of /proc/meminfo");
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
    const double in_use = proc_field_bytes("/proc/self/status", "VmSize");
    const double left = static_cast<double>(address_space.rlim_cur) - (std::isfinite(in_use) ? in_use : 0.0);
    consider(std::max(left, 0.0), "the address-space limit (ulimit -v) less what is mapped");
  }
  consider(cgroup_memory_left(), "the container's memory.max (cgroup v2) less its memory.current");
  if (user_limit > 0.0) consider(user_limit, "--memory-limit");
  return limit;
}

}  // namespace

double available_memory_bytes() { return tightest_limit().bytes; }

void set_memory_limit(double bytes) { user_limit = bytes > 0.0 ? bytes : 0.0; }

std::string format_bytes(double bytes) {
  if (!std::isfinite(bytes)) return "unbounded";
  if (bytes >= 1024.0 * 1024.0 * 1024.0) return fmt::format("{:.1f} GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  if (bytes >= 1024.0 * 1024.0) return fmt::format("{:.1f} MiB", bytes / (1024.0 * 1024.0));
  return fmt::format("{:.0f} KiB", std::ceil(bytes / 1024.0));
}

MemoryEstimate memory_for(double count, const std::string& unit, double bytes_each) {
  return {count * bytes_each, fmt::format("{:.0f} {} x {:g} B", count, unit, bytes_each)};
}

MemoryEstimate operator+(const MemoryEstimate& a, const MemoryEstimate& b) {
  return {a.bytes + b.bytes, a.basis + " + " + b.basis};
}

void require_memory(const MemoryEstimate& estimate, const std::string& what) {
  require_memory(estimate.bytes, estimate.basis, what);
}

void require_memory(double bytes, const std::string& basis, const std::string& what) {
  const Limit limit = tightest_limit();
  if (!(bytes <= limit.bytes)) {
    throw InputError(fmt::format("{} needs about {} ({}), more than the {} this process may use ({})", what,
                                 format_bytes(bytes), basis, format_bytes(limit.bytes), limit.source));
  }
}

}  // namespace gt
