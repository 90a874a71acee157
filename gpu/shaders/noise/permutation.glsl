// The permutation table of the lattice noises, GLSL side of core/noise/permutation.hpp: the host
// uploads doubled_permutation(table), 512 uints (the 256-entry table twice), so that
// perm[i + step + perm[j ...]] with i <= 255, step <= 1 and a looked-up entry <= 255 needs no wrap.
// Guarded: several noise files include it.
// Inputs:  declares perm (storage binding 5, read only): the doubled table, 512 uints.
// Outputs: the table for the lattice noises.
// Twin:    core/noise/permutation.hpp (doubled_permutation).
#ifndef GT_NOISE_PERMUTATION_GLSL
#define GT_NOISE_PERMUTATION_GLSL

layout(std430, binding = 5) readonly buffer Permutation { uint perm[]; };

#endif
