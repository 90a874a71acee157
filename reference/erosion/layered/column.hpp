// Column operations of seed 001's layered ground (digest 001 §3.1, §3.10, §3.12), CPU reference.
//
//   organize_horizon(g, c, needed, max): "reserve": when topsoil + needed > max and the topsoil is
//     not empty, move the share clamp((topsoil + needed − max)/topsoil, 0, 1) of every topsoil
//     component into the subsoil (the code's organize_horizon).
//   deposit_soil(g, c, material, max): reserve room for the whole material, add it to the topsoil,
//     then push any remaining excess down (organize_horizon(0)). So a full organic topsoil that
//     receives a topsoil's worth of rock ends pure rock over an organic subsoil (the thesis's
//     example), not half and half.
//   remove_soil(g, c, amount) -> Removed: take from the topsoil, then the subsoil (each proportionally
//     to its components), then from the first non-empty bedrock layer.
//   fragments(type, amount) -> Composition: bedrock broken into sand..boulders by the type's K_rock.
//   erode_component(g, c, component, request, params) -> what was taken: force erosion's removal of
//     one component (§3.12, eq. 3.10 and the transparency rule), top layer down: in each non-empty
//     soil layer of thickness V holding V_j of the component, take min(m·max(K_emin, V_j/V), V_j)
//     (thesis) or min(V_j, m)·max(K_emin, V_j/V) (share_form seed001_code), then carry the request
//     m ← max(m − V_j, 0)·max(1 − V/K_pmin, 0) to the layer below. Empty layers are skipped (they
//     let everything through). The surface is lowered by what was taken.
//   take_from_layer(g, c, layer, component, request, params) -> one soil layer's part of
//     erode_component (the surface is the caller's to lower).
//   soil_transparency(g, c, params): Π over the non-empty soil layers of max(1 − V/K_pmin, 0), the
//     share of a request that reaches the bedrock.
//   erode_bedrock(g, c, amount) -> ErodedBedrock: takes min(amount, thickness) from the first
//     non-empty bedrock layer (remove_soil's rule: it stops there) and lowers the surface; returns
//     the layer and amount.
//   top_nonempty_layer(g, c), ordered_total(parts), composition_total(material): the topmost layer
//     with thickness > 0 (0 topsoil, 1 subsoil, 2 + k bedrock layer k, -1 none); sums of the parts
//     in index order (the order the GPU twin adds them in).
//
// Inputs:  a LayeredGround<Real> (core/layered/layered_ground.hpp) and a column index c; amounts and
//          requests ≥ 0; LayeredParams (core/params/layered.hpp) for the share form, K_emin, K_pmin.
// Outputs: the column changed in place; every operation changes the surface height by the thickness
//          it adds or removes, as the code keeps its height map in step with the layers.
// Units:   metres.
// Throws:  nothing.
// Twin:    gpu/shaders/erosion/layered/column.glsl (included by apply.comp, force_erosion.comp,
//          impact_erosion.comp and dissolution.comp).
// Decisions:
//   - remove_soil: the removal stops at the first non-empty bedrock layer (the code's rule); what
//     that layer cannot give is not taken, and the result says what was.
//   - fragments: eq. 3.3's bedrock flux S = K_rock_j·Δmaterial/h_rock gives a fraction; the intent,
//     S = K_rock_j·Δmaterial, is taken. Boulders get the remainder amount − (sand + gravel + stones),
//     so the fragments sum to the rock volume to rounding whatever the rounding of ΣK_rock.
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

// One soil layer's part of erode_component: takes min(m·max(K_emin, V_j/V), V_j) (or the
// seed001_code share form) of `component` from soil layer `layer` (thickness V > 0) and returns it;
// the surface is the caller's to lower.
template <class Real>
Real take_from_layer(LayeredGround<Real>& ground, std::size_t c, int layer, int component, Real request,
                     const LayeredParams& params);

template <class Real>
Real erode_component(LayeredGround<Real>& ground, std::size_t c, int component, Real request,
                     const LayeredParams& params);

template <class Real>
Real soil_transparency(const LayeredGround<Real>& ground, std::size_t c, const LayeredParams& params);

// The bedrock layer taken from (-1: none) and the thickness taken, m.
template <class Real>
struct ErodedBedrock {
  int layer = -1;
  Real amount = 0;
};

template <class Real>
ErodedBedrock<Real> erode_bedrock(LayeredGround<Real>& ground, std::size_t c, Real amount);

}  // namespace gt::reference
