#include "compare/specificity.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "compare/algorithm.hpp"
#include "compare/cases.hpp"
#include "compare/report/report_common.hpp"
#include "compare/sweep.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/rng.hpp"

namespace gt {
namespace {

using report_detail::case_anchor;
using report_detail::escape_markup;

// One parameter's plausible values: a real or integer interval (log-uniform when `logarithmic`),
// or choices drawn alike. `clears`: parameters left at their defaults when this one is drawn other
// than "0" (settings the algorithm refuses beside it); `needs`: a parameter drawn before it without
// which it is left at its default (drawn "0": a setting the algorithm refuses alone).
struct Plausible {
  std::string parameter;
  double low = 0.0;
  double high = 0.0;
  bool logarithmic = false;
  std::vector<std::string> choices;  // non-empty: one of these
  std::vector<std::string> clears = {};
  std::string needs = {};
};

struct SpecificityAlgorithm {
  std::string algorithm;
  std::vector<Plausible> parameters;
};

Plausible linear(std::string name, double low, double high) { return {std::move(name), low, high, false, {}}; }
Plausible logarithmic(std::string name, double low, double high) { return {std::move(name), low, high, true, {}}; }
Plausible one_of(std::string name, std::vector<std::string> choices) { return {std::move(name), 0, 0, false, std::move(choices)}; }
Plausible clearing(Plausible plausible, std::vector<std::string> cleared) {
  plausible.clears = std::move(cleared);
  return plausible;
}
Plausible needing(std::string needed, Plausible plausible) {
  plausible.needs = std::move(needed);
  return plausible;
}

// The plausible sub-ranges: what a user sets on purpose, each inside the declared range. Left out:
// settings the algorithm refuses in combination (droplets' disjoint ordering needs a spacing
// beyond twice the lifetime) and those that only draw pictures; where one setting refuses others
// (Šťava's layers beside regolith and the thermal step) it clears them. New parameters go last, so
// the draws of those before them stay what they were.
const std::vector<SpecificityAlgorithm>& plausible_table() {
  static const std::vector<SpecificityAlgorithm> table = {
      {"erosion.thermal",
       {linear("iterations", 20, 200), linear("talus_angle", 10, 60), linear("strength", 0.2, 1.5),
        one_of("neighbourhood", {"cardinal", "diagonal", "alternating"})}},
      {"erosion.thermal_jako", {linear("iterations", 20, 200), linear("talus_angle", 10, 60), linear("rate", 0.1, 0.9)}},
      {"erosion.dissolution",
       {linear("iterations", 20, 200), logarithmic("rain", 1e-3, 0.05), linear("evaporation", 0.0, 0.2),
        logarithmic("evaporation_threshold", 1e-6, 1e-3), logarithmic("saturation", 0.01, 0.3),
        linear("dissolution_rate", 0.2, 1.0), linear("deposition_rate", 0.2, 1.0)}},
      {"erosion.pipe",
       {linear("steps", 50, 300), logarithmic("time_step", 0.005, 0.05), logarithmic("rain_rate", 1e-5, 2e-3),
        logarithmic("evaporation_rate", 1e-4, 0.1), logarithmic("capacity", 0.01, 1.0),
        linear("dissolving_rate", 0.1, 2.0), linear("deposition_rate", 0.1, 2.0), one_of("pipes", {"4", "8"}),
        one_of("transport", {"flux", "semi_lagrangian"}), one_of("boundary", {"closed", "open"}),
        linear("sediment_diffusion", 0.0, 0.1), linear("regolith_depth", 0.0, 0.05),
        logarithmic("initial_depth", 0.01, 0.5), one_of("thermal_step", {"false", "true"}),
        clearing(one_of("layers", {"0", "0", "1", "2", "3"}), {"regolith_depth", "thermal_step"}),
        logarithmic("layer_capacity_1", 0.01, 1.0), logarithmic("layer_capacity_2", 0.01, 1.0),
        logarithmic("layer_capacity_3", 0.01, 1.0), logarithmic("layer_thickness_1", 1e-3, 0.5),
        logarithmic("layer_thickness_2", 1e-3, 0.5), logarithmic("layer_thickness_3", 1e-3, 0.5),
        needing("layers", one_of("layer_erosion", {"capacity_above_sediment", "capacity_above_sediment",
                                                   "capacity_above_sediment", "as_printed"}))}},
      {"erosion.particle",
       {linear("iterations", 2, 10), linear("lifetime", 10, 60), linear("erosion_strength", 0.05, 0.4),
        linear("deposition_strength", 0.05, 0.4), linear("drag", 0.05, 0.5), logarithmic("capacity_factor", 1e-3, 0.05),
        one_of("ordering", {"batch", "race"})}},
      {"erosion.beyer",
       {linear("iterations", 2, 10), linear("lifetime", 10, 40), linear("inertia", 0.0, 0.5),
        linear("capacity_factor", 1.0, 8.0), linear("deposition", 0.1, 0.5), linear("erosion", 0.1, 0.5),
        linear("evaporation", 0.005, 0.05), linear("radius", 1.0, 4.0), one_of("ordering", {"batch", "race"}),
        one_of("speed_rule", {"physical", "printed"})}},
      {"erosion.layered",
       {linear("steps", 20, 100), linear("time_step", 0.05, 0.2), logarithmic("creep_rate", 1e-3, 0.05),
        one_of("talus_random", {"false", "true"}), linear("initial_water", 0.0, 0.3), one_of("soil", {"loam", "sand", "scree"}),
        linear("vegetation", 0.0, 0.5)}},
  };
  return table;
}

// The two real inputs every set runs on: a volcano (87 x 61, 10 m cells) and a coast with its sea
// floor (120 x 91, negative heights).
const std::vector<std::string>& specificity_inputs() {
  static const std::vector<std::string> inputs = {std::string(GT_DATASET_DIR) + "/real/volcano.json",
                                                  std::string(GT_DATASET_DIR) + "/real/topobathy.npz"};
  return inputs;
}

// A uniform number in [0, 1) for (seed, algorithm, set, parameter), the same on every machine.
double draw(std::uint32_t seed, std::size_t algorithm, int set, std::size_t parameter) {
  return uniform01(random_u32(seed, static_cast<std::uint32_t>(algorithm), static_cast<std::uint32_t>(set),
                              static_cast<std::uint32_t>(parameter)));
}

// The value of one plausible parameter for a draw u in [0, 1), as --set text.
std::string drawn_value(const Plausible& plausible, const ParamSpec& spec, double u) {
  if (!plausible.choices.empty()) {
    const auto index = std::min(plausible.choices.size() - 1, static_cast<std::size_t>(u * plausible.choices.size()));
    return plausible.choices[index];
  }
  if (spec.kind == ParamKind::integer) {
    const auto span = static_cast<long long>(plausible.high - plausible.low) + 1;
    return std::to_string(static_cast<long long>(plausible.low) + std::min(span - 1, static_cast<long long>(u * span)));
  }
  const double value = plausible.logarithmic
                           ? std::exp(std::log(plausible.low) + u * (std::log(plausible.high) - std::log(plausible.low)))
                           : plausible.low + u * (plausible.high - plausible.low);
  return fmt::format("{:.4g}", value);
}

}  // namespace

std::vector<std::string> specificity_algorithms() {
  std::vector<std::string> names;
  for (const auto& entry : plausible_table()) names.push_back(entry.algorithm);
  return names;
}

Sweep make_specificity(const std::vector<std::string>& patterns, int sets, std::uint32_t seed) {
  if (sets < 1 || sets > 100) throw InputError(fmt::format("specificity: --sets {} is outside [1, 100]", sets));
  Sweep sweep;
  sweep.kind = SweepKind::specificity;
  sweep.varied = {"set"};
  const auto& table = plausible_table();
  for (std::size_t a = 0; a < table.size(); ++a) {
    const SpecificityAlgorithm& entry = table[a];
    if (!named_by_any(patterns, entry.algorithm)) continue;
    for (int set = 0; set < sets; ++set) {
      std::vector<std::string> assignments;
      std::vector<std::string> cleared;
      for (std::size_t p = 0; p < entry.parameters.size(); ++p) {
        const Plausible& plausible = entry.parameters[p];
        const ParamSpec& spec = find_spec(entry.algorithm, *find_algorithm(entry.algorithm).params, plausible.parameter);
        const std::string value = drawn_value(plausible, spec, draw(seed, a, set, p));
        assignments.push_back(plausible.parameter + "=" + value);
        if (value != "0") cleared.insert(cleared.end(), plausible.clears.begin(), plausible.clears.end());
        if (!plausible.needs.empty() && std::ranges::find(assignments, plausible.needs + "=0") != assignments.end()) {
          cleared.push_back(plausible.parameter);
        }
      }
      std::erase_if(assignments, [&](const std::string& assignment) {
        return std::ranges::find(cleared, assignment.substr(0, assignment.find('='))) != cleared.end();
      });
      for (const std::string& input : specificity_inputs()) {
        AdHocCase variant{.algorithm = entry.algorithm, .input = input, .assignments = assignments};
        variant.name = fmt::format("specificity.{}.{}.set_{:02}", entry.algorithm, ad_hoc_input_name(variant), set);
        sweep.variants.push_back(std::move(variant));
        sweep.varied_values.push_back({fmt::format("{:02}", set)});
      }
    }
  }
  if (sweep.variants.empty()) {
    throw InputError(fmt::format("specificity: no algorithm matches {}; those with plausible ranges: {}",
                                 fmt::join(patterns, ", "), fmt::join(specificity_algorithms(), ", ")));
  }
  return sweep;
}

namespace {

struct AlgorithmTally {
  std::map<std::string, int> outcomes;  // outcome name → runs
  int runs = 0;
  int false_alarms = 0;
  nlohmann::json alarms = nlohmann::json::array();
  nlohmann::json undecided = nlohmann::json::array();  // inconclusive runs: not alarms, shown with why
};

bool is_false_alarm(const CaseResult& result) { return result.status == Outcome::fail || result.status == Outcome::error; }

// A run worth a line: its parameters and the checks that ended with its outcome (fail, or inconclusive
// with the check's reason).
nlohmann::json alarm_json(const AdHocCase& variant, const CaseResult& result) {
  nlohmann::json failing = nlohmann::json::array();
  for (const Check& check : result.checks) {
    if (check.status == Outcome::fail) failing.push_back(fmt::format("{} = {:.3g}", check.name, check.value));
    if (check.status == Outcome::inconclusive && result.status == Outcome::inconclusive) {
      failing.push_back(fmt::format("{}: {}", check.name, check.detail));
    }
  }
  return {{"case", result.name},   {"outcome", outcome_name(result.status)}, {"parameters", variant.assignments},
          {"input", variant.input}, {"failing_checks", failing},             {"error", result.error}};
}

// One run on the page: its case (linked), outcome, checks or error, and parameters.
std::string run_line(const nlohmann::json& run) {
  const auto name = run.at("case").get<std::string>();
  return fmt::format("<p><a href=\"index.html#{}\">{}</a> ({}): {} {}<br>parameters: {}</p>\n", case_anchor(name),
                     escape_markup(name), escape_markup(run.at("outcome").get<std::string>()),
                     escape_markup(run.at("failing_checks").dump()), escape_markup(run.at("error").get<std::string>()),
                     escape_markup(run.at("parameters").dump()));
}

void write_specificity_page(const std::map<std::string, AlgorithmTally>& tallies, const std::filesystem::path& folder) {
  std::ostringstream html;
  html << report_detail::page_head("specificity", "body{font-family:sans-serif}table{border-collapse:collapse}td,th{"
                                                  "border:1px solid #ccc;padding:4px}");
  html << "<h1>Specificity: honest runs not failed</h1>\n<p>Each stepping algorithm as it is, with parameter sets drawn "
          "from plausible sub-ranges of its declared ranges, on two real inputs. A <code>fail</code> or "
          "<code>error</code> here is a false alarm of the harness (or a bug the bundled cases miss). Every run in "
          "full in <a href=\"index.html\">the report</a>; the figures as <a href=\"specificity.json\">JSON</a>.</p>\n"
          "<table><tr><th>algorithm</th><th>runs</th><th>outcomes</th><th>false alarms</th><th>specificity</th></tr>\n";
  for (const auto& [algorithm, tally] : tallies) {
    std::string outcomes;
    for (const auto& [outcome, count] : tally.outcomes) outcomes += fmt::format("{}{} {}", outcomes.empty() ? "" : ", ", count, outcome);
    html << "<tr><td>" << escape_markup(algorithm) << "</td><td>" << tally.runs << "</td><td>" << outcomes << "</td><td>"
         << tally.false_alarms << "</td><td>"
         << fmt::format("{:.3f}", specificity_share(tally.false_alarms, tally.runs)) << "</td></tr>\n";
  }
  html << "</table>\n";
  for (const auto& [algorithm, tally] : tallies) {
    for (const auto& alarm : tally.alarms) html << run_line(alarm);
  }
  bool any_undecided = false;
  for (const auto& [algorithm, tally] : tallies) {
    for (const auto& run : tally.undecided) {
      if (!any_undecided) html << "<h2>Runs not decided (inconclusive: not counted as alarms)</h2>\n";
      any_undecided = true;
      html << run_line(run);
    }
  }
  html << "</body></html>\n";
  write_file_atomically(folder / "specificity.html", html.str());
}

}  // namespace

void write_specificity_summary(const Sweep& sweep, Report& report, const std::filesystem::path& folder) {
  std::map<std::string, AlgorithmTally> tallies;
  for (const AdHocCase& variant : sweep.variants) {
    const auto found = std::find_if(report.cases.begin(), report.cases.end(),
                                    [&](const CaseResult& result) { return result.name == variant.name; });
    if (found == report.cases.end()) continue;  // another shard's
    AlgorithmTally& tally = tallies[variant.algorithm];
    ++tally.runs;
    ++tally.outcomes[outcome_name(found->status)];
    if (is_false_alarm(*found)) {
      ++tally.false_alarms;
      tally.alarms.push_back(alarm_json(variant, *found));
    } else if (found->status == Outcome::inconclusive) {
      tally.undecided.push_back(alarm_json(variant, *found));
    }
  }
  nlohmann::json summary = {{"algorithms", nlohmann::json::array()}};
  int runs = 0, false_alarms = 0;
  for (const auto& [algorithm, tally] : tallies) {
    runs += tally.runs;
    false_alarms += tally.false_alarms;
    summary["algorithms"].push_back({{"algorithm", algorithm},
                                     {"runs", tally.runs},
                                     {"outcomes", tally.outcomes},
                                     {"false_alarms", tally.false_alarms},
                                     {"specificity", specificity_share(tally.false_alarms, tally.runs)},
                                     {"alarms", tally.alarms},
                                     {"undecided", tally.undecided}});
  }
  summary["runs"] = runs;
  summary["false_alarms"] = false_alarms;
  summary["specificity"] = specificity_share(false_alarms, runs);
  write_file_atomically(folder / "specificity.json", summary.dump(2) + '\n');
  write_specificity_page(tallies, folder);
  report.plots.push_back({"", "plot",
                          fmt::format("specificity: {} of {} honest runs not failed ({} false alarms); per algorithm "
                                      "and each alarm in specificity.html",
                                      runs - false_alarms, runs, false_alarms)});
}

}  // namespace gt
