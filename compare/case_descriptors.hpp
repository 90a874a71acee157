// Terrain descriptors in every erosion and terrain case (issue 16): the descriptors
// (compare/descriptors/terrain_descriptors.hpp) of the case's input and of each twin's result,
// measured the same way on a real DEM for comparison, with their checks and plot.
//
// Checks:
//   parity.descriptors.gpu_vs_double   the twins agree on the statistics: the largest
//       difference of a continuous descriptor (HI, slope mean and percentiles, β) from ref<double>'s,
//       as a share of half the resolution at which that descriptor is quoted (ScalarDescriptor::
//       parity_resolution); passes up to 1 for a generated terrain (one evaluation per cell), shown
//       without a bound for the end of an iterated run (CaseTerrains::ends_of_a_run): half a table's
//       resolution is a presentation convention, not an error model of a chaotic run. Drainage
//       descriptors are shown, not judged (D8 is discontinuous in the heights).
//   fidelity.<descriptor>.{cpu,gpu}            for cases whose "expect" lists "fidelity": the distance
//       of the result's descriptor outside its target range from the literature (fidelity_targets()),
//       0 inside; `warn` outside (a terrain can be valid and still unlike Earth's), never `fail`.
// Case JSON: "expect": {"fidelity": true} turns the fidelity checks on and puts the case in the
// report's fidelity table.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "core/grid.hpp"

namespace gt {

// The terrains of one case; a missing one is nullptr (a generator has no "before"; no GPU).
struct CaseTerrains {
  const Heightmap* input = nullptr;
  const Grid<double>* cpu = nullptr;
  const Grid<double>* cpu_float = nullptr;
  const Grid<double>* gpu = nullptr;
  // The terrains are the ends of an iterated run (an eroder's many steps): rounding differences
  // grow along it by an amount no error model gives before the run, so the GPU's descriptors are
  // shown beside ref<double>'s (parity.descriptors.gpu_vs_double informative), not graded; the
  // shadow steps grade the twin step by step.
  bool ends_of_a_run = false;
};

struct FidelityTarget {
  std::string descriptor;  // a ScalarDescriptor name
  double low = 0.0;
  double high = 0.0;
  std::string source;      // where the range comes from
};

const std::vector<FidelityTarget>& fidelity_targets();

// Memory the descriptors of a case's terrains add to its peak, per cell: measured as the peak RSS
// of `groundtruth stats` on 512² and 1024² fBm EXRs (86.5 MB over 786,432 more cells: 110 B, the
// file read included), plus the two double copies of the float results a case makes (18 B with
// their masks), rounded up. Algorithms whose cases describe terrain add it to their estimates.
constexpr double descriptor_bytes_per_cell = 130.0;

// Whether a case reports descriptors: every erosion algorithm's case and every terrain.* case.
bool case_describes_terrain(const CaseResult& result);

// The keys of "expect" this adds: {"fidelity": true|false}.
nlohmann::json descriptor_expect_shape();

// The checks add_case_descriptors makes of a GPU terrain, by name: a caller whose GPU half did not
// run adds them as `skip`.
std::vector<std::string> descriptor_gpu_check_names(const nlohmann::json& expect);

// Sets result.descriptors, adds the checks above and (with a report folder) descriptors.png.
void add_case_descriptors(const CaseTerrains& terrains, const nlohmann::json& expect, const RunOptions& options,
                          CaseResult& result);

}  // namespace gt
