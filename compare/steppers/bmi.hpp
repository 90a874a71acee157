// An outside implementation as a stepper: its model behind the C Basic Model Interface
// (include/groundtruth/bmi.h), loaded with the algorithm's declared state and stepped by update().
//
// Inputs:  the model (compare/external/bmi_model.hpp: a C library's, a Python object's), already
//          initialised with the case's config file, the declared state and its grid.
// Outputs: a Stepper (compare/stepper.hpp): set_state writes every field with set_value (and the
//          iterations behind it to "iteration" where the model takes it), update(n) calls update()
//          n times, get_state reads every field with get_value, widened to double.
// Units:   the declared fields' own; the model's are checked against them when it is made.
// Conventions: no-data cells are handed over as NaN (the model keeps them and treats them as
//          absent); fields are float or double as the model declares (every field alike).
// Throws:  InputError when the model does not expose the state as declared
//          (compare/external/bmi_conformance.hpp), std::runtime_error when a BMI call fails.
// Twin:    none of its own: it stands where the GPU twin stands (compare/stepped_case.hpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <vector>

#include "compare/external/bmi_conformance.hpp"
#include "compare/external/bmi_model.hpp"
#include "compare/stepper.hpp"

namespace gt {

class BmiStepper : public Stepper {
 public:
  BmiStepper(std::unique_ptr<BmiModel> model, StateDecl decl, StateGrid grid, const std::string& algorithm);
  void set_state(const State& state, int done) override;
  void update(int count) override;
  State get_state() override;
  bool double_precision() const { return layout_.double_precision; }

 private:
  std::unique_ptr<BmiModel> model_;
  StateDecl decl_;
  StateGrid grid_;
  BmiLayout layout_;
  std::vector<std::byte> buffer_;
};

}  // namespace gt
