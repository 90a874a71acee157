// The stepper protocol's declarations and states; see stepper.hpp.
#include "compare/stepper.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

namespace gt {

const char* extent_name(Extent extent) {
  switch (extent) {
    case Extent::cell: return "cell";
    case Extent::cell_layer: return "cell x layer";
    case Extent::cell_pipe: return "cell x pipe";
  }
  return "?";
}

std::string component_label(const FieldDecl& field, int component) {
  if (field.extent == Extent::cell) return field.name;
  const auto index = static_cast<std::size_t>(component);
  const std::string part = index < field.component_names.size() ? field.component_names[index] : std::to_string(component);
  return field.name + "_" + part;
}

Grid<double> component_grid(const StateDecl& decl, const State& state, std::size_t field, int component) {
  const FieldDecl& declared = decl.at(field);
  Grid<double> grid = state.grid.blank(0.0, declared.unit);
  const auto stride = static_cast<std::size_t>(declared.components);
  const auto& values = state.fields.at(field);
  for (std::size_t cell = 0; cell < grid.size(); ++cell) {
    grid.values[cell] = values[cell * stride + static_cast<std::size_t>(component)];
  }
  return grid;
}

void check_state_shape(const StateDecl& decl, const State& state, const std::string& who) {
  if (state.fields.size() != decl.size()) {
    throw std::logic_error(fmt::format("{}: a state of {} fields where {} are declared", who, state.fields.size(),
                                       decl.size()));
  }
  for (std::size_t f = 0; f < decl.size(); ++f) {
    const std::size_t expected = state.grid.cells() * static_cast<std::size_t>(decl[f].components);
    if (state.fields[f].size() != expected) {
      throw std::logic_error(fmt::format("{}: field {} holds {} values where its extent needs {}", who, decl[f].name,
                                         state.fields[f].size(), expected));
    }
  }
}

void check_state_decl(const StateDecl& decl, const std::string& algorithm) {
  std::set<std::string> seen;
  for (const FieldDecl& field : decl) {
    const auto where = [&](const std::string& what) {
      return std::logic_error(fmt::format("{}: state field '{}': {}", algorithm, field.name, what));
    };
    if (field.name.empty()) throw where("no name");
    const bool plain = std::all_of(field.name.begin(), field.name.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    if (!plain) throw where("a name is made of a-z, 0-9 and _");
    if (!seen.insert(field.name).second) throw where("declared twice");
    if (field.unit.empty()) throw where("no unit (dimensionless is \"1\")");
    if (field.meaning.empty()) throw where("no meaning");
    if (field.read_only && field.conserved) throw where("read-only and conserved: the model never changes it");
    if (field.extent == Extent::cell ? field.components != 1 : field.components < 1) {
      throw where(fmt::format("{} components for extent {}", field.components, extent_name(field.extent)));
    }
  }
}

}  // namespace gt
