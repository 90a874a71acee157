// Cases in worker processes (`run`/`report -j N`, `--case-timeout`): each case runs as
// `groundtruth run CASE --worker --out FOLDER/.workers/<n> ...` (its own process and GL context),
// N at a time. A worker that crashes, aborts or runs past the timeout ends as the case's `error`,
// naming the signal or the timeout, with its log kept beside the case's pictures; the run goes on.
//
// Inputs: the cases (each with the arguments that select it in a worker, and what the parent
//   already knows about it), the arguments every worker shares (backend, GL, repetitions, mutant),
//   the report folder being filled.
// Output: the cases' results in the order given; each worker's case folder is moved into the
//   report folder (so artifact paths stay "<case>/<file>"), and the workers' GL description and
//   provenance digests are folded into `environment`. The .workers folder is removed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/progress.hpp"
#include "compare/result.hpp"

namespace gt {

struct IsolatedCase {
  std::vector<std::string> selection;  // the worker arguments that select this case alone
  CaseResult known;                    // name, algorithm, input, size: what an error result shows
};

struct IsolationOptions {
  int parallel = 1;
  double timeout_seconds = 1800.0;
  std::vector<std::string> common_args;  // after "run": --gl, --backend, --cpu-reps, ...
};

std::vector<CaseResult> run_isolated(const std::vector<IsolatedCase>& cases, const IsolationOptions& options,
                                     const std::filesystem::path& folder, Environment& environment,
                                     Progress& progress);

// A case name as an fnmatch pattern that matches only itself.
std::string exact_pattern(const std::string& case_name);

}  // namespace gt
