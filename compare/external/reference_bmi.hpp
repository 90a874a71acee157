// groundtruth's own reference of a stepped algorithm behind the Basic Model Interface: what a
// framework that drives models through the BMI (landlab, pymt) steps, and the round trip that
// checks the protocol itself — the reference, handed to the harness as an outside model, must pass.
//
// Inputs:  the algorithm (a stepped one), the precision (ref<double> or ref<float>), and the config
//          file initialize() reads (compare/external/bmi_config.hpp: rows, columns, spacing and the
//          parameters, as the harness writes it).
// Outputs: the declared state fields as variables (values as doubles here; their declared type
//          float64 or float32), "iteration" as an input, update() one iteration of the reference.
// Decisions: the twin is prepared on a flat grid of the config's size and spacing; the state the
//          caller sets replaces it. What an algorithm derives from its input heights beyond the
//          state (erosion.pipe's orographic rain map, erosion.thermal's normalised aspect) is not
//          in the config, so the round trip holds where the parameters alone set the model.
// Throws:  InputError for a config or algorithm it cannot use; std::out_of_range for an unknown
//          variable name.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "compare/stepper.hpp"

namespace gt {

class ReferenceBmi {
 public:
  ReferenceBmi(std::string algorithm, bool double_precision);
  void initialize(const std::filesystem::path& config);
  void update();
  std::vector<std::string> output_names() const;
  std::vector<std::string> input_names() const;
  const FieldDecl& field(const std::string& name) const;
  const StateGrid& grid() const { return state_.grid; }
  bool double_precision() const { return double_precision_; }
  int iteration() const { return iteration_; }
  // A field's values, components interleaved per cell.
  std::vector<double> get(const std::string& name);
  void set(const std::string& name, const std::vector<double>& values);
  void set_iteration(int iteration);

 private:
  void require_initialised() const;
  void sync_state();  // state_ from the stepper, where it stepped since
  std::string algorithm_;
  bool double_precision_;
  StateDecl fields_;
  State state_;
  std::unique_ptr<Stepper> stepper_;
  bool stepped_ = false;  // the stepper holds a newer state than state_
  int iteration_ = 0;
};

}  // namespace gt
