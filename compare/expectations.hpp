// datasets/expectations.txt: known outcomes of named checks (issue 11). One entry a line:
//
//   CASE_GLOB  CHECK_GLOB  OUTCOME  [device=GLOB]  REASON...
//
// e.g. `cave.marching_cubes.solid.block12 mesh.closed.cpu fail the seed's marching cubes leaves holes`.
// Globs are shell-style (fnmatch); OUTCOME is one of pass, warn, inconclusive, fail, skip, error,
// flaky; device=GLOB restricts the entry to runs whose GL renderer matches (e.g. device=llvmpipe*).
// '#' starts a comment line. A user's own files come with `--expectations FILE` (beside their
// `--cases`), a flake list with `--flakes FILE` (the same format, every entry `flaky`).
//
// `flaky` entries form the flake list: they set no check's expected outcome. A case that failed
// and then passed when run again (--retries) is `flaky`; it is a known flake, which does not fail
// the run, when every failing check of its failed attempts matches a flaky entry of the case (an
// attempt that could not run at all counts as the check "error"). A case a flaky entry names is
// run again at least once even without --retries.
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
  std::string file;            // the file and line, for messages
  int line = 0;
};

enum class ExpectationFile { optional, required, flakes_only };

// Throws InputError for the malformed entries described above; `suite` is every case of the
// case folder and the --cases (whether or not this run selected it). An absent file is no
// entries when `kind` is optional (the bundled list), else bad input; a flakes_only file may
// hold only `flaky` entries.
std::vector<Expectation> load_expectations(const std::filesystem::path& file, const std::vector<CaseSpec>& suite,
                                           ExpectationFile kind = ExpectationFile::optional);

// The flaky entries' reason for `result` when it is a known flake (see above), else empty.
std::string known_flake_reason(const std::vector<Expectation>& expectations, const CaseResult& result);

// Whether a flaky entry names the case (it gets at least one retry).
bool named_as_flaky(const std::vector<Expectation>& expectations, const std::string& case_name);

// Marks the checks of `report`'s cases that entries match (Check::expected, expectation), sets
// each case's expected_failure and, for flaky cases, known_flake; returns one line per broken rule
// (empty: none broken).
std::vector<std::string> apply_expectations(const std::vector<Expectation>& expectations, Report& report);

}  // namespace gt
