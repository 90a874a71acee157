// An outside model behind the C BMI as a stepper; see bmi.hpp.
#include "compare/steppers/bmi.hpp"

#include <cstdint>
#include <cstring>
#include <limits>

namespace gt {
namespace {

template <class Real>
void pack(const std::vector<double>& values, const StateGrid& grid, int components, std::vector<std::byte>& bytes) {
  bytes.resize(values.size() * sizeof(Real));
  for (std::size_t i = 0; i < values.size(); ++i) {
    const bool valid = grid.is_valid(i / static_cast<std::size_t>(components));
    const Real value = valid ? static_cast<Real>(values[i]) : std::numeric_limits<Real>::quiet_NaN();
    std::memcpy(bytes.data() + i * sizeof(Real), &value, sizeof(Real));
  }
}

template <class Real>
std::vector<double> unpack(const std::vector<std::byte>& bytes, std::size_t count) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    Real value;
    std::memcpy(&value, bytes.data() + i * sizeof(Real), sizeof(Real));
    values[i] = value;
  }
  return values;
}

}  // namespace

BmiStepper::BmiStepper(std::unique_ptr<BmiModel> model, StateDecl decl, StateGrid grid, const std::string& algorithm)
    : model_(std::move(model)), decl_(std::move(decl)), grid_(std::move(grid)) {
  layout_ = check_bmi_conformance(*model_, decl_, grid_, algorithm);
}

void BmiStepper::set_state(const State& state, int done) {
  check_state_shape(decl_, state, model_->label() + " state");
  for (std::size_t f = 0; f < decl_.size(); ++f) {
    if (layout_.double_precision) {
      pack<double>(state.fields[f], grid_, decl_[f].components, buffer_);
    } else {
      pack<float>(state.fields[f], grid_, decl_[f].components, buffer_);
    }
    model_->set_value(decl_[f].name, buffer_);
  }
  if (layout_.takes_iteration) {
    const std::int32_t iteration = done;
    buffer_.resize(sizeof iteration);
    std::memcpy(buffer_.data(), &iteration, sizeof iteration);
    model_->set_value(bmi_iteration_variable, buffer_);
  }
}

void BmiStepper::update(int count) {
  for (int k = 0; k < count; ++k) model_->update();
}

State BmiStepper::get_state() {
  State state{.grid = grid_, .fields = {}};
  const std::size_t item = layout_.double_precision ? sizeof(double) : sizeof(float);
  for (const FieldDecl& field : decl_) {
    const std::size_t count = grid_.cells() * static_cast<std::size_t>(field.components);
    buffer_.assign(count * item, std::byte{0});
    model_->get_value(field.name, buffer_);
    state.fields.push_back(layout_.double_precision ? unpack<double>(buffer_, count) : unpack<float>(buffer_, count));
  }
  return state;
}

}  // namespace gt
