// `groundtruth specificity` (issue 38): the harness's own false-alarm rate, measured. Mutation
// testing shows that the checks fail on bugs (sensitivity); this shows that they pass honest code:
// each stepping algorithm is run, as it is, with N parameter sets drawn from plausible sub-ranges
// of its declared ranges, on two real inputs, and every `fail` or `error` is a false alarm of the
// harness (or a real bug the suite's own cases do not reach: the page names the run to rerun).
//
// make_specificity draws the sets: seeded with the counter-based RNG (core/rng.hpp), so a seed and
// a count give the same sets on every machine; a parameter not named in the plausible table keeps
// its default. Each (algorithm, set, input) is an ad-hoc case named
// specificity.<algorithm>.<input>.set_<nn>, run by the driver like a sweep's variants (with -j in
// workers). The plausible sub-ranges are declared in specificity.cpp beside the algorithms' names:
// ranges a user would set on purpose (a stable time step, a talus angle that moves material, ...),
// each inside the declared range; log-uniform where they span decades.
//
// write_specificity_summary, after the runs, writes specificity.json and specificity.html into the
// report folder: per algorithm the runs and their outcomes, specificity = 1 − (fail + error)/runs,
// and each false alarm with its parameters and failing checks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "compare/driver.hpp"

namespace gt {

// Algorithms with plausible sub-ranges declared, by name.
std::vector<std::string> specificity_algorithms();

// Throws InputError for a pattern that matches no such algorithm, or sets outside [1, 100].
Sweep make_specificity(const std::vector<std::string>& patterns, int sets, std::uint32_t seed);

void write_specificity_summary(const Sweep& sweep, Report& report, const std::filesystem::path& folder);

}  // namespace gt
