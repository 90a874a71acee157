// Whether an outside model, initialised for a case, exposes the algorithm's declared state the way
// the harness reads and writes it (include/groundtruth/bmi.h says the rules to the user).
//
// Inputs:  the model, the algorithm's StateDecl (compare/stepper.hpp) and the case's grid.
// Outputs: the layout the stepper uses: whether the fields are double (float64) or float (float32),
//          and whether the model takes the iteration count as the input variable "iteration".
// Throws:  InputError listing every mismatch at once: a declared field missing from the output or
//          input variables, a unit, type, item size, byte count, grid rank, shape or spacing other
//          than expected (each with what was expected), fields of mixed precision.
#pragma once

#include <string>

#include "compare/external/bmi_model.hpp"
#include "compare/stepper.hpp"

namespace gt {

struct BmiLayout {
  bool double_precision = false;
  bool takes_iteration = false;
};

// The name of the optional input variable that receives the iterations behind a loaded state.
inline constexpr const char* bmi_iteration_variable = "iteration";

BmiLayout check_bmi_conformance(BmiModel& model, const StateDecl& decl, const StateGrid& grid,
                                const std::string& algorithm);

}  // namespace gt
