// report.json read back into a Report; see compare/report/report_read.hpp.
#include "compare/report/report_read.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "compare/shards.hpp"
#include "core/errors.hpp"
#include "core/names.hpp"

namespace gt {
namespace {

using nlohmann::json;

Outcome outcome_of(const json& word) {
  const auto outcome = outcome_from_name(word.get<std::string>());
  if (!outcome) throw InputError(fmt::format("'{}' is not an outcome", word.get<std::string>()));
  return *outcome;
}

// A number written by number_or_null: null stands for a non-finite value spelled in `text`.
double number_of(const json& value, const std::string& text) {
  if (!value.is_null()) return value.get<double>();
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  return std::numeric_limits<double>::quiet_NaN();
}

std::optional<double> optional_number(const json& object, const char* key) {
  if (!object.contains(key)) return std::nullopt;
  return number_of(object[key], "nan");
}

Environment environment_from_json(const json& in) {
  Environment environment;
  environment.gl_renderer = in.value("gl_renderer", "");
  environment.gl_version = in.value("gl_version", "");
  environment.gl_platform = in.value("gl_platform", "");
  environment.cpu = in.value("cpu", "");
  environment.compiler = in.value("compiler", "");
  environment.build_type = in.value("build_type", "");
  environment.git = in.value("git", "");
  environment.mutant = in.value("mutant", "");
  environment.graded = in.value("graded", "");
  environment.calibration_ms = optional_number(in, "calibration_ms");
  environment.run_started = in.value("run_started", "");
  environment.command_line = in.value("command_line", "");
  environment.git_revision = in.value("git_revision", "");
  environment.git_dirty = in.value("git_dirty", false);
  environment.git_at_configure = in.value("git_at_configure", "");
  environment.build_flags = in.value("build_flags", "");
  environment.shaders = in.value("shaders", std::map<std::string, std::string>{});
  environment.data = in.value("data", std::map<std::string, std::string>{});
  return environment;
}

Check check_from_json(const json& in) {
  Check check;
  check.name = in.at("name").get<std::string>();
  check.value = number_of(in.at("value"), in.value("value_text", "nan"));
  check.threshold = optional_number(in, "threshold");
  check.loose_threshold = optional_number(in, "loose_threshold");
  check.status = outcome_of(in.at("status"));
  check.detail = in.value("detail", "");
  if (in.contains("expected")) {
    check.expected = outcome_of(in["expected"]);
    check.expectation = in.value("expectation", "");
  }
  return check;
}

Timings timings_from_json(const json& in) {
  Timings timings;
  timings.cpu_ms = optional_number(in, "cpu_ms");
  timings.gpu_ms = optional_number(in, "gpu_ms");
  timings.cpu_reps = in.value("cpu_reps", 0);
  timings.gpu_reps = in.value("gpu_reps", 0);
  return timings;
}

// A map's colour scale as report_json writes it; colours that are not RGB triples of numbers are
// left out (the bar is then drawn grey), so a hand-edited report cannot break the page.
ColourScale colour_scale_from_json(const json& in) {
  ColourScale scale{in.value("palette", ""), in.value("low", 0.0), in.value("high", 0.0), in.value("unit", ""), {}};
  const json colours = in.value("colours", json::array());
  for (const json& colour : colours) {
    if (!colour.is_array() || colour.size() != 3 || !colour[0].is_number() || !colour[1].is_number() ||
        !colour[2].is_number()) {
      return {scale.palette, scale.low, scale.high, scale.unit, {}};
    }
    // Clamped in double first: a channel beyond float's range would make the conversion undefined.
    const auto channel = [&](std::size_t c) { return static_cast<float>(std::clamp(colour[c].get<double>(), 0.0, 1.0)); };
    scale.colours.push_back({channel(0), channel(1), channel(2)});
  }
  return scale;
}

std::vector<Artifact> artifacts_from_json(const json& in) {
  std::vector<Artifact> artifacts;
  const json paths = in.value("artifacts", json::array());
  const json details = in.value("artifact_details", json::array());
  for (std::size_t index = 0; index < paths.size(); ++index) {
    Artifact artifact{paths[index].get<std::string>(), "image", ""};
    if (index < details.size()) {
      artifact.kind = details[index].value("kind", artifact.kind);
      artifact.caption = details[index].value("caption", "");
      if (const auto scale = details[index].find("scale"); scale != details[index].end() && scale->is_object()) {
        artifact.scale = colour_scale_from_json(*scale);
      }
      // A width that is not a positive finite number draws no scale bar (a hand-edited report).
      if (const auto width = details[index].find("width_m"); width != details[index].end() && width->is_number()) {
        artifact.width_m = map_width_m(1, width->get<double>());
      }
    }
    artifacts.push_back(std::move(artifact));
  }
  return artifacts;
}

std::vector<CaseResult::Attempt> attempts_from_json(const json& in) {
  std::vector<CaseResult::Attempt> attempts;
  for (const auto& entry : in) {
    attempts.push_back({outcome_of(entry.at("status")), entry.value("error", ""),
                        entry.value("failing_checks", std::vector<std::string>{})});
  }
  return attempts;
}

// A case name from a report: it becomes a folder's name when reports are merged, so it must be a
// dotted identifier as every case name groundtruth gives is ('..' or 'a/b' would name a path).
std::string case_name_of(const json& name) {
  const std::string text = name.get<std::string>();
  if (!is_dotted_identifier(text)) {
    throw InputError(fmt::format("case name '{}' is not a dotted identifier (lower-case letters, digits, '_' and "
                                 "single dots)",
                                 text.substr(0, 120)));
  }
  return text;
}

CaseResult case_from_json(const json& in) {
  CaseResult result;
  result.name = case_name_of(in.at("name"));
  result.algorithm = in.value("algorithm", "");
  result.input = in.value("input", "");
  result.notes = in.value("notes", std::vector<std::string>{});
  result.width = in.value("width", 0);
  result.height = in.value("height", 0);
  result.status = outcome_of(in.at("status"));
  result.expected_failure = in.value("expected_failure", "");
  result.params = in.value("params", json::object());
  for (const auto& check : in.value("checks", json::array())) result.checks.push_back(check_from_json(check));
  result.timings = timings_from_json(in.value("timings", json::object()));
  result.artifacts = artifacts_from_json(in);
  result.descriptors = in.value("descriptors", json());
  result.error = in.value("error", "");
  result.seconds = in.contains("seconds") ? number_of(in["seconds"], "nan") : 0.0;
  if (in.contains("expected_seconds")) result.expected_seconds = number_of(in["expected_seconds"], "nan");
  result.tier = in.value("tier", "");
  result.earlier_attempts = attempts_from_json(in.value("earlier_attempts", json::array()));
  result.known_flake = in.value("known_flake", "");
  return result;
}

// The shard record: 1 <= index <= count <= max_shard_count, as --shard accepts them.
ShardInfo shard_from_json(const json& in) {
  ShardInfo shard{in.at("index").get<int>(), in.at("count").get<int>(), {}, in.value("balanced_by", "")};
  if (shard.count < 1 || shard.count > max_shard_count || shard.index < 1 || shard.index > shard.count) {
    throw InputError(fmt::format("index {} of {} is not a shard (1 <= index <= count <= {})", shard.index, shard.count,
                                 max_shard_count));
  }
  for (const auto& name : in.at("selection")) shard.selection.push_back(case_name_of(name));
  return shard;
}

}  // namespace

Report report_from_json(const json& document) {
  Report report;
  std::string where = "environment";
  try {
    report.environment = environment_from_json(document.value("environment", json::object()));
    for (const auto& entry : document.at("cases")) {
      where = fmt::format("case {}", entry.value("name", "(unnamed)"));
      report.cases.push_back(case_from_json(entry));
    }
    where = "expectation_problems";
    report.expectation_problems = document.value("expectation_problems", std::vector<std::string>{});
    where = "shard";
    if (document.contains("shard")) report.shard = shard_from_json(document["shard"]);
    report.scope = document.value("scope", "");
  } catch (const json::exception& error) {
    throw InputError(fmt::format("report.json: {} is malformed: {}", where, error.what()));
  } catch (const InputError& error) {
    throw InputError(fmt::format("report.json: {}: {}", where, error.what()));
  }
  return report;
}

}  // namespace gt
