// Scaling laws of a drainage network: Hack's law (Hack 1957) on a D8 routing, and the exceedance
// probability of drainage area (Rodríguez-Iturbe & Rinaldo 1997) on D8 or D∞ areas.
//
// hack_fit(flow, min_area_m2) -> LineFit of ln L against ln A
//   flow       D8 routing (d8_flow); L = upstream_length_m (m), A = area_m2 (m²).
//   min_area_m2  the band: cells with A ≥ min_area_m2 (and L > 0). Choose it at or above the
//              stream threshold: below it the cells are hillslopes, where D8's parallel flow gives
//              L ∝ A (h = 1) and says nothing about the network. No upper bound: the trunk's
//              cells are the very points Hack measured.
//   slope      Hack's exponent h in L ∝ A^h (≈ 0.57 on real basins). nullopt with fewer than two
//              cells in the band or a single area among them.
//   Throws InputError when min_area_m2 is negative or not finite.
//
// exceedance_fit(area_m2, min_area_m2, max_area_m2) -> LineFit of ln P(A ≥ a) against ln a
//   area_m2    contributing area per cell (D8Flow::area_m2 or DinfFlow::area_m2), 0 for no-data.
//   P(A ≥ a) is the fraction of the valid cells (area_m2 > 0) whose area is at least a, sampled
//   at a_i = min·(max/min)^(i/(n−1)), i = 0..n−1, n = max(2, round(10·log10(max/min)) + 1):
//   ten points a decade, evenly spaced in ln a so every decade weighs the same in the fit.
//   Points where P = 0 are left out. Callers report −slope as the exponent (≈ 0.43 on real
//   basins). The band [min, max]: min above the hillslope scale (the stream threshold or some
//   tens of cells: below it P reflects hillslope lengths), max well below the largest basin
//   (a hundredth of the largest outlet's area, say: near the basin size P falls off faster than
//   the power law, the finite-size cut-off).
//   nullopt with fewer than two sampled points where P > 0.
//   Throws InputError unless 0 < min_area_m2 < max_area_m2, both finite.
#pragma once

#include <optional>
#include <vector>

#include "compare/descriptors/fit.hpp"
#include "compare/descriptors/flow_d8.hpp"

namespace gt {

std::optional<LineFit> hack_fit(const D8Flow& flow, double min_area_m2);

std::optional<LineFit> exceedance_fit(const std::vector<double>& area_m2, double min_area_m2, double max_area_m2);

}  // namespace gt
