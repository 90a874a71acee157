// Memory estimates checked before allocating (issue 18): a file, a case or a command states what
// it is about to need, and is refused with that estimate in the message when it exceeds what this
// process may still use, instead of being killed half-way or thrashing the machine.
//
//   double available_memory_bytes()
//     The least of: MemAvailable of /proc/meminfo (what Linux can give without swapping), the
//     address-space limit (RLIMIT_AS) less the address space in use (VmSize), the cgroup v2
//     memory.max less memory.current (containers), and the limit set by set_memory_limit
//     (groundtruth --memory-limit). +inf when none is known.
//
//   void set_memory_limit(double bytes)
//     A cap of the caller's choosing (0: none).
//
//   void require_memory(double bytes, const std::string& basis, const std::string& what)
//     Throws InputError "WHAT needs about N MiB (BASIS), more than the M MiB this process may use
//     (SOURCE)" when bytes > available_memory_bytes(). `basis` says how the estimate was made,
//     e.g. "512x512 cells x 460 B a cell". Estimates are doubles: products of untrusted sizes can
//     not overflow them.
//
// Conventions: estimates are upper bounds of the extra peak resident memory, measured for each
// algorithm and written beside it; the process's fixed cost (code, GL driver, LLVM's JIT: about
// 200 MiB under llvmpipe) is the stated margin, not part of any estimate.
#pragma once

#include <string>

namespace gt {

// What a case or a file is about to need: bytes, and how they were counted (for messages).
struct MemoryEstimate {
  double bytes = 0.0;
  std::string basis;
};

// `count` items of `bytes_each`: {count·bytes_each, "COUNT UNIT x BYTES_EACH B"}.
MemoryEstimate memory_for(double count, const std::string& unit, double bytes_each);
MemoryEstimate operator+(const MemoryEstimate& a, const MemoryEstimate& b);

double available_memory_bytes();
void set_memory_limit(double bytes);
void require_memory(double bytes, const std::string& basis, const std::string& what);
void require_memory(const MemoryEstimate& estimate, const std::string& what);

// "12.5 MiB", "3.2 GiB": a size for messages.
std::string format_bytes(double bytes);

}  // namespace gt
