// `groundtruth mutants [PATTERN...]`: the proof that the checks can fail (issue 11). For every
// registered mutant (compare/mutants/) whose name matches a pattern (all when none):
//   1. per family, the union of the selected mutants' cases runs once unmutated (the baseline):
//      it must finish with nothing failed, or a kill would prove nothing;
//   2. each mutant runs its cases with the mutant on, in a worker process of this executable
//      (`groundtruth run CASES --mutant NAME`), with a time limit;
//   3. the mutant is killed when one of its cases has a check that fails under the mutant, did not
//      fail in the baseline, and is of the kind meant for the mutant (check_kind_kills: parity,
//      image and determinism checks or a float twin's own ledgers and invariants for one-twin
//      mutants, anything but parity, image and determinism for both-twins ones).
//      A run that errors or times out cannot tell: the mutant's status says so, it is not killed.
// The mutation score is killed / selected. Every run's report stays under the folder given; the
// HTML links each mutant to its run's report (runs/<name>/index.html below the mutation folder).
// The kill matrix (MutationReport::kill_matrix) lists every check graded in a baseline (one with a
// bound) with the mutants it killed: a graded check that kills none is a check not yet proved.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/mutants/mutants.hpp"
#include "compare/result.hpp"

namespace gt {

struct MutationOptions {
  std::vector<std::string> patterns;   // mutant-name globs; empty: all
  std::string gl = "egl";
  bool require_gpu = false;            // passed to every worker run
  double timeout_seconds = 600.0;      // per worker run
  int parallel = 1;                    // worker runs at once (-j)
  int specificity_sets = 0;  // > 0: also `groundtruth specificity --sets N` (report --full, mutants --specificity-sets)
};

// The selected mutants; throws InputError when a pattern matches none.
std::vector<Mutant> select_mutants(const std::vector<std::string>& patterns);

// Runs the baselines and the mutants into `folder` (created; runs/<name>/ and baseline/<family>/),
// and with specificity_sets > 0 `groundtruth specificity --sets N` into specificity/.
// Throws InputError when a mutant names a case pattern that matches no case.
MutationReport run_mutation(const MutationOptions& options, const std::filesystem::path& folder,
                            const std::filesystem::path& dataset_dir);

nlohmann::json mutation_to_json(const MutationReport& report);

}  // namespace gt
