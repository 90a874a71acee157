// Column operations of seed 001's layered ground (digest 001 §3.1, §3.10), CPU reference.
//
//   organize_horizon(g, c, needed, max): "reserve": when topsoil + needed > max and the topsoil is
//     not empty, move the share clamp((topsoil + needed − max)/topsoil, 0, 1) of every topsoil
//     component into the subsoil (the code's organize_horizon).
//   deposit_soil(g, c, material, max): reserve room for the whole material, add it to the topsoil,
//     then push any remaining excess down (organize_horizon(0)). So a full organic topsoil that
//     receives a topsoil's worth of rock ends pure rock over an organic subsoil (the thesis's
//     example), not half and half.
//   remove_soil(g, c, amount): take from the topsoil, then the subsoil (each proportionally to its
//     components), then from the first non-empty bedrock layer. Decision: the removal stops there
//     (the code's rule); what that layer cannot give is not taken, and the result says what was.
//   fragments(type, amount): bedrock broken into sand..boulders by the type's K_rock. Eq. 3.3's
//     bedrock flux S = K_rock_j·Δmaterial/h_rock gives a fraction; the intent, S = K_rock_j·Δmaterial,
//     is taken. Decision: boulders get the remainder amount − (sand + gravel + stones), so the
//     fragments sum to the rock volume to rounding whatever the rounding of ΣK_rock.
// Every operation changes the surface height by the thickness it adds or removes, as the code keeps
// its height map in step with the layers. Units: metres.
#pragma once

#include <array>
#include <cstddef>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
using Composition = std::array<Real, soil_component_count>;  // component thicknesses, m

// Sum of the parts in index order (the order the GPU twin adds them in).
template <class Real, std::size_t Count>
Real ordered_total(const std::array<Real, Count>& parts) {
  Real sum = 0;
  for (Real part : parts) sum += part;
  return sum;
}

template <class Real>
Real composition_total(const Composition<Real>& material) {
  return ordered_total(material);
}

// What remove_soil took: soil components (both soil layers together) and bedrock of one layer.
template <class Real>
struct Removed {
  Composition<Real> soil{};
  int bedrock_layer = -1;  // -1: none taken
  Real bedrock = 0;
  Real total() const { return composition_total(soil) + bedrock; }
};

// The topmost layer with thickness > 0: 0 topsoil, 1 subsoil, 2 + k bedrock layer k; -1 none.
template <class Real>
int top_nonempty_layer(const LayeredGround<Real>& ground, std::size_t c);

template <class Real>
void organize_horizon(LayeredGround<Real>& ground, std::size_t c, Real needed, Real topsoil_max);

template <class Real>
void deposit_soil(LayeredGround<Real>& ground, std::size_t c, const Composition<Real>& material, Real topsoil_max);

template <class Real>
Removed<Real> remove_soil(LayeredGround<Real>& ground, std::size_t c, Real amount);

template <class Real>
Composition<Real> fragments(const BedrockType& type, Real amount);

}  // namespace gt::reference
