// The BMI config file of one case; see bmi_config.hpp.
#include "compare/external/bmi_config.hpp"

#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace gt {
namespace {

std::string config_value(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) return fmt::format("{:.17g}", value.get<double>());
  return value.dump();
}

}  // namespace

void write_bmi_config(const std::filesystem::path& path, const std::string& algorithm, const std::string& case_name,
                      const StateGrid& grid, const nlohmann::json& params) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  out << "# groundtruth: one case for a model behind the Basic Model Interface (docs/external-implementations.md)\n";
  out << fmt::format("algorithm {}\ncase {}\n", algorithm, case_name);
  out << fmt::format("rows {}\ncolumns {}\n", grid.height, grid.width);
  out << fmt::format("spacing_y {:.17g}\nspacing_x {:.17g}\nhorizontal_unit {}\n", grid.cell_size_y, grid.cell_size_x,
                     grid.horizontal_unit);
  for (const auto& [name, value] : params.items()) out << name << ' ' << config_value(value) << '\n';
  out.close();
  if (!out) throw std::runtime_error(fmt::format("could not write the BMI config {}", path.string()));
}

}  // namespace gt
