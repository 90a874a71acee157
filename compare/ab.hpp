// `groundtruth ab` (issue 19): two variants of one algorithm on one input, side by side.
//
// make_ab makes two ad-hoc cases from the base (its input and --set assignments): A with the
// --a assignments, B with the --b ones, named ab.<algorithm>.<input>.a and .b; the driver runs
// them as any ad-hoc case, so unknown parameters and values out of range exit 2 before anything
// runs. A and B must differ, and a parameter may not be both --set and --a/--b.
//
// write_ab_summary, after the runs, writes into the report folder:
// (Files named with the Sweep's ab_stem, "ab" for the command:)
//   ab.json        both variants' assignments and, for every metric (compare/sweep.hpp's
//                  run_metric_names), A's value, B's and B - A; the outcomes
//   ab_difference.png   B's result - A's (the first ref<double> field of fields.json: the
//                  terrain or the generated field), blue below, red above
//   ab.html        A's and B's pictures, the difference map, and the metrics table with the
//                  metrics that moved first
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/cases.hpp"
#include "compare/driver.hpp"
#include "compare/result.hpp"

namespace gt {

Sweep make_ab(const AdHocCase& base, const std::vector<std::string>& a, const std::vector<std::string>& b);

void write_ab_summary(const Sweep& ab, Report& report, const std::filesystem::path& folder);

// A case file's A/B pairs (compare/cases.hpp "ab"): for each pair whose A and B cases are both
// among `specs` (the run's), the summary above under the stem ab.<pair name>: ab.<pair>.html,
// ab.<pair>.json and ab.<pair>_difference.png (also a report-level plot, so index.html shows it).
void write_case_ab_summaries(const std::vector<CaseSpec>& specs, Report& report, const std::filesystem::path& folder);

}  // namespace gt
