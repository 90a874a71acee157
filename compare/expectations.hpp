// datasets/expectations.txt: known outcomes of named checks (issue 11). One entry a line:
//
//   CASE_GLOB  CHECK_GLOB  OUTCOME  [device=GLOB]  REASON...
//
// e.g. `cave.marching_cubes.solid.block12 mesh.closed.cpu fail the seed's marching cubes leaves holes`.
// Globs are shell-style (fnmatch); OUTCOME is one of pass, warn, inconclusive, fail, skip, error;
// device=GLOB restricts the entry to runs whose GL renderer matches (e.g. device=llvmpipe*).
// '#' starts a comment line.
//
// Rules, applied after every case has run:
//   - a check an entry matches is expected to have that outcome: if it has, it does not fail the
//     run (a known failure); if it has not, the run fails (a fixed bug or a new one: update the file);
//   - an entry whose case glob matches a case of this run but none of its checks fails the run
//     (the check it names was renamed or no longer runs);
//   - a case that could not run (error) fails the run, listed or not;
//   - loading: an entry whose case glob matches no case of the suite at all, an unknown outcome, a
//     missing reason or a malformed line is bad input (InputError, exit 2).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/cases.hpp"
#include "compare/result.hpp"

namespace gt {

struct Expectation {
  std::string case_pattern;
  std::string check_pattern;
  Outcome outcome = Outcome::fail;
  std::string device_pattern;  // empty: every device
  std::string reason;
  int line = 0;                // in the file, for messages
};

// Throws InputError for the malformed entries described above; `suite` is every case of the
// case folder (whether or not this run selected it).
std::vector<Expectation> load_expectations(const std::filesystem::path& file, const std::vector<CaseSpec>& suite);

// Marks the checks of `report`'s cases that entries match (Check::expected, expectation) and
// sets each case's expected_failure; returns one line per broken rule (empty: none broken).
std::vector<std::string> apply_expectations(const std::vector<Expectation>& expectations, Report& report);

}  // namespace gt
