// The layered ground's state and its steppers (compare/stepper.hpp) over seed 001's twins:
// reference::layered_iteration in double and float (reference/erosion/layered/iteration.hpp) and
// gpu::LayeredIteration (gpu/erosion/layered/iteration.hpp). The numerical code is theirs.
//
// Inputs:  a LayeredSetup (compare/layered_case.hpp): surface, profile, parameters, vegetation.
// Outputs: the declared state, layered_fields(bedrock layers, wet), in this order:
//            terrain        m    the surface h (topographic__elevation)
//            soil           m    each component's thickness, topsoil then subsoil (cell x layer, 10)
//            bedrock        m    each bedrock layer's thickness, top down (cell x layer)
//            bedrock_type   1    each bedrock layer's type, an index into the case's types
//            vegetation     1    density in [0, 1]
//          and with water (initial_water, rain_rate or the river):
//            water, previous_water  m   the depth now and before the step's flow (surface_water__depth)
//            water_flux     m³/s the outflow of pipes L, R, T, B (cell x pipe)
//            carried        m    suspended material and regolith per kind (cell x layer, 7)
//            wetness        m·s  eq. 3.12
//          Ledger records, one a step, cumulative since the state was loaded:
//            converted.<m>  m³   material m's net conversion (into − out of − sunk), m in the ledger's
//                                order: the 5 soil components, then each bedrock type
//            converted_out, converted_in, sunk, water_added, water_sunk   m³
//            volume.<m>     m³   (the references) each material's volume, in the ground and in the water
//            deepest_water  m    (the references, with water) the deepest column
// Conventions: the models keep a kind per plane (plane k: values k·cells ..); the state interleaves
// them per cell (compare/stepper.hpp). Iteration numbers seed the RNG: a stepper loaded with `done`
// iterations behind it steps iteration done next, as the walk from the start does.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/layered_case.hpp"
#include "compare/stepper.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"

namespace gt {

StateDecl layered_fields(int bedrock_layers, bool wet);

// The setup's start state in double.
State layered_start_state(const LayeredSetup& setup);

// The state's ground and, when it has the water's fields, its water, in double.
LayeredGround<double> layered_ground_of(const State& state, int bedrock_layers);
std::optional<LayeredWater<double>> layered_water_of(const State& state);

// Every material's volume, m³, in the ledger's order (the 5 components, in the ground and in the
// water; then each bedrock type).
std::vector<double> layered_volumes(const State& state, int bedrock_layers, std::size_t types);
double layered_water_volume(const State& state);

// The ledger record keys of material m.
std::string layered_converted_key(std::size_t material);
std::string layered_volume_key(std::size_t material);

template <class Real>
std::unique_ptr<Stepper> layered_reference_stepper(const LayeredSetup& setup);
// Needs a current GL context.
std::unique_ptr<Stepper> layered_gpu_stepper(const LayeredSetup& setup);

}  // namespace gt
