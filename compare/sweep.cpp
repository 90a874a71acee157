#include "compare/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/algorithm.hpp"
#include "compare/cases.hpp"
#include "compare/report/plots.hpp"
#include "compare/report/report_common.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/text_file.hpp"
#include "core/json_keys.hpp"

namespace gt {
namespace {

using report_detail::case_anchor;
using report_detail::escape_markup;

// The plots drawn at most (each is a matplotlib run); the table holds every metric.
constexpr std::size_t sweep_plot_cap = 24;

struct Varied {
  std::string name;
  std::vector<std::string> values;
};

Varied parse_vary(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) {
    throw InputError(fmt::format("--vary '{}': expected name=v1,v2,...", text));
  }
  Varied varied{text.substr(0, equals), {}};
  std::size_t start = equals + 1;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string value = text.substr(start, comma - start);
    if (value.empty()) throw InputError(fmt::format("--vary '{}': an empty value", text));
    if (std::find(varied.values.begin(), varied.values.end(), value) != varied.values.end()) {
      throw InputError(fmt::format("--vary '{}': the value {} twice", text, value));
    }
    varied.values.push_back(value);
    start = comma + 1;
  }
  return varied;
}

// Counted in double: a product of the axes' sizes cannot wrap around to a small number (3.1e20
// combinations once counted as 2). --force lifts the cap up to the most runs one report can
// list; beyond that nothing is run.
void check_run_count(double runs, bool force) {
  constexpr double most_runs_forced = 1e6;
  if (runs > most_runs_forced) {
    throw InputError(fmt::format("sweep: {:.3g} runs, more than any sweep may have ({:.0f}); vary fewer values",
                                 runs, most_runs_forced));
  }
  if (runs > sweep_run_cap && !force) {
    throw InputError(fmt::format("sweep: {:.0f} runs, more than the cap of {}; pass --force to run them all", runs,
                                 sweep_run_cap));
  }
}

// The number a varied value stands for, or nullopt when the parameter is not numeric.
std::optional<double> number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

struct Row {
  std::vector<std::string> values;  // the varied values, as given
  const CaseResult* result = nullptr;
};

std::vector<const CaseResult*> results_of(const std::vector<Row>& rows) {
  std::vector<const CaseResult*> results;
  for (const Row& row : rows) results.push_back(row.result);
  return results;
}

// The scalar terrain descriptors of ref<double>'s result (compare/case_descriptors.hpp), as
// "descriptor.<group>.<name>" (hypsometry.integral, slope_deg.mean, drainage.drainage_density_per_m...).
std::map<std::string, double> descriptor_metrics(const CaseResult& result) {
  std::map<std::string, double> metrics;
  const nlohmann::json* cpu = result.descriptors.is_object() ? &result.descriptors : nullptr;
  for (const char* key : {"terrains", "cpu"}) {
    cpu = cpu != nullptr && cpu->contains(key) && (*cpu)[key].is_object() ? &(*cpu)[key] : nullptr;
  }
  if (cpu == nullptr) return metrics;
  for (const auto& [group, values] : cpu->items()) {
    if (group == "grid" || !values.is_object()) continue;
    for (const auto& [name, value] : values.items()) {
      if (value.is_number()) metrics[fmt::format("descriptor.{}.{}", group, name)] = value.get<double>();
    }
  }
  return metrics;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void write_table(const Sweep& sweep, const std::vector<Row>& rows, const std::vector<std::string>& metrics,
                 const std::filesystem::path& folder) {
  std::ofstream csv(folder / "sweep.csv");
  std::vector<std::string> header = sweep.varied;
  header.insert(header.end(), {"case", "outcome"});
  header.insert(header.end(), metrics.begin(), metrics.end());
  for (std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << csv_field(header[i]);
  csv << '\n';
  nlohmann::json table = {{"varied", sweep.varied}, {"metrics", metrics}, {"runs", nlohmann::json::array()}};
  for (const Row& row : rows) {
    nlohmann::json run = {{"case", row.result->name}, {"outcome", outcome_name(row.result->status)}};
    std::vector<std::string> cells = row.values;
    cells.insert(cells.end(), {row.result->name, outcome_name(row.result->status)});
    for (std::size_t k = 0; k < sweep.varied.size(); ++k) run["params"][sweep.varied[k]] = row.values[k];
    for (const std::string& name : metrics) {
      const auto value = run_metric(*row.result, name);
      cells.push_back(value ? fmt::format("{:.9g}", *value) : "");
      run["metrics"][name] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
    }
    for (std::size_t i = 0; i < cells.size(); ++i) csv << (i ? "," : "") << csv_field(cells[i]);
    csv << '\n';
    table["runs"].push_back(run);
  }
  write_file_atomically(folder / "sweep.json", table.dump(2) + '\n');
}

// How far a metric moved across the runs, as a share of its largest magnitude (0 when it did not):
// the plots' order, so that the parameter's effect comes before the noise of the timings.
double relative_spread(const std::vector<const CaseResult*>& results, const std::string& name) {
  std::optional<double> low, high;
  for (const CaseResult* result : results) {
    const auto value = run_metric(*result, name);
    if (!value) continue;
    low = std::min(low.value_or(*value), *value);
    high = std::max(high.value_or(*value), *value);
  }
  if (!low || *high == *low) return 0.0;
  return (*high - *low) / std::max(std::abs(*high), std::abs(*low));
}

// The varied parameter as an axis: its name and its declared unit ("talus_angle (degree)").
std::string axis_label(const std::string& algorithm, const std::string& parameter) {
  const Algorithm& declared = find_algorithm(algorithm);
  if (declared.params != nullptr) {
    for (const ParamSpec& spec : *declared.params) {
      if (spec.name == parameter && !spec.unit.empty() && spec.unit != "1") return fmt::format("{} ({})", parameter, spec.unit);
    }
  }
  return parameter;
}

std::string labelled(const MetricLabel& label) {
  return label.unit.empty() ? label.label : fmt::format("{} ({})", label.label, label.unit);
}

// One plot per metric that differs between the runs: against the first varied parameter, a line
// per combination of the others; the result's descriptors first, then the checks, then the
// timings, each group by how far its metrics moved (relative_spread), largest first.
std::vector<Artifact> plot_metrics(const Sweep& sweep, const std::vector<Row>& rows,
                                   const std::vector<std::string>& metrics, const std::filesystem::path& folder) {
  bool numeric = true;
  for (const Row& row : rows) numeric = numeric && number(row.values.front()).has_value();
  std::vector<std::string> first_values;
  for (const Row& row : rows) {
    if (std::find(first_values.begin(), first_values.end(), row.values.front()) == first_values.end()) {
      first_values.push_back(row.values.front());
    }
  }
  const auto x_of = [&](const Row& row) {
    if (numeric) return *number(row.values.front());
    return static_cast<double>(std::find(first_values.begin(), first_values.end(), row.values.front()) -
                               first_values.begin());
  };
  const std::vector<std::string> order = metrics_by_movement(results_of(rows), metrics);
  const std::string x_label = rows.empty() ? sweep.varied.front() : axis_label(rows.front().result->algorithm, sweep.varied.front());
  std::vector<Artifact> plots;
  for (const std::string& name : order) {
    if (plots.size() == sweep_plot_cap) break;
    std::set<double> distinct;
    std::map<std::string, Series> lines;  // by the other varied values
    const std::string title = labelled(metric_label(name));
    for (const Row& row : rows) {
      const auto value = run_metric(*row.result, name);
      if (!value) continue;
      distinct.insert(*value);
      std::string others;
      for (std::size_t k = 1; k < row.values.size(); ++k) {
        others += fmt::format("{}{}={}", others.empty() ? "" : ", ", sweep.varied[k], row.values[k]);
      }
      Series& line = lines[others];
      line.label = others;  // empty for a single line: the title names it
      line.x.push_back(x_of(row));
      line.y.push_back(*value);
    }
    if (distinct.size() < 2) continue;
    SeriesPlot plot{.title = title, .x_label = x_label, .y_label = title};
    if (!numeric) {
      for (std::size_t i = 0; i < first_values.size(); ++i) plot.x_ticks.emplace_back(double(i), first_values[i]);
    }
    for (auto& [others, line] : lines) plot.series.push_back(std::move(line));
    const std::string file = fmt::format("sweep_{}.png", plots.size() + 1);
    std::string reason;
    if (auto artifact = plot_series({plot}, folder, file,
                                    fmt::format("{} against {} ({} moved {:.3g} % of its largest value)", title, x_label,
                                                name, 100.0 * relative_spread(results_of(rows), name)),
                                    reason)) {
      plots.push_back(*artifact);
    } else {
      plots.push_back({"", "plot", "plot unavailable: " + reason});
      break;  // no Python with matplotlib: the next would fail alike
    }
  }
  return plots;
}

void write_page(const Sweep& sweep, const std::vector<Row>& rows, const std::vector<Artifact>& plots,
                const std::filesystem::path& folder) {
  std::ofstream html(folder / "sweep.html");
  const std::string algorithm = rows.empty() ? "" : rows.front().result->algorithm;
  html << report_detail::page_head("sweep of " + algorithm,
                                   "body{font-family:sans-serif}table{border-collapse:collapse}td,th{border:1px solid "
                                   "#ccc;padding:4px}img.thumb{width:128px;image-rendering:pixelated}"
                                   "div.plots{display:grid;grid-template-columns:repeat(auto-fill,minmax(400px,1fr));gap:1em}"
                                   "div.plots img{width:100%}figure{margin:0}figcaption{font-size:.9em;color:#444}");
  html << "<h1>Sweep of " << escape_markup(algorithm) << "</h1>\n<p>" << rows.size()
       << " runs; the table as <a href=\"sweep.csv\">CSV</a> and <a href=\"sweep.json\">JSON</a>; every run in full "
          "in <a href=\"index.html\">the report</a>.</p>\n<table><tr>";
  for (const auto& name : sweep.varied) html << "<th>" << escape_markup(name) << "</th>";
  html << "<th>case</th><th>outcome</th><th>picture</th></tr>\n";
  for (const Row& row : rows) {
    html << "<tr>";
    for (const auto& value : row.values) html << "<td>" << escape_markup(value) << "</td>";
    const std::string picture = result_picture(*row.result);
    html << "<td><a href=\"index.html#" << case_anchor(row.result->name) << "\">" << escape_markup(row.result->name)
         << "</a></td><td>" << outcome_name(row.result->status) << "</td><td>";
    if (!picture.empty()) html << "<img class=\"thumb\" src=\"" << escape_markup(picture) << "\" alt=\"\">";
    html << "</td></tr>\n";
  }
  html << "</table>\n<h2>What moved</h2>\n<p>Each metric against " << escape_markup(sweep.varied.front())
       << ": the result's terrain descriptors first, then the checks, then the timings; in each, what moved most "
          "first.</p>\n<div class=\"plots\">\n";
  for (const Artifact& plot : plots) {
    if (plot.path.empty()) {
      html << "<p>" << escape_markup(plot.caption) << "</p>\n";
    } else {
      html << "<figure><img src=\"" << escape_markup(plot.path) << "\" alt=\"" << escape_markup(plot.caption)
           << "\" loading=\"lazy\"><figcaption>" << escape_markup(plot.caption) << "</figcaption></figure>\n";
    }
  }
  html << "</div>\n</body></html>\n";
}

}  // namespace

std::vector<std::string> run_metric_names(const std::vector<const CaseResult*>& results) {
  std::vector<std::string> names = {"seconds", "cpu_ms", "gpu_ms"};
  std::set<std::string> seen(names.begin(), names.end());
  for (const CaseResult* result : results) {
    for (const Check& check : result->checks) {
      if (check.status != Outcome::skip && seen.insert(check.name).second) names.push_back(check.name);
    }
  }
  for (const CaseResult* result : results) {
    for (const auto& [name, value] : descriptor_metrics(*result)) {
      if (seen.insert(name).second) names.push_back(name);
    }
  }
  return names;
}

std::optional<double> run_metric(const CaseResult& result, const std::string& name) {
  if (name == "seconds") return result.seconds;
  if (name == "cpu_ms") return result.timings.cpu_ms;
  if (name == "gpu_ms") return result.timings.gpu_ms;
  if (name.rfind("descriptor.", 0) == 0) {
    const auto descriptors = descriptor_metrics(result);
    const auto found = descriptors.find(name);
    if (found != descriptors.end() && std::isfinite(found->second)) return found->second;
    return std::nullopt;
  }
  for (const Check& check : result.checks) {
    if (check.name == name && check.status != Outcome::skip && std::isfinite(check.value)) return check.value;
  }
  return std::nullopt;
}

MetricLabel metric_label(const std::string& name) {
  if (name == "seconds") return {"the case's wall time", "s"};
  if (name == "cpu_ms") return {"CPU reference time, median", "ms"};
  if (name == "gpu_ms") return {"GPU time, median", "ms"};
  if (name.rfind("descriptor.", 0) != 0) return {name, ""};
  // descriptor.<group>.<name>: a unit suffix on either names the unit (slope_deg, laplacian_per_m,
  // stream_threshold_m2, drainage_density_per_m); the hypsometry's min, mean and max are heights.
  std::string rest = name.substr(std::string("descriptor.").size());
  std::string unit;
  const auto strip_unit = [&](std::string word) {
    for (const auto& [suffix, symbol] : {std::pair{"_per_m", "1/m"}, {"_deg", "°"}, {"_m2", "m²"}, {"_m", "m"}}) {
      const std::string tail = suffix;
      if (word.size() > tail.size() && word.compare(word.size() - tail.size(), tail.size(), tail) == 0) {
        unit = symbol;
        return word.substr(0, word.size() - tail.size());
      }
    }
    return word;
  };
  const auto dot = rest.find('.');
  const std::string group = strip_unit(rest.substr(0, dot));
  const std::string leaf = dot == std::string::npos ? "" : strip_unit(rest.substr(dot + 1));
  if (group == "hypsometry" && (leaf == "min" || leaf == "mean" || leaf == "max")) unit = "m";
  if (leaf == "count" || leaf.ends_with("cells")) unit = "";  // how many cells were measured
  std::string label = leaf.empty() || leaf == group ? group : group + ", " + leaf;
  std::replace(label.begin(), label.end(), '_', ' ');
  return {label, unit};
}

MetricGroup metric_group(const std::string& name) {
  if (name.rfind("descriptor.", 0) == 0) return MetricGroup::descriptor;
  if (name == "seconds" || name == "cpu_ms" || name == "gpu_ms") return MetricGroup::timing;
  return MetricGroup::check;
}

std::vector<std::string> metrics_by_movement(const std::vector<const CaseResult*>& results,
                                             const std::vector<std::string>& metrics) {
  std::vector<std::pair<std::string, double>> ranked;
  for (const auto& name : metrics) ranked.emplace_back(name, relative_spread(results, name));
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
    const MetricGroup group_a = metric_group(a.first), group_b = metric_group(b.first);
    if (group_a != group_b) return group_a < group_b;
    return a.second > b.second;
  });
  std::vector<std::string> order;
  for (auto& [name, spread] : ranked) order.push_back(std::move(name));
  return order;
}

std::string result_picture(const CaseResult& result) {
  for (const char* file : {"/after_cpu.png", "/cpu.png"}) {
    for (const Artifact& artifact : result.artifacts) {
      if (artifact.kind == "image" && artifact.path.ends_with(file)) return artifact.path;
    }
  }
  for (const Artifact& artifact : result.artifacts) {
    if (artifact.kind == "image") return artifact.path;
  }
  return "";
}

bool sets_parameter(const AdHocCase& base, const std::string& name) {
  return std::any_of(base.assignments.begin(), base.assignments.end(),
                     [&](const std::string& assignment) { return assignment.starts_with(name + "="); });
}

std::string assignment_text(const std::string& name, const nlohmann::json& value) {
  return name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
}

Sweep make_sweep(const AdHocCase& base, const std::vector<std::string>& vary, bool force) {
  if (vary.empty()) throw InputError("sweep: give at least one --vary name=v1,v2,..., or --sets FILE of named parameter sets");
  std::vector<Varied> axes;
  double runs = 1.0;
  for (const auto& text : vary) {
    Varied varied = parse_vary(text);
    for (const auto& axis : axes) {
      if (axis.name == varied.name) throw InputError(fmt::format("--vary {} given twice", varied.name));
    }
    if (sets_parameter(base, varied.name)) {
      throw InputError(fmt::format("{} is both --set and --vary: choose one", varied.name));
    }
    runs *= static_cast<double>(varied.values.size());
    axes.push_back(std::move(varied));
  }
  check_run_count(runs, force);
  Sweep sweep;
  for (const auto& axis : axes) sweep.varied.push_back(axis.name);
  for (std::size_t index = 0; index < static_cast<std::size_t>(runs); ++index) {
    AdHocCase variant = base;
    std::string name = fmt::format("sweep.{}.{}", base.algorithm, ad_hoc_input_name(base));
    std::size_t rest = index;
    std::vector<std::string> chosen(axes.size());
    for (std::size_t k = axes.size(); k-- > 0;) {  // the last axis varies fastest
      chosen[k] = axes[k].values[rest % axes[k].values.size()];
      rest /= axes[k].values.size();
    }
    for (std::size_t k = 0; k < axes.size(); ++k) {
      variant.assignments.push_back(axes[k].name + "=" + chosen[k]);
      name += "." + case_name_part(axes[k].name + "_" + chosen[k]);
    }
    variant.name = name;
    sweep.variants.push_back(std::move(variant));
    sweep.varied_values.push_back(std::move(chosen));
  }
  return sweep;
}

Sweep make_sweep_of_sets(const AdHocCase& base, const std::filesystem::path& file, bool force) {
  const std::string where = fmt::format("--sets {}", file.string());
  const std::string text = read_text_file(file, json_document_limits, "--sets");
  // Counted before the sets are read in order: an ordered object finds each key by a linear
  // search, so parsing 300,000 sets in order takes a minute (61 s here) before the cap could
  // refuse them.
  std::size_t count = 0;
  try {
    std::istringstream counted(text);
    const nlohmann::json unordered = parse_json_bounded(counted, where);
    count = unordered.is_object() ? unordered.size() : 0;
  } catch (const nlohmann::json::exception& error) {
    throw InputError(fmt::format("{}: not valid JSON: {}", where, error.what()));
  }
  if (count == 0) {
    throw InputError(fmt::format("{}: expected a non-empty object of named parameter sets, "
                                 "{{\"name\": {{\"parameter\": value, ...}}, ...}}",
                                 where));
  }
  check_run_count(static_cast<double>(count), force);
  std::istringstream in(text);
  const nlohmann::ordered_json sets = parse_ordered_json_bounded(in, where);  // the sets run in the file's order
  std::set<std::string> case_names;
  Sweep sweep;
  sweep.varied = {"set"};
  for (const auto& [set_name, params] : sets.items()) {
    if (!params.is_object()) throw InputError(fmt::format("{}: set '{}' is not an object of parameters", where, set_name));
    AdHocCase variant = base;
    for (const auto& [name, value] : params.items()) {
      if (!value.is_primitive() || value.is_null()) {
        throw InputError(fmt::format("{}: set '{}': {} must be a number, a bool or a string", where, set_name, name));
      }
      if (sets_parameter(base, name)) {
        throw InputError(fmt::format("{} is both --set and in set '{}': choose one", name, set_name));
      }
      variant.assignments.push_back(assignment_text(name, value));
    }
    variant.name = fmt::format("sweep.{}.{}.{}", base.algorithm, ad_hoc_input_name(base), case_name_part(set_name));
    if (!case_names.insert(variant.name).second) {
      throw InputError(fmt::format("{}: sets '{}' and another name the same case {}: rename one", where, set_name,
                                   variant.name));
    }
    sweep.variants.push_back(std::move(variant));
    sweep.varied_values.push_back({set_name});
  }
  return sweep;
}

void write_sweep_summary(const Sweep& sweep, Report& report, const std::filesystem::path& folder) {
  std::vector<Row> rows;
  for (std::size_t index = 0; index < sweep.variants.size(); ++index) {
    const auto found = std::find_if(report.cases.begin(), report.cases.end(), [&](const CaseResult& result) {
      return result.name == sweep.variants[index].name;
    });
    if (found == report.cases.end()) continue;  // another shard's
    rows.push_back({sweep.varied_values[index], &*found});
  }
  const std::vector<std::string> metrics = run_metric_names(results_of(rows));
  write_table(sweep, rows, metrics, folder);
  const std::vector<Artifact> plots = plot_metrics(sweep, rows, metrics, folder);
  write_page(sweep, rows, plots, folder);
  report.plots.insert(report.plots.end(), plots.begin(), plots.end());
}

}  // namespace gt
