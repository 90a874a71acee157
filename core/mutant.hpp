// Mutants: deliberate bugs that prove a check can fail (issue 11). At most one mutant is active
// per process; none unless a run names one (`groundtruth run --mutant NAME`, which the
// `groundtruth mutants` command uses for each registered mutant in a worker process).
//
// The registry of names, families, kinds and the cases that must kill each mutant lives in
// compare/mutants/ (one file per family). What lives here is only the switch both twins read:
//   - a reference tests `mutant_active("erosion.thermal.swapped_gather")` where its bug goes;
//   - every shader compiled while a mutant is active gets `#define GT_MUTANT_<NAME>` after its
//     #version line (gpu/shader_program.cpp), NAME in capitals with '.' as '_', e.g.
//     GT_MUTANT_EROSION_THERMAL_SWAPPED_GATHER; a shader tests it with #ifdef.
// Mutant names are dotted lower-case identifiers: family.algorithm.what.
#pragma once

#include <string>
#include <string_view>

namespace gt {

// The active mutant's name, empty when none.
const std::string& active_mutant();

namespace detail {
// Whether any mutant is active; set only by set_active_mutant. Read inline so that the references'
// checks cost one load per call when none is (noise functions test a mutant per corner).
extern bool any_mutant_active;
bool is_active_mutant(std::string_view name);
}  // namespace detail

// Whether `name` is the active mutant.
inline bool mutant_active(std::string_view name) {
  return detail::any_mutant_active && detail::is_active_mutant(name);
}

// Activates `name` for the rest of the process (empty: none). Throws InputError for a name that
// is not a dotted lower-case identifier; whether it is registered is the caller's business.
void set_active_mutant(const std::string& name);

// The shader define of a mutant name: "erosion.pipe.half_rain" -> "GT_MUTANT_EROSION_PIPE_HALF_RAIN".
std::string mutant_define(std::string_view name);

}  // namespace gt
