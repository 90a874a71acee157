// `groundtruth sweep` (issue 19): one algorithm on one input over a grid of parameter values.
//
// make_sweep expands every `--vary name=v1,v2,...` into the Cartesian product of the values (or
// make_sweep_of_sets takes named parameter sets from a file, `--sets FILE`), each
// combination an ad-hoc case (compare/driver.hpp's AdHocCase) named
// sweep.<algorithm>.<input>.<name>_<value>[.<name>_<value>...] with the base's --set assignments
// and its own; the driver runs them as any ad-hoc case (with -j, in workers), so values out of
// range and unknown parameters are refused before anything runs (exit 2).
//
// write_sweep_summary, after the runs, writes into the report folder:
//   sweep.csv, sweep.json  one row per run: the varied values, the outcome, the case's wall time,
//                          the CPU and GPU medians, and the value of every check the runs report
//   sweep_<n>.png          a metric against the first varied parameter and its unit (one line per
//                          combination of the others; categorical values at their index), for
//                          every descriptor, check and timing whose value differs between the runs,
//                          in metrics_by_movement's order, titled by metric_label
//   sweep.html             the table with a thumbnail of each run's result and the plots
// and lists the plots as report-level plots, so index.html shows them too.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/driver.hpp"
#include "compare/result.hpp"

namespace gt {

// More runs than this need --force: a sweep is meant to be read, and each run takes its time.
constexpr std::size_t sweep_run_cap = 64;

Sweep make_sweep(const AdHocCase& base, const std::vector<std::string>& vary, bool force);

// Whether the base's --set assignments give `name`: a sweep or an A/B comparison may then not
// vary it.
bool sets_parameter(const AdHocCase& base, const std::string& name);

// A parameter value from JSON (a named set, a case file's A/B side) as the name=value text of
// --set, which the declarations parse back: a string as it is, anything else as JSON.
std::string assignment_text(const std::string& name, const nlohmann::json& value);

// A sweep over named parameter sets read from a JSON file, {"thesis": {"tilt_differences":
// "central"}, "code": {...}, ...}: one run per set, in the file's order, named
// sweep.<algorithm>.<input>.<set name> and tabled under the varied "set". Refused (InputError): a
// file that cannot be read or is not a non-empty object of objects, a value that is not a number,
// bool or string, a parameter also given with --set, two sets of the same case name, more sets
// than the cap without --force.
Sweep make_sweep_of_sets(const AdHocCase& base, const std::filesystem::path& file, bool force);

// What a sweep or an A/B comparison reads of each run. The metrics: "seconds" (the case's wall
// time), "cpu_ms" and "gpu_ms" (the medians), every check the runs report (not skipped), and
// "descriptor.<group>.<name>" for each scalar terrain descriptor of ref<double>'s result, in that
// order, each name once.
std::vector<std::string> run_metric_names(const std::vector<const CaseResult*>& results);

// A metric of one run, or nullopt where the run has none (or a non-finite value).
std::optional<double> run_metric(const CaseResult& result, const std::string& name);

// A metric as a reader names it, and its unit ("" where it has none): the timings and the
// descriptors in words ("slope, mean", "°"); a check by its stable dotted name.
struct MetricLabel {
  std::string label;
  std::string unit;
};
MetricLabel metric_label(const std::string& name);

// What a metric is: a terrain descriptor of the result ("descriptor.*"), a timing ("seconds",
// "cpu_ms", "gpu_ms") or a check (anything else).
enum class MetricGroup { descriptor, check, timing };
MetricGroup metric_group(const std::string& name);

// The metrics in the order a reader wants them: the result's descriptors, then the checks, then the
// timings (noise of one run); in each group, what moved most across the runs first (the spread
// max - min as a share of the largest magnitude).
std::vector<std::string> metrics_by_movement(const std::vector<const CaseResult*>& results,
                                             const std::vector<std::string>& metrics);

// The picture of a run's result: ref<double>'s terrain after it (after_cpu.png) or its field
// (cpu.png), else its first picture; empty when it has none.
std::string result_picture(const CaseResult& result);

void write_sweep_summary(const Sweep& sweep, Report& report, const std::filesystem::path& folder);

}  // namespace gt
