// The permutation of 0..255 that lattice noises hash their cells with: Ken Perlin's reference table
// (Perlin 2002; the table seed 004's simplex noise uses, digest 004 §2.2.3), or a seeded shuffle of
// it. Shared data of the noise twins: the references index it directly, the shaders receive it as
// a storage buffer of 512 uints (the table twice, so perm[i + perm[j]] needs no wrap).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace gt {

using Permutation = std::array<std::uint8_t, 256>;

// Perlin's reference permutation.
const Permutation& perlin_permutation();

// Seed 0 gives perlin_permutation(); any other seed a Fisher-Yates shuffle of it driven by the
// counter RNG: entry i (from 255 down to 1) swaps with entry random_u32(seed, i, 0, 0) % (i + 1).
// (The modulo bias, below 2^-24 relative, is irrelevant for a hash table.)
Permutation seeded_permutation(std::uint32_t seed);

// The table twice, as the shaders' storage buffer holds it.
std::vector<std::uint32_t> doubled_permutation(const Permutation& permutation);

}  // namespace gt
