// Seed 001's sediment diffusion weights (digest 001 §3.8), a parameter of both models that diffuse
// sediment: the pipe model's seed 001 variant (core/params/hydraulic.hpp) and the layered ground
// (core/params/layered.hpp).
//   uniform: the thesis's symmetric weight σ to each edge neighbour, 1 − Σσ kept;
//   water:   its code's weights by water depth, ½·w_n/(w + Σ ½·w_n) to neighbour n (nothing moves
//            where base = 0).
#pragma once

#include "core/param_table.hpp"

namespace gt {

enum class DiffusionWeighting { uniform, water };

inline constexpr Choice<DiffusionWeighting> diffusion_weighting_choices[] = {{"uniform", DiffusionWeighting::uniform},
                                                                             {"water", DiffusionWeighting::water}};

// "uniform", "water".
inline const char* diffusion_weighting_name(DiffusionWeighting weighting) {
  return choice_name(diffusion_weighting_choices, weighting);
}

}  // namespace gt
