#include "compare/benchmark_table.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace gt {
namespace {

bool timed(const BenchmarkRow& row) { return row.note.empty() && row.median_ms > 0.0; }

bool is_probe(const BenchmarkRow& row) { return row.algorithm == bandwidth_probe_name; }

// Bytes per millisecond of the probe on `row`'s backend and device, or 0 when there is none.
double bandwidth_for(const BenchmarkRow& row, const std::vector<BenchmarkRow>& rows) {
  for (const BenchmarkRow& probe : rows) {
    if (is_probe(probe) && timed(probe) && probe.bytes_per_cell && probe.backend == row.backend &&
        probe.device == row.device) {
      return *probe.bytes_per_cell * benchmark_work(probe) / probe.median_ms;
    }
  }
  return 0.0;
}

const BenchmarkRow* fastest_peer(const BenchmarkRow& row, const std::vector<BenchmarkRow>& rows) {
  const BenchmarkRow* fastest = nullptr;
  for (const BenchmarkRow& peer : rows) {
    if (peer.peer.empty() || !timed(peer) || peer.algorithm != row.algorithm || peer.size != row.size ||
        peer.dimensions != row.dimensions) {
      continue;
    }
    if (fastest == nullptr || peer.median_ms < fastest->median_ms) fastest = &peer;
  }
  return fastest;
}

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mean_x += x[i] / n;
    mean_y += y[i] / n;
  }
  double covariance = 0.0;
  double variance = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    covariance += (x[i] - mean_x) * (y[i] - mean_y);
    variance += (x[i] - mean_x) * (x[i] - mean_x);
  }
  return covariance / variance;
}

}  // namespace

double benchmark_work(const BenchmarkRow& row) {
  return std::pow(static_cast<double>(row.size), row.dimensions) * row.iterations;
}

void annotate_benchmarks(std::vector<BenchmarkRow>& rows) {
  for (BenchmarkRow& row : rows) {
    if (!timed(row)) continue;
    if (row.bytes_per_cell) {
      const double bytes_per_ms = bandwidth_for(row, rows);
      if (bytes_per_ms > 0.0) row.floor_ms = *row.bytes_per_cell * benchmark_work(row) / bytes_per_ms;
    }
    if (row.peer.empty() && !is_probe(row)) {
      if (const BenchmarkRow* peer = fastest_peer(row, rows)) {
        row.times_peer = row.median_ms / peer->median_ms;
        row.fastest_peer = peer->peer;
      }
    }
  }
}

std::vector<ScalingFit> fit_scaling(const std::vector<BenchmarkRow>& rows) {
  using Key = std::tuple<std::string, std::string, std::string, std::string, int>;
  std::map<Key, std::map<int, const BenchmarkRow*>> groups;  // one row per size: the last one
  std::vector<Key> order;
  for (const BenchmarkRow& row : rows) {
    if (!timed(row)) continue;
    const Key key{row.algorithm, row.backend, row.peer, row.device, row.dimensions};
    if (!groups.contains(key)) order.push_back(key);
    groups[key][row.size] = &row;
  }
  std::vector<ScalingFit> fits;
  for (const Key& key : order) {
    const auto& by_size = groups.at(key);
    if (static_cast<int>(by_size.size()) < scaling_min_sizes) continue;
    ScalingFit fit{.algorithm = std::get<0>(key), .backend = std::get<1>(key), .peer = std::get<2>(key),
                   .device = std::get<3>(key), .dimensions = std::get<4>(key)};
    std::vector<double> log_work;
    std::vector<double> log_time;
    for (const auto& [size, row] : by_size) {
      fit.sizes.push_back(size);
      log_work.push_back(std::log(benchmark_work(*row)));
      log_time.push_back(std::log(row->median_ms));
    }
    fit.exponent = slope(log_work, log_time);
    fits.push_back(fit);
  }
  return fits;
}

}  // namespace gt
