// Cases are data (piglit-style declarative files): datasets/cases/*.json hold arrays of cases,
// each naming the algorithm, its parameters, its input and what is expected. Ad-hoc cases from
// `groundtruth run --algorithm --input --set` become the same CaseSpec.
//
// Case file entry:
//   {"name": "erosion.thermal.cardinal.volcano",          stable dotted name
//    "algorithm": "erosion.thermal",
//    "params": {"iterations": 100, ...},                   checked against the algorithm's specs
//    "input": {"file": "real/volcano.json"}                path relative to datasets/, or absolute
//          | {"generator": "cone", "width": 128, ...}      see compare/inputs.hpp
//          | {"mesh": "real/meshes/bunny00.off"}           a triangle mesh
//                                                          (absent: the algorithm makes its own, e.g. the cave)
//    "crop": [x, y, width, height],                        optional, applied to the input
//    "expect": {"cells": [[x, y, value], ...],             optional spec vectors (spec.* checks)
//               "total": 1.0, "tolerance": 1e-12},
//    "ab": {"a": {"tilt_differences": "central"},          optional: an A/B pair (issue 19). The entry
//           "b": {"tilt_differences": "seed001_code"}}}    becomes two cases, <name>.a and <name>.b,
//                                                          each with "params" and its side's; the two
//                                                          sides differ and set no parameter of "params".
//                                                          A run holding both writes the pair's page
//                                                          ab.<name>.html (compare/ab.hpp).
//    "tier": "quick" | "report" | "full"}                 optional, "report" when absent: the
//                                                          smallest suite that runs it (see Tier)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

// The suites a case belongs to, each holding the one before: `run --quick` runs the quick tier
// (a pre-commit answer in under 2 minutes on 2 cores, every algorithm family), `report` the quick
// and report tiers (every family's decisive checks, within the README's 15 minutes), `report
// --full` every case (the long runs and the largest grids too). Declared by each case file entry.
enum class Tier { quick, report, full };

const char* tier_name(Tier tier);

struct CaseSpec {
  std::string name;
  std::string algorithm;
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json input = nlohmann::json::object();
  nlohmann::json crop;     // null or [x, y, width, height]
  nlohmann::json expect;   // null or {"cells": [...], "total": ..., "tolerance": ...}
  std::string origin;      // the case file it came from, or "command line"
  Tier tier = Tier::report;
  // One side of a case file's A/B pair: the entry's name, "a" or "b", and that side's parameters
  // (also merged into params); empty for other cases.
  std::string ab_pair;
  std::string ab_side;
  nlohmann::json ab_params;
};

// Every case of every *.json in `folder`, in file-name order then file order. Throws InputError
// for malformed files and for duplicate names.
std::vector<CaseSpec> load_cases(const std::filesystem::path& folder);

// The bundled cases of `folder` plus those of each extra path (a case file or a folder of them,
// `groundtruth run --cases`); a name used twice is refused. An extra case's relative input paths
// ("file", "mesh", "volume", "global_grid") resolve against its case file's folder, the bundled
// ones' against datasets/.
std::vector<CaseSpec> load_suite(const std::filesystem::path& folder, const std::vector<std::filesystem::path>& extra);

// The case (or, for an entry with "ab", the A and B cases) of one case file entry.
std::vector<CaseSpec> cases_from_json(const nlohmann::json& entry, const std::string& origin);

// `text` (a file name, an algorithm) as one part of a dotted case name: lower case, every other
// character '_', at most 100 characters, "input" when empty.
std::string case_name_part(const std::string& text);

// The cases of `tier` and of the tiers it holds, in load order.
std::vector<CaseSpec> cases_in_tier(const std::vector<CaseSpec>& cases, Tier tier);

// Whether `name` matches one of the shell-style `patterns` (fnmatch); true when there are none.
bool named_by_any(const std::vector<std::string>& patterns, const std::string& name);

// The cases whose names match any of the shell-style patterns (fnmatch), in load order.
// Throws InputError when a pattern matches nothing, listing how to see the names.
std::vector<CaseSpec> select_cases(const std::vector<CaseSpec>& cases, const std::vector<std::string>& patterns);

}  // namespace gt
