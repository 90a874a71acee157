// floor(v) as an int for the noise references' lattice cells, without a call into libm: on the
// x86-64 baseline std::floor is a call (no SSE4.1 roundsd), three of them per sample, a sixth of a
// simplex3 sample's time.
//
// lattice_floor(v) == static_cast<int>(std::floor(v)) for every v where the latter is defined
// (finite, floor(v) in int's range): truncation rounds toward zero, so it is one too high exactly
// when v is negative and not whole. Where the cast of std::floor is undefined, so is this.
#pragma once

namespace gt::reference {

template <class Real>
inline int lattice_floor(Real v) {
  const int truncated = static_cast<int>(v);
  return v < static_cast<Real>(truncated) ? truncated - 1 : truncated;
}

}  // namespace gt::reference
