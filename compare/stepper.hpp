// The stepper protocol: how the harness loads, steps and reads back any iterative twin.
//
// Inputs:  an algorithm's declared state (StateDecl: its fields with units, extents and standard
//          names) and, per backend, a Stepper over that state.
// Outputs: State, one flat array of doubles per declared field on the case's grid.
// Units:   each field's own, as declared; the grid's cell sizes in its horizontal unit.
// Conventions:
//   - A field of extent cell holds one value a cell (row-major, as Grid); cell_layer and cell_pipe
//     hold `components` values a cell, interleaved (cell·components + k), the layout of a C array
//     of per-cell arrays, which is also how the Basic Model Interface hands a variable over.
//   - Values are doubles on every backend: a float twin's values are floats widened exactly, so
//     ref<float>'s state loads into a float GPU twin without a rounding (the shadow steps need
//     both to start from the same bits).
//   - Invalid (no-data) cells are part of the arrays; their values are unspecified and never compared.
//   - A read-only field (FieldDecl::read_only) is an input of the model: a stepper reads it on each
//     set_state and hands it back as loaded.
//   - A stepper counts its iterations: set_state(state, done) says how many lie behind `state`,
//     and update(n) runs the next n, numbered from there (an alternating method reads the number).
// Landlab's components and CSDMS's Basic Model Interface are the models: fields declared once with
// units serve the report, field export, the Python module and outside implementations alike.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/grid.hpp"

namespace gt {

// Where a field's values live: one a cell, or `components` a cell (layers of a column, pipes).
enum class Extent { cell, cell_layer, cell_pipe };

const char* extent_name(Extent extent);

struct FieldDecl {
  std::string name;           // e.g. water; a check or file name part: [a-z0-9_]
  std::string unit;           // e.g. m, m/s, m³/s, 1
  std::string meaning;        // one line
  Extent extent = Extent::cell;
  int components = 1;         // values a cell: 1 for Extent::cell
  bool conserved = false;     // whether the model conserves its total (alone or in a ledger)
  // An input the model reads and hands back unchanged (Jákó's hardness map): it travels with the
  // state so that an outside implementation receives it as it receives the terrain, and the runner
  // holds every backend to returning it bit for bit (state.<name>.unchanged.<backend>).
  bool read_only = false;
  std::string standard_name;  // CSDMS standard name where one exists (topographic__elevation)
  // Names of the components (pipe L, R, ...; layer 0, 1, ...), used in file names; empty: 0, 1, ...
  std::vector<std::string> component_names = {};
};

using StateDecl = std::vector<FieldDecl>;

// The name of component k of a field: the field's own name for a cell field, else name_component.
std::string component_label(const FieldDecl& field, int component);

// The grid a state lives on: its size, spacing, horizontal unit and no-data mask.
struct StateGrid {
  int width = 0;
  int height = 0;
  double cell_size_x = 1.0;
  double cell_size_y = 1.0;
  std::string horizontal_unit = "m";
  std::vector<std::uint8_t> valid;  // empty: every cell valid

  std::size_t cells() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  bool is_valid(std::size_t cell) const { return valid.empty() || valid[cell] != 0; }

  template <class T>
  static StateGrid of(const Grid<T>& grid) {
    return {grid.width, grid.height, grid.cell_size_x, grid.cell_size_y, grid.horizontal_unit, grid.valid};
  }
  // A grid of this geometry filled with `fill`, values in `unit`.
  template <class T>
  Grid<T> blank(T fill, const std::string& unit) const {
    Grid<T> grid(width, height, fill);
    grid.cell_size_x = cell_size_x;
    grid.cell_size_y = cell_size_y;
    grid.horizontal_unit = horizontal_unit;
    grid.vertical_unit = unit;
    grid.valid = valid;
    return grid;
  }
};

struct State {
  StateGrid grid;
  std::vector<std::vector<double>> fields;  // in declaration order, grid.cells()·components each
};

// Component k of field `field` as a grid in the field's unit.
Grid<double> component_grid(const StateDecl& decl, const State& state, std::size_t field, int component);

// Throws std::logic_error unless `state` has one array per declared field, each of its size.
void check_state_shape(const StateDecl& decl, const State& state, const std::string& who);

// Throws std::logic_error naming the first problem: an empty or repeated name, a name with other
// characters than [a-z0-9_], an empty unit, a component count that does not fit the extent.
void check_state_decl(const StateDecl& decl, const std::string& algorithm);

// What a model books beside its state (water rained in, evaporated, gone through the borders):
// totals by name after `step` iterations since the state was loaded; record 0 is the state loaded.
struct LedgerRecord {
  int step = 0;
  std::map<std::string, double> totals;
};

// One backend of an iterative twin. The GPU's update() need not wait for the device: the caller
// brackets it with glFinish to time it; get_state() waits.
class Stepper {
 public:
  virtual ~Stepper() = default;
  // Loads `state`, which has `done` iterations behind it.
  virtual void set_state(const State& state, int done) = 0;
  // The next `count` iterations.
  virtual void update(int count) = 0;
  virtual State get_state() = 0;
  // The records since the last set_state, one a step; none where the model books nothing beside its
  // state (its ledger terms then read the states alone).
  virtual std::vector<LedgerRecord> ledger() { return {}; }
};

}  // namespace gt
