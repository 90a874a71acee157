// The C Basic Model Interface driven from C++; see c_bmi_model.hpp.
#include "compare/external/c_bmi_model.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "groundtruth/bmi.h"

namespace gt {
namespace {

// A model's variable list is read into buffers we allocate: more names than this is refused.
constexpr int most_variables = 1024;

// A string the model wrote into a buffer of `size` chars, refused when it left it unterminated.
std::string bounded_string(const std::vector<char>& buffer, const char* function, const std::string& label) {
  const auto end = std::find(buffer.begin(), buffer.end(), '\0');
  if (end == buffer.end()) {
    throw std::runtime_error(fmt::format("{}: {} wrote a string of {} chars or more without its terminating NUL",
                                         label, function, buffer.size()));
  }
  return {buffer.begin(), end};
}

// The members groundtruth calls: a NULL one is refused when the model is registered.
struct Required {
  const char* name;
  bool set;
};

std::vector<Required> required_members(const Bmi& bmi) {
  return {{"initialize", bmi.initialize != nullptr},
          {"update", bmi.update != nullptr},
          {"finalize", bmi.finalize != nullptr},
          {"get_input_item_count", bmi.get_input_item_count != nullptr},
          {"get_output_item_count", bmi.get_output_item_count != nullptr},
          {"get_input_var_names", bmi.get_input_var_names != nullptr},
          {"get_output_var_names", bmi.get_output_var_names != nullptr},
          {"get_var_grid", bmi.get_var_grid != nullptr},
          {"get_var_type", bmi.get_var_type != nullptr},
          {"get_var_units", bmi.get_var_units != nullptr},
          {"get_var_itemsize", bmi.get_var_itemsize != nullptr},
          {"get_var_nbytes", bmi.get_var_nbytes != nullptr},
          {"get_grid_rank", bmi.get_grid_rank != nullptr},
          {"get_grid_size", bmi.get_grid_size != nullptr},
          {"get_grid_shape", bmi.get_grid_shape != nullptr},
          {"get_grid_spacing", bmi.get_grid_spacing != nullptr},
          {"get_value", bmi.get_value != nullptr},
          {"set_value", bmi.set_value != nullptr}};
}

}  // namespace

ExternalImplementation parse_implementation(const std::string& text) {
  ExternalImplementation implementation;
  const auto colon = text.rfind(':');
  const std::string library = colon == std::string::npos ? text : text.substr(0, colon);
  if (colon != std::string::npos) implementation.register_symbol = text.substr(colon + 1);
  if (library.empty()) throw InputError(fmt::format("--implementation '{}': no library named before the ':'", text));
  if (implementation.register_symbol.empty()) {
    throw InputError(fmt::format("--implementation '{}': no registration function named after the ':'", text));
  }
  implementation.library = std::filesystem::absolute(library);
  return implementation;
}

CBmiModel::CBmiModel(const ExternalImplementation& implementation, const std::filesystem::path& config)
    : label_(implementation.label()), model_(std::make_unique<Bmi>()) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(implementation.library, error)) {
    throw InputError(fmt::format("--implementation {}: no such file", implementation.library.string()));
  }
  library_ = dlopen(implementation.library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library_ == nullptr) {
    throw InputError(fmt::format("--implementation {}: not a shared library this process can load: {}",
                                 implementation.library.string(), dlerror()));
  }
  void* symbol = dlsym(library_, implementation.register_symbol.c_str());
  if (symbol == nullptr) {
    dlclose(library_);
    throw InputError(fmt::format("--implementation {}: no function '{}' in it (name the registration function that "
                                 "fills the Bmi struct: LIBRARY:FUNCTION; include/groundtruth/bmi.h)",
                                 implementation.library.string(), implementation.register_symbol));
  }
  std::memset(model_.get(), 0, sizeof(Bmi));
  const auto register_model = reinterpret_cast<BmiRegisterFunction>(symbol);
  if (register_model(model_.get()) == nullptr) {
    dlclose(library_);
    throw InputError(fmt::format("{}: {} returned NULL: the model refused to register", label_,
                                 implementation.register_symbol));
  }
  std::vector<std::string> missing;
  for (const Required& member : required_members(*model_)) {
    if (!member.set) missing.emplace_back(member.name);
  }
  if (!missing.empty()) {
    dlclose(library_);
    throw InputError(fmt::format("{}: {} left these BMI functions NULL, which groundtruth calls: {}", label_,
                                 implementation.register_symbol, fmt::join(missing, ", ")));
  }
  const std::string config_text = config.string();
  check(model_->initialize(model_.get(), config_text.c_str()), "initialize", config_text);
  initialised_ = true;
}

CBmiModel::~CBmiModel() {
  if (initialised_) model_->finalize(model_.get());
  if (library_ != nullptr) dlclose(library_);
}

void CBmiModel::check(int status, const char* function, const std::string& what) {
  if (status == BMI_SUCCESS) return;
  throw std::runtime_error(fmt::format("{}: {}({}) returned {} (BMI_FAILURE is {})", label_, function, what, status,
                                       BMI_FAILURE));
}

std::vector<std::string> CBmiModel::names(int (*count_of)(Bmi*, int*), int (*list)(Bmi*, char**), const char* function) {
  int count = 0;
  check(count_of(model_.get(), &count), function);
  if (count < 0 || count > most_variables) {
    throw std::runtime_error(fmt::format("{}: {} says {} variables (0 to {} are read)", label_, function, count,
                                         most_variables));
  }
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(count), std::vector<char>(BMI_MAX_VAR_NAME, '\0'));
  std::vector<char*> pointers;
  for (auto& buffer : buffers) pointers.push_back(buffer.data());
  if (count > 0) check(list(model_.get(), pointers.data()), function);
  std::vector<std::string> names;
  for (const auto& buffer : buffers) names.push_back(bounded_string(buffer, function, label_));
  return names;
}

std::vector<std::string> CBmiModel::output_names() {
  return names(model_->get_output_item_count, model_->get_output_var_names, "get_output_var_names");
}

std::vector<std::string> CBmiModel::input_names() {
  return names(model_->get_input_item_count, model_->get_input_var_names, "get_input_var_names");
}

BmiVariable CBmiModel::variable(const std::string& name) {
  BmiVariable variable{.name = name};
  std::vector<char> text(std::max(BMI_MAX_TYPE_NAME, BMI_MAX_UNITS_NAME), '\0');
  check(model_->get_var_type(model_.get(), name.c_str(), text.data()), "get_var_type", name);
  variable.type = bounded_string(text, "get_var_type", label_);
  std::fill(text.begin(), text.end(), '\0');
  check(model_->get_var_units(model_.get(), name.c_str(), text.data()), "get_var_units", name);
  variable.units = bounded_string(text, "get_var_units", label_);
  check(model_->get_var_itemsize(model_.get(), name.c_str(), &variable.itemsize), "get_var_itemsize", name);
  int nbytes = 0;
  check(model_->get_var_nbytes(model_.get(), name.c_str(), &nbytes), "get_var_nbytes", name);
  variable.nbytes = nbytes;
  check(model_->get_var_grid(model_.get(), name.c_str(), &variable.grid), "get_var_grid", name);
  return variable;
}

BmiGrid CBmiModel::grid(int id) {
  constexpr int most_dimensions = 8;
  BmiGrid grid;
  check(model_->get_grid_rank(model_.get(), id, &grid.rank), "get_grid_rank", std::to_string(id));
  if (grid.rank < 1 || grid.rank > most_dimensions) {
    throw std::runtime_error(fmt::format("{}: get_grid_rank({}) says rank {} (1 to {} are read)", label_, id, grid.rank,
                                         most_dimensions));
  }
  int size = 0;
  check(model_->get_grid_size(model_.get(), id, &size), "get_grid_size", std::to_string(id));
  grid.size = size;
  grid.shape.assign(static_cast<std::size_t>(grid.rank), 0);
  grid.spacing.assign(static_cast<std::size_t>(grid.rank), 0.0);
  check(model_->get_grid_shape(model_.get(), id, grid.shape.data()), "get_grid_shape", std::to_string(id));
  check(model_->get_grid_spacing(model_.get(), id, grid.spacing.data()), "get_grid_spacing", std::to_string(id));
  return grid;
}

void CBmiModel::update() { check(model_->update(model_.get()), "update"); }

void CBmiModel::get_value(const std::string& name, std::vector<std::byte>& bytes) {
  check(model_->get_value(model_.get(), name.c_str(), bytes.data()), "get_value", name);
}

void CBmiModel::set_value(const std::string& name, std::vector<std::byte>& bytes) {
  check(model_->set_value(model_.get(), name.c_str(), bytes.data()), "set_value", name);
}

ExternalModel c_bmi_external_model(const ExternalImplementation& implementation) {
  return {.label = implementation.label(),
          .origin = fmt::format("{}, registered by {}", implementation.library.string(), implementation.register_symbol),
          .make = [implementation](const std::filesystem::path& config) -> std::unique_ptr<BmiModel> {
            return std::make_unique<CBmiModel>(implementation, config);
          }};
}

}  // namespace gt
