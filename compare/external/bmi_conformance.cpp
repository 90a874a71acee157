// Checks an outside model's variables against the algorithm's declared state; see bmi_conformance.hpp.
#include "compare/external/bmi_conformance.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"

namespace gt {
namespace {

// The precision a BMI type name says: float32 or float64; empty for any other type.
std::optional<bool> is_double(const std::string& type) {
  if (type == "float" || type == "float32") return false;
  if (type == "double" || type == "float64") return true;
  return std::nullopt;
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The grid a field of `components` values a cell lives on: {rows, columns}, or {rows, columns,
// components}; spacing {dy, dx} (a component axis has spacing 1).
std::vector<int> expected_shape(const StateGrid& grid, int components) {
  if (components == 1) return {grid.height, grid.width};
  return {grid.height, grid.width, components};
}

bool spacing_matches(const BmiGrid& found, const StateGrid& grid) {
  const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); };
  return found.spacing.size() >= 2 && close(found.spacing[0], grid.cell_size_y) && close(found.spacing[1], grid.cell_size_x);
}

void check_field(BmiModel& model, const FieldDecl& field, const StateGrid& grid, std::vector<std::string>& problems,
                 std::optional<bool>& precision) {
  const BmiVariable variable = model.variable(field.name);
  const std::string who = fmt::format("'{}'", field.name);
  if (variable.units != field.unit) {
    problems.push_back(fmt::format("{}: units '{}', expected '{}' ({})", who, variable.units, field.unit, field.meaning));
  }
  const auto precise = is_double(variable.type);
  if (!precise) {
    problems.push_back(fmt::format("{}: type '{}', expected float (float32) or double (float64)", who, variable.type));
    return;
  }
  if (precision && *precision != *precise) {
    problems.push_back(fmt::format("{}: type '{}' where another field is {}: declare every field in one precision", who,
                                   variable.type, *precision ? "double" : "float"));
  }
  precision = precision.value_or(*precise);
  const int itemsize = *precise ? 8 : 4;
  if (variable.itemsize != itemsize) {
    problems.push_back(fmt::format("{}: itemsize {}, expected {} for type '{}'", who, variable.itemsize, itemsize, variable.type));
  }
  const long long nbytes = static_cast<long long>(grid.cells()) * field.components * itemsize;
  if (variable.nbytes != nbytes) {
    problems.push_back(fmt::format("{}: nbytes {}, expected {} ({} cells × {} value(s) × {} bytes)", who, variable.nbytes,
                                   nbytes, grid.cells(), field.components, itemsize));
  }
  const BmiGrid found = model.grid(variable.grid);
  const std::vector<int> shape = expected_shape(grid, field.components);
  if (found.shape != shape) {
    problems.push_back(fmt::format("{}: grid {} has shape [{}], expected [{}] (rows, columns{})", who, variable.grid,
                                   fmt::join(found.shape, ", "), fmt::join(shape, ", "),
                                   field.components > 1 ? ", values a cell" : ""));
  } else if (!spacing_matches(found, grid)) {
    problems.push_back(fmt::format("{}: grid {} has spacing [{}], expected [{:.17g}, {:.17g}] (dy, dx in {})", who,
                                   variable.grid, fmt::join(found.spacing, ", "), grid.cell_size_y, grid.cell_size_x,
                                   grid.horizontal_unit));
  }
}

void check_iteration(BmiModel& model, std::vector<std::string>& problems) {
  const BmiVariable variable = model.variable(bmi_iteration_variable);
  if ((variable.type != "int" && variable.type != "int32") || variable.itemsize != 4 || variable.nbytes != 4) {
    problems.push_back(fmt::format("'{}': type '{}', itemsize {}, nbytes {}; expected one int (int32, 4 bytes)",
                                   bmi_iteration_variable, variable.type, variable.itemsize, variable.nbytes));
  }
}

}  // namespace

BmiLayout check_bmi_conformance(BmiModel& model, const StateDecl& decl, const StateGrid& grid,
                                const std::string& algorithm) {
  const auto outputs = model.output_names();
  const auto inputs = model.input_names();
  std::vector<std::string> problems;
  std::optional<bool> precision;
  for (const FieldDecl& field : decl) {
    const bool output = listed(outputs, field.name);
    const bool input = listed(inputs, field.name);
    if (!output || !input) {
      problems.push_back(fmt::format("'{}' ({}, {}) is not among its {} variables", field.name, field.unit,
                                     field.meaning, !output && !input ? "input or output" : !output ? "output" : "input"));
      continue;
    }
    check_field(model, field, grid, problems, precision);
  }
  const bool takes_iteration = listed(inputs, bmi_iteration_variable);
  if (takes_iteration) check_iteration(model, problems);
  if (!problems.empty()) {
    std::vector<std::string> expected;
    for (const FieldDecl& field : decl) expected.push_back(fmt::format("{} ({})", field.name, field.unit));
    throw InputError(fmt::format(
        "{} does not expose {}'s state as declared:\n  {}\n(expected: {}; its output variables: {}; input variables: "
        "{}; include/groundtruth/bmi.h)",
        model.label(), algorithm, fmt::join(problems, "\n  "), fmt::join(expected, ", "),
        outputs.empty() ? "none" : fmt::format("{}", fmt::join(outputs, ", ")),
        inputs.empty() ? "none" : fmt::format("{}", fmt::join(inputs, ", "))));
  }
  return {.double_precision = precision.value_or(false), .takes_iteration = takes_iteration};
}

}  // namespace gt
