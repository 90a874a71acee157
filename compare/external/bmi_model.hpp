// One instance of an outside model behind the C Basic Model Interface (include/groundtruth/bmi.h):
// the library opened, its registration function called, the model initialised from a config file,
// and each BMI call checked (a BMI_FAILURE, a NULL member, a string not terminated within its
// buffer becomes an exception naming the function and the library).
//
// Inputs:  an ExternalImplementation and the path of the config file initialize() reads.
// Outputs: the model's variables and grids as it describes them; update(); whole-variable
//          get_value/set_value through byte buffers of get_var_nbytes.
// Throws:  InputError where the library, its registration function or a required BMI member is
//          missing (the user's setup); std::runtime_error where a call returns BMI_FAILURE.
// Lifetime: finalize() and dlclose on destruction. A model's state belongs in Bmi::data: a library
//          that keeps it in globals shares it between instances (dlopen returns one handle a path).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "compare/external/implementation.hpp"

struct Bmi;

namespace gt {

struct BmiVariable {
  std::string name;
  std::string type;   // as the model says it: float, float32, double, float64, int, ...
  std::string units;
  int itemsize = 0;
  int nbytes = 0;
  int grid = 0;
};

struct BmiGrid {
  int rank = 0;
  int size = 0;
  std::vector<int> shape;        // slowest first: {rows, columns}
  std::vector<double> spacing;   // {dy, dx}
};

class BmiModel {
 public:
  BmiModel(const ExternalImplementation& implementation, const std::filesystem::path& config);
  ~BmiModel();
  BmiModel(const BmiModel&) = delete;
  BmiModel& operator=(const BmiModel&) = delete;

  std::string component_name();  // empty where the model gives none
  std::vector<std::string> output_names();
  std::vector<std::string> input_names();
  BmiVariable variable(const std::string& name);
  BmiGrid grid(int id);
  void update();
  void get_value(const std::string& name, std::vector<std::byte>& bytes);
  void set_value(const std::string& name, std::vector<std::byte>& bytes);
  const std::string& label() const { return label_; }

 private:
  void check(int status, const char* function, const std::string& what = "");
  std::vector<std::string> names(int (*count)(Bmi*, int*), int (*list)(Bmi*, char**), const char* function);

  std::string label_;
  void* library_ = nullptr;
  std::unique_ptr<Bmi> model_;
  bool initialised_ = false;
};

}  // namespace gt
