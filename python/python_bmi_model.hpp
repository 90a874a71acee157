// An outside model written in Python, behind bmipy's method names (duck-typed: initialize, update,
// finalize, get_output_var_names, get_input_var_names, get_var_type, get_var_units,
// get_var_itemsize, get_var_nbytes, get_var_grid, get_grid_rank, get_grid_size, get_grid_shape,
// get_grid_spacing, get_value, set_value), driven by the harness's stepper like a C library's.
//
// Inputs:  a Python callable that returns a fresh model (a class, or a function returning the one
//          object the caller gave), the name it is shown by, the case's config file.
// Outputs: compare/external/bmi_model.hpp's BmiModel. Each call takes the GIL (the driver runs with
//          it released); a Python exception becomes std::runtime_error naming the method and
//          carrying Python's message.
#pragma once

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "compare/external/bmi_model.hpp"

namespace gt::python {

// The run's ExternalModel for a Python model factory.
ExternalModel python_external_model(const pybind11::object& factory, const std::string& label);

}  // namespace gt::python
