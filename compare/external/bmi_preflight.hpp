// Before a run grades an outside implementation, one instance of it is made for each case (a
// library's in a child process, `isolated`; a Python object's in this one): registered, initialised
// with the case's config and checked against the declared state (bmi_conformance.hpp). Bad input there (a missing library or function, a variable with the
// wrong name, unit, type or grid) is the user's to fix before anything runs: exit 2 with every
// mismatch named. A crash or hang of the model there is said the same way, with the signal or the
// time limit, and the harness is untouched (the child's).
//
// Inputs:  the outside model, the algorithm, its declared state and grid, the resolved parameters,
//          the case's name, and the seconds the child may take.
// Throws:  InputError with what the child found; nothing when the model conforms.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "compare/external/bmi_model.hpp"
#include "compare/stepper.hpp"

namespace gt {

void preflight_implementation(const ExternalModel& external, const std::string& algorithm,
                              const StateDecl& decl, const StateGrid& grid, const nlohmann::json& params,
                              const std::string& case_name, double timeout_seconds, bool isolated);

}  // namespace gt
