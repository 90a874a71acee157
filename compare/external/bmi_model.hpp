// A model behind the Basic Model Interface, as the harness drives it, whatever its language: the C
// binding of a shared library (c_bmi_model.hpp), a Python object with bmipy's methods
// (python/module.cpp). The stepper and the conformance check speak to this interface alone.
//
// Outputs: the model's variables and grids as it describes them; update(); whole-variable
//          get_value/set_value through byte buffers of the variable's nbytes.
// Throws:  std::runtime_error (or InputError, for what the user must fix) naming the BMI function.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gt {

struct BmiVariable {
  std::string name;
  std::string type;   // as the model says it: float, float32, double, float64, int, ...
  std::string units;
  int itemsize = 0;
  long long nbytes = 0;
  int grid = 0;
};

struct BmiGrid {
  int rank = 0;
  long long size = 0;
  std::vector<int> shape;        // slowest first: {rows, columns}
  std::vector<double> spacing;   // {dy, dx}
};

class BmiModel {
 public:
  virtual ~BmiModel() = default;
  virtual std::vector<std::string> output_names() = 0;
  virtual std::vector<std::string> input_names() = 0;
  virtual BmiVariable variable(const std::string& name) = 0;
  virtual BmiGrid grid(int id) = 0;
  virtual void update() = 0;
  virtual void get_value(const std::string& name, std::vector<std::byte>& bytes) = 0;
  virtual void set_value(const std::string& name, std::vector<std::byte>& bytes) = 0;
  // The name the model is shown by (a library's file name, a Python class's name).
  virtual const std::string& label() const = 0;
};

// How a run makes its outside model: a fresh instance initialised with a case's config file.
struct ExternalModel {
  std::string label;   // shown in check details and captions
  std::string origin;  // where it comes from, for the case's notes (a path and function, a class)
  std::function<std::unique_ptr<BmiModel>(const std::filesystem::path& config)> make;
};

}  // namespace gt
