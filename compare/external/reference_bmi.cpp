// A stepped algorithm's reference behind the BMI; see reference_bmi.hpp.
#include "compare/external/reference_bmi.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/algorithm.hpp"
#include "core/errors.hpp"
#include "core/io/text_file.hpp"

namespace gt {
namespace {

struct Config {
  int rows = 0;
  int columns = 0;
  double spacing_y = 1.0;
  double spacing_x = 1.0;
  std::string horizontal_unit = "m";
  std::vector<std::pair<std::string, std::string>> params;  // name, text as --set takes it
};

Config read_config(const std::filesystem::path& path) {
  std::istringstream in(read_text_file(path, hand_written_limits, "BMI config"));
  Config config;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    const auto space = line.find(' ');
    if (space == std::string::npos) continue;
    const std::string key = line.substr(0, space), value = line.substr(space + 1);
    if (key == "rows") config.rows = std::stoi(value);
    else if (key == "columns") config.columns = std::stoi(value);
    else if (key == "spacing_y") config.spacing_y = std::stod(value);
    else if (key == "spacing_x") config.spacing_x = std::stod(value);
    else if (key == "horizontal_unit") config.horizontal_unit = value;
    else if (key != "algorithm" && key != "case") config.params.emplace_back(key, value);
  }
  if (config.rows < 1 || config.columns < 1) {
    throw InputError(fmt::format("BMI config {}: rows and columns must be given and positive", path.string()));
  }
  return config;
}

}  // namespace

ReferenceBmi::ReferenceBmi(std::string algorithm, bool double_precision)
    : algorithm_(std::move(algorithm)), double_precision_(double_precision) {
  if (find_algorithm(algorithm_).kind != CaseKind::stepped) {
    throw InputError(fmt::format("{} is not a stepped algorithm: it has no state to step through the BMI", algorithm_));
  }
}

void ReferenceBmi::initialize(const std::filesystem::path& config_file) {
  const Config config = read_config(config_file);
  const Algorithm& algorithm = find_algorithm(algorithm_);
  LoadedInput input;
  input.heights = Heightmap(config.columns, config.rows, 0.0);
  input.heights.cell_size_x = config.spacing_x;
  input.heights.cell_size_y = config.spacing_y;
  input.heights.horizontal_unit = config.horizontal_unit;
  input.description = "a flat grid of the BMI config's size";
  nlohmann::json given = nlohmann::json::object();
  for (const auto& [name, text] : config.params) given[name] = parse_param_text(algorithm_, *algorithm.params, name, text);
  const nlohmann::json resolved = resolve_params(algorithm_, *algorithm.params, given);
  PreparedTwin prepared = algorithm.prepare(resolved, input);
  auto& twin = std::get<SteppedTwin>(prepared.kind);
  fields_ = twin.fields;
  state_ = twin.initial;
  stepper_ = double_precision_ ? twin.reference_double() : twin.reference_float();
  iteration_ = 0;
  stepper_->set_state(state_, iteration_);
  stepped_ = false;
}

void ReferenceBmi::require_initialised() const {
  if (!stepper_) throw std::logic_error(fmt::format("{} reference: initialize() first", algorithm_));
}

void ReferenceBmi::sync_state() {
  if (!stepped_) return;
  state_ = stepper_->get_state();
  stepped_ = false;
}

void ReferenceBmi::update() {
  require_initialised();
  stepper_->update(1);
  ++iteration_;
  stepped_ = true;
}

std::vector<std::string> ReferenceBmi::output_names() const {
  std::vector<std::string> names;
  for (const FieldDecl& field : fields_) names.push_back(field.name);
  return names;
}

std::vector<std::string> ReferenceBmi::input_names() const {
  auto names = output_names();
  names.emplace_back("iteration");
  return names;
}

const FieldDecl& ReferenceBmi::field(const std::string& name) const {
  for (const FieldDecl& field : fields_) {
    if (field.name == name) return field;
  }
  throw std::out_of_range(fmt::format("{} has no variable '{}'", algorithm_, name));
}

std::vector<double> ReferenceBmi::get(const std::string& name) {
  require_initialised();
  sync_state();
  const auto index = static_cast<std::size_t>(&field(name) - fields_.data());
  return state_.fields[index];
}

void ReferenceBmi::set(const std::string& name, const std::vector<double>& values) {
  require_initialised();
  sync_state();
  const auto index = static_cast<std::size_t>(&field(name) - fields_.data());
  if (values.size() != state_.fields[index].size()) {
    throw std::invalid_argument(fmt::format("{}: {} values for '{}', which holds {}", algorithm_, values.size(), name,
                                            state_.fields[index].size()));
  }
  state_.fields[index] = values;
  stepper_->set_state(state_, iteration_);
}

void ReferenceBmi::set_iteration(int iteration) {
  require_initialised();
  sync_state();
  iteration_ = iteration;
  stepper_->set_state(state_, iteration_);
}

}  // namespace gt
