// The classic (material, thickness) stack and its talus (digest 001 §3.1, Fig. 3.1; rules in
// classic_stack.hpp). Units: metres.
#include "reference/erosion/layered/classic_stack.hpp"

#include <algorithm>
#include <array>

namespace gt::reference {
namespace {

using Slide = std::vector<ClassicLayer>;  // top first, as peeled

double movable(const std::vector<ClassicLayer>& column) {
  double sum = 0.0;
  for (std::size_t i = 1; i < column.size(); ++i) sum += column[i].thickness;
  return sum;
}

// Takes `amount` off the top of `column` (never its base), top layer first.
Slide peel(std::vector<ClassicLayer>& column, double amount) {
  Slide slide;
  while (amount > 0.0 && column.size() > 1) {
    ClassicLayer& top = column.back();
    const double part = std::min(amount, top.thickness);
    slide.push_back({top.material, part});
    top.thickness -= part;
    amount -= part;
    if (top.thickness <= 0.0) column.pop_back();
  }
  return slide;
}

bool homogeneous(const Slide& slide, int material) {
  return std::all_of(slide.begin(), slide.end(), [material](const ClassicLayer& layer) { return layer.material == material; });
}

void receive(std::vector<ClassicLayer>& column, const Slide& slide) {
  if (slide.empty()) return;
  if (homogeneous(slide, column.back().material)) {
    for (const auto& layer : slide) column.back().thickness += layer.thickness;
    return;
  }
  for (auto layer = slide.rbegin(); layer != slide.rend(); ++layer) column.push_back(*layer);
}

// Amounts column i sends to its left (0) and right (1) neighbours.
std::array<double, 2> outflow(const ClassicRow& row, std::size_t i, double time_step) {
  std::array<double, 2> amounts{};
  const double threshold = row.repose_tan.at(static_cast<std::size_t>(row.columns[i].back().material));
  const double height = classic_surface(row, i);
  for (int side = 0; side < 2; ++side) {
    const bool exists = side == 0 ? i > 0 : i + 1 < row.columns.size();
    if (!exists) continue;
    const double drop = height - classic_surface(row, side == 0 ? i - 1 : i + 1);
    if (drop > 0.0 && drop / row.cell_size >= threshold) amounts[static_cast<std::size_t>(side)] = time_step * drop * 0.5;
  }
  const double total = amounts[0] + amounts[1];
  const double available = movable(row.columns[i]);
  if (total > available) {
    for (double& amount : amounts) amount *= available / total;
  }
  return amounts;
}

}  // namespace

double classic_surface(const ClassicRow& row, std::size_t column) {
  double sum = 0.0;
  for (const auto& layer : row.columns[column]) sum += layer.thickness;
  return sum;
}

void classic_deposit(ClassicRow& row, std::size_t column, ClassicLayer layer) {
  receive(row.columns[column], Slide{layer});
}

void classic_talus_step(ClassicRow& row, double time_step) {
  const std::size_t count = row.columns.size();
  std::vector<std::array<double, 2>> amounts(count);
  for (std::size_t i = 0; i < count; ++i) amounts[i] = outflow(row, i, time_step);
  std::vector<std::array<Slide, 2>> slides(count);  // slides[i][side]: from i towards side
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t side = 0; side < 2; ++side) slides[i][side] = peel(row.columns[i], amounts[i][side]);
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) receive(row.columns[i], slides[i - 1][1]);
    if (i + 1 < count) receive(row.columns[i], slides[i + 1][0]);
  }
}

std::size_t classic_max_layers(const ClassicRow& row) {
  std::size_t most = 0;
  for (const auto& column : row.columns) most = std::max(most, column.size());
  return most;
}

}  // namespace gt::reference
