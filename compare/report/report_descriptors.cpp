// The descriptor tables of the report (report_common.hpp): a case's table and the fidelity table,
// read back from CaseResult::descriptors (compare/case_descriptors.cpp writes it).
#include <algorithm>
#include <cmath>

#include "compare/case_descriptors.hpp"
#include "compare/report/report_common.hpp"

namespace gt::report_detail {

namespace {

using json = nlohmann::json;

// The terrains shown as columns, in this order, with their headings.
constexpr std::pair<const char*, const char*> terrain_columns[] = {
    {"before", "before"}, {"cpu", "after, CPU"}, {"gpu", "after, GPU"}};

// The value of the scalar whose `key` ("name" or "label") is `wanted`, in a terrain's descriptors.
std::optional<double> scalar_value(const json& terrain, const char* key, const std::string& wanted) {
  for (const auto& scalar : terrain.at("scalars")) {
    if (scalar.at(key) == wanted && scalar.at("value").is_number()) return scalar.at("value").get<double>();
  }
  return std::nullopt;
}

// Columns present in this case: its terrains, then the real DEM.
std::vector<std::pair<std::string, const json*>> present_columns(const json& descriptors) {
  std::vector<std::pair<std::string, const json*>> columns;
  for (const auto& [key, heading] : terrain_columns) {
    if (descriptors["terrains"].contains(key)) columns.emplace_back(heading, &descriptors["terrains"][key]);
  }
  if (descriptors.contains("real")) {
    columns.emplace_back(descriptors["real"]["name"].get<std::string>(), &descriptors["real"]["descriptors"]);
  }
  return columns;
}

void add_rows_of(const json& terrain, DescriptorTable& table) {
  for (const auto& scalar : terrain.at("scalars")) {
    const std::string label = scalar.at("label");
    const bool known = std::any_of(table.rows.begin(), table.rows.end(),
                                   [&](const DescriptorTable::Row& row) { return row.label == label; });
    if (!known) table.rows.push_back({label, scalar.at("unit"), {}});
  }
}

}  // namespace

std::optional<DescriptorTable> descriptor_table(const CaseResult& result) {
  if (result.descriptors.is_null()) return std::nullopt;
  const auto columns = present_columns(result.descriptors);
  DescriptorTable table;
  for (const auto& [heading, terrain] : columns) {
    table.columns.push_back(heading);
    add_rows_of(*terrain, table);
  }
  for (auto& row : table.rows) {
    for (const auto& column : columns) row.values.push_back(scalar_value(*column.second, "label", row.label));
  }
  return table;
}

std::optional<FidelityTable> fidelity_table(const Report& report) {
  // Scale-free descriptors only: slopes, curvatures and drainage density depend on the cell size,
  // and the generated terrain (1 m cells) and the real DEM (about 90 m) do not share one.
  std::vector<std::string> names{"hypsometric_integral"};
  FidelityTable table;
  table.targets.push_back(std::nullopt);
  for (const auto& target : fidelity_targets()) {
    names.push_back(target.descriptor);
    table.targets.push_back(target);
  }
  table.descriptors = names;
  table.labels = names;
  for (const auto& result : report.cases) {
    const auto& descriptors = result.descriptors;
    if (descriptors.is_null() || !descriptors.value("fidelity", false) || !descriptors.contains("real")) continue;
    const auto& terrains = descriptors["terrains"];
    if (!terrains.contains("before") || !terrains.contains("cpu")) continue;
    const auto& real = descriptors["real"]["descriptors"];
    for (std::size_t index = 0; index < names.size(); ++index) {
      for (const auto& scalar : real.at("scalars")) {
        if (scalar.at("name") == names[index]) table.labels[index] = scalar.at("label");
      }
    }
    table.real_name = descriptors["real"]["name"];
    table.real.clear();
    FidelityTable::Row row{result.name, result.algorithm, {}};
    for (const auto& name : names) {
      const auto before = scalar_value(terrains["before"], "name", name);
      const auto after = scalar_value(terrains["cpu"], "name", name);
      const auto target = scalar_value(real, "name", name);
      table.real.push_back(target);
      if (!before || !after) {
        row.cells.push_back(std::nullopt);
        continue;
      }
      FidelityTable::Cell cell{*before, *after, std::nullopt};
      if (target && *before != *target) {
        cell.moved = (std::abs(*before - *target) - std::abs(*after - *target)) / std::abs(*before - *target);
      }
      row.cells.push_back(cell);
    }
    table.rows.push_back(row);
  }
  if (table.rows.empty()) return std::nullopt;
  return table;
}

}  // namespace gt::report_detail
