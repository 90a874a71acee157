// The classic layered column of Beneš & Forsbach 2001 with the thesis's talus rules (digest 001 §3.1), CPU reference.
//
// A growing stack of (material, thickness) layers, kept minimal: only to show the failure of
// Fig. 3.1 (layer count growing without bound) that the fixed soil–rock model avoids. A row of
// columns (the figure's cross-section), 2 neighbours at distance l.
//   classic_surface(row, column) -> the column's surface height.
//   classic_deposit(row, column, layer): add a layer on top; merged into the top layer when of the
//     same material.
//   classic_talus_step(row, time_step): compute-then-apply. Column i, slope to neighbour j (Δh/l) ≥
//     tan φ of i's top material: the amount Δt·Δh/2 (eq. 3.3 without the random factor), clamped in
//     total to what lies above the column's first layer (the base). Apply: each donor peels its
//     amounts off its top, left neighbour first, each peel a slide of one or more (partial) layers;
//     each receiver takes its slides, left donor first: a homogeneous slide of its top material is
//     merged into the top layer, any other slide is stacked on top in its order (the thesis's
//     reading of BF01).
//   classic_max_layers(row) -> the largest layer count of the row's columns.
//
// Inputs:  ClassicRow: cell size l, tan φ per material (repose_tan), the columns bottom to top (layer
//          0 is the base); a layer's material indexes repose_tan.
// Outputs: the row, changed in place; the surface height and the largest layer count.
// Units:   metres; Δt in the units of eq. 3.3 (amount Δt·Δh/2).
// Throws:  std::out_of_range (std::vector::at) from classic_talus_step when a column's top material
//          has no entry in repose_tan.
// Twin:    none: no GPU twin, the classic stack is only the counter-example of Fig. 3.1 (tests), not
//          part of the compared model.
#pragma once

#include <cstddef>
#include <vector>

namespace gt::reference {

struct ClassicLayer {
  int material = 0;
  double thickness = 0.0;  // m
};

struct ClassicRow {
  double cell_size = 1.0;                          // l, m
  std::vector<double> repose_tan;                  // tan φ per material
  std::vector<std::vector<ClassicLayer>> columns;  // bottom to top; layer 0 is the base
};

double classic_surface(const ClassicRow& row, std::size_t column);
void classic_deposit(ClassicRow& row, std::size_t column, ClassicLayer layer);
void classic_talus_step(ClassicRow& row, double time_step);
std::size_t classic_max_layers(const ClassicRow& row);

}  // namespace gt::reference
