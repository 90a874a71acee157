// Loading and selecting case files; see compare/cases.hpp for the format.
#include "compare/cases.hpp"

#include <algorithm>
#include <fnmatch.h>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/io/text_file.hpp"
#include "core/json_keys.hpp"
#include "core/names.hpp"

namespace gt {
namespace {

const std::vector<std::string> known_case_keys = {"name",   "algorithm",   "params", "input", "crop",
                                                  "expect", "description", "ab",     "tier"};

std::vector<std::filesystem::path> case_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  }
  if (error) throw InputError(fmt::format("cannot read the case folder {}: {}", folder.string(), error.message()));
  std::sort(files.begin(), files.end());
  return files;
}

Tier tier_of(const nlohmann::json& entry, const std::string& where) {
  if (!entry.contains("tier")) return Tier::report;
  for (const Tier tier : {Tier::quick, Tier::report, Tier::full}) {
    if (entry["tier"] == tier_name(tier)) return tier;
  }
  throw InputError(fmt::format("{}: \"tier\" must be \"quick\", \"report\" or \"full\", not {}", where,
                               entry["tier"].dump()));
}

}  // namespace

const char* tier_name(Tier tier) {
  return tier == Tier::quick ? "quick" : tier == Tier::report ? "report" : "full";
}

std::vector<CaseSpec> cases_in_tier(const std::vector<CaseSpec>& cases, Tier tier) {
  std::vector<CaseSpec> kept;
  std::copy_if(cases.begin(), cases.end(), std::back_inserter(kept), [&](const CaseSpec& spec) { return spec.tier <= tier; });
  return kept;
}

std::string case_name_part(const std::string& text) {
  std::string part;
  for (const char c : text) {
    const char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    const bool allowed = (lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9');
    part += allowed ? lower : '_';
  }
  return part.empty() ? "input" : part.substr(0, 100);
}

namespace {

CaseSpec single_case_from_json(const nlohmann::json& entry, const std::string& origin) {
  if (!entry.is_object()) throw InputError(fmt::format("{}: a case must be a JSON object", origin));
  const std::string where =
      entry.contains("name") && entry["name"].is_string() ? fmt::format("{}: case {}", origin, entry["name"].get<std::string>()) : origin;
  require_known_keys(entry, known_case_keys, where);
  if (!entry.contains("name") || !entry["name"].is_string() || !entry.contains("algorithm") ||
      !entry["algorithm"].is_string() || (entry.contains("input") && !entry["input"].is_object())) {
    throw InputError(fmt::format("{}: a case needs string 'name', string 'algorithm' and, when it has one, "
                                 "an object 'input'",
                                 origin));
  }
  CaseSpec spec;
  spec.name = entry["name"].get<std::string>();
  if (!is_dotted_identifier(spec.name)) {
    throw InputError(fmt::format("{}: case name '{}' must be a dotted identifier of lower-case letters, digits and "
                                 "'_' (it names the case's folder in the report)",
                                 origin, spec.name));
  }
  spec.algorithm = entry["algorithm"].get<std::string>();
  spec.params = entry.value("params", nlohmann::json::object());
  spec.input = entry.value("input", nlohmann::json::object());
  spec.crop = entry.value("crop", nlohmann::json());
  spec.expect = entry.value("expect", nlohmann::json());
  spec.origin = origin;
  spec.tier = tier_of(entry, where);
  return spec;
}

// The A and B cases of an entry's "ab" pair (see cases.hpp).
std::vector<CaseSpec> ab_cases(const CaseSpec& base, const nlohmann::json& pair) {
  const std::string where = fmt::format("{}: case {}", base.origin, base.name);
  if (!pair.is_object() || pair.size() != 2 || !pair.contains("a") || !pair.contains("b") || !pair["a"].is_object() ||
      !pair["b"].is_object()) {
    throw InputError(fmt::format("{}: \"ab\" must be {{\"a\": {{parameters}}, \"b\": {{parameters}}}}", where));
  }
  if (pair["a"] == pair["b"]) throw InputError(fmt::format("{}: A and B are the same variant", where));
  std::vector<CaseSpec> sides;
  for (const char* side : {"a", "b"}) {
    CaseSpec spec = base;
    for (const auto& [name, value] : pair[side].items()) {
      if (spec.params.contains(name)) {
        throw InputError(fmt::format("{}: {} is set both in \"params\" and in \"ab\": choose one", where, name));
      }
      spec.params[name] = value;
    }
    spec.name = base.name + "." + side;
    spec.ab_pair = base.name;
    spec.ab_side = side;
    spec.ab_params = pair[side];
    sides.push_back(std::move(spec));
  }
  return sides;
}

}  // namespace

std::vector<CaseSpec> cases_from_json(const nlohmann::json& entry, const std::string& origin) {
  const CaseSpec spec = single_case_from_json(entry, origin);
  if (!entry.contains("ab")) return {spec};
  return ab_cases(spec, entry["ab"]);
}

std::vector<CaseSpec> load_cases(const std::filesystem::path& folder) { return load_suite(folder, {}); }

namespace {

// A user's case file (--cases) names its inputs relative to itself, so that a suite kept beside
// the user's code runs from any working directory; absolute paths stay as they are.
void anchor_inputs_at(CaseSpec& spec, const std::filesystem::path& case_folder) {
  for (const char* key : {"file", "mesh", "volume", "global_grid"}) {
    if (!spec.input.is_object() || !spec.input.contains(key) || !spec.input[key].is_string()) continue;
    const std::filesystem::path path = spec.input[key].get<std::string>();
    if (path.is_relative()) spec.input[key] = (case_folder / path).lexically_normal().string();
  }
}

}  // namespace

std::vector<CaseSpec> load_suite(const std::filesystem::path& folder, const std::vector<std::filesystem::path>& extra) {
  std::vector<CaseSpec> cases;
  std::set<std::string> names;
  auto files = case_files(folder);
  const std::size_t bundled_files = files.size();
  for (const auto& path : extra) {
    if (std::filesystem::is_directory(path)) {
      for (const auto& file : case_files(path)) files.push_back(file);
    } else if (std::filesystem::is_regular_file(path)) {
      files.push_back(path);
    } else {
      throw InputError(fmt::format("--cases {}: no such case file or folder", path.string()));
    }
  }
  for (std::size_t index = 0; index < files.size(); ++index) {
    const auto& file = files[index];
    std::istringstream stream(read_text_file(file, json_document_limits, "case file"));
    nlohmann::json document;
    try {
      document = parse_json_bounded(stream, file.string());
    } catch (const nlohmann::json::exception& error) {
      throw InputError(fmt::format("{}: not valid JSON: {}", file.string(), error.what()));
    }
    if (!document.is_array()) throw InputError(fmt::format("{}: expected an array of cases", file.string()));
    for (const auto& entry : document) {
      for (auto& spec : cases_from_json(entry, file.filename().string())) {
        if (index >= bundled_files) anchor_inputs_at(spec, std::filesystem::absolute(file).parent_path());
        if (!names.insert(spec.name).second) {
          throw InputError(fmt::format("{}: case name '{}' is used twice", file.string(), spec.name));
        }
        cases.push_back(std::move(spec));
      }
    }
  }
  return cases;
}

bool named_by_any(const std::vector<std::string>& patterns, const std::string& name) {
  return patterns.empty() || std::any_of(patterns.begin(), patterns.end(), [&](const std::string& pattern) {
           return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
         });
}

std::vector<CaseSpec> select_cases(const std::vector<CaseSpec>& cases, const std::vector<std::string>& patterns) {
  std::vector<CaseSpec> selected;
  for (const auto& pattern : patterns) {
    const auto before = selected.size();
    for (const auto& spec : cases) {
      const bool already = std::any_of(selected.begin(), selected.end(),
                                       [&](const CaseSpec& chosen) { return chosen.name == spec.name; });
      if (!already && fnmatch(pattern.c_str(), spec.name.c_str(), 0) == 0) selected.push_back(spec);
    }
    if (selected.size() == before && std::none_of(cases.begin(), cases.end(), [&](const CaseSpec& spec) {
          return fnmatch(pattern.c_str(), spec.name.c_str(), 0) == 0;
        })) {
      throw InputError(fmt::format("no case matches '{}'; `groundtruth list` shows the case names", pattern));
    }
  }
  return selected;
}

}  // namespace gt
