// report.json read back into a Report: how a run collects its worker processes' cases (-j) and how
// `groundtruth merge` joins shards. The inverse of report_to_json (writers.hpp) for everything a
// case and the environment hold, and the shard record; benchmarks, the mutation and a baseline's
// diff are not read back (shards and workers do not make them).
//
// Inputs: a document that read_report_json (compare/report_diff.hpp) accepted (schema 1).
// Output: the Report; a null value with "value_text" ("nan", "inf", "-inf") becomes that number.
// Throws InputError when a field has the wrong type or an outcome is unknown, naming the case.
#pragma once

#include <nlohmann/json.hpp>

#include "compare/result.hpp"

namespace gt {

Report report_from_json(const nlohmann::json& document);

}  // namespace gt
