// An outside model from a shared library with the C Basic Model Interface (include/groundtruth/bmi.h):
// the library opened, its registration function called, the model initialised from a config file,
// and each BMI call checked (a BMI_FAILURE, a NULL member, a string not terminated within its
// buffer becomes an exception naming the function and the library).
//
// Inputs:  an ExternalImplementation and the path of the config file initialize() reads.
// Outputs: compare/external/bmi_model.hpp's BmiModel.
// Throws:  InputError where the library, its registration function or a required BMI member is
//          missing (the user's setup); std::runtime_error where a call returns BMI_FAILURE.
// Lifetime: finalize() and dlclose on destruction. A model's state belongs in Bmi::data: a library
//          that keeps it in globals shares it between instances (dlopen returns one handle a path).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compare/external/bmi_model.hpp"
#include "compare/external/implementation.hpp"

struct Bmi;

namespace gt {

class CBmiModel : public BmiModel {
 public:
  CBmiModel(const ExternalImplementation& implementation, const std::filesystem::path& config);
  ~CBmiModel() override;
  CBmiModel(const CBmiModel&) = delete;
  CBmiModel& operator=(const CBmiModel&) = delete;

  std::vector<std::string> output_names() override;
  std::vector<std::string> input_names() override;
  BmiVariable variable(const std::string& name) override;
  BmiGrid grid(int id) override;
  void update() override;
  void get_value(const std::string& name, std::vector<std::byte>& bytes) override;
  void set_value(const std::string& name, std::vector<std::byte>& bytes) override;
  const std::string& label() const override { return label_; }

 private:
  void check(int status, const char* function, const std::string& what = "");
  std::vector<std::string> names(int (*count)(Bmi*, int*), int (*list)(Bmi*, char**), const char* function);

  std::string label_;
  void* library_ = nullptr;
  std::unique_ptr<Bmi> model_;
  bool initialised_ = false;
};

// The run's ExternalModel for a library (--implementation).
ExternalModel c_bmi_external_model(const ExternalImplementation& implementation);

}  // namespace gt
