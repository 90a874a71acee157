// Steps 2–3 of the Earth-like generator; see plates.hpp. The synchronous rule is the one both twins
// run; the legacy rule repeats the seed code's TectonicPlateModifier (digest 002 §4.4.2): its
// sequential first-come fill, with Algorithm 3 as coded (ceil(rate) + 1 expansions per cycle,
// erratum 10), on the same seeds and rates.
#include "reference/planet/plates.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/mutant.hpp"
#include "core/rng.hpp"

namespace gt::reference {
namespace {

float draw(const PlanetParams& params, int plate, std::uint32_t step, PlanetStream stream) {
  return uniform01(random_u32(params.seed, static_cast<std::uint32_t>(plate), step, stream));
}

std::vector<std::int32_t> seeded_plates(const PlanetParams& params) {
  std::vector<std::int32_t> plate(static_cast<std::size_t>(params.region_count()), invalid_region);
  const auto seeds = plate_seeds(params);
  for (std::size_t index = 0; index < seeds.size(); ++index) plate[seeds[index]] = static_cast<std::int32_t>(index);
  return plate;
}

// The lowest plate among the region's neighbours that is active in sub-step `substep`, or
// invalid_region.
std::int32_t lowest_active_plate(const CubeSphere& sphere, const std::vector<std::int32_t>& plate,
                                 const std::vector<int>& expansions, std::size_t region, int substep) {
  std::int32_t lowest = INT32_MAX;
  for (const std::int32_t neighbour : sphere.neighbours(region)) {
    if (neighbour == invalid_region) continue;
    const std::int32_t owner = plate[neighbour];
    if (owner != invalid_region && substep < expansions[owner]) lowest = std::min(lowest, owner);
  }
  return lowest == INT32_MAX ? invalid_region : lowest;
}

// The unassigned neighbours of `regions` not yet on the frontier, appended to it.
void extend_frontier(const CubeSphere& sphere, const std::vector<std::int32_t>& plate,
                     const std::vector<std::size_t>& regions, std::vector<std::uint8_t>& on_frontier,
                     std::vector<std::size_t>& frontier) {
  for (const std::size_t region : regions) {
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region || plate[neighbour] != invalid_region || on_frontier[neighbour]) continue;
      on_frontier[neighbour] = 1;
      frontier.push_back(static_cast<std::size_t>(neighbour));
    }
  }
}

// Only unassigned regions next to a plate can be claimed: each sub-step visits that frontier, not
// every unassigned region, so the fill costs O(N + Σ frontier) rather than O(N · cycles).
PlatePartition grow_synchronously(const CubeSphere& sphere, const PlanetParams& params) {
  PlatePartition partition;
  partition.plate = seeded_plates(params);
  const auto rates = plate_rates(params);
  const int max_expansions = plate_rate_bounds(params).max_expansions;
  // Counted, not taken as N − P: a seed placed twice (planet.plates.seeds_repeat) leaves one more.
  // Mutant planet.plates.seeds_counted_twice (both twins): the seeds counted again as the fill
  // starts, so it stops with P regions still unassigned.
  const std::size_t counted_again =
      mutant_active("planet.plates.seeds_counted_twice") ? static_cast<std::size_t>(params.plates) : 0;
  std::size_t unassigned =
      static_cast<std::size_t>(std::count(partition.plate.begin(), partition.plate.end(), invalid_region));
  unassigned -= std::min(unassigned, counted_again);
  std::vector<std::uint8_t> on_frontier(partition.plate.size(), 0);
  std::vector<std::size_t> frontier, claimed;
  const auto seeds = plate_seeds(params);
  extend_frontier(sphere, partition.plate, std::vector<std::size_t>(seeds.begin(), seeds.end()), on_frontier, frontier);
  std::vector<int> expansions(rates.size());
  std::vector<std::pair<std::size_t, std::int32_t>> claims;
  for (; unassigned > 0; ++partition.cycles) {
    for (int plate = 0; plate < params.plates; ++plate) {
      expansions[plate] = plate_expansions(params, rates, plate, partition.cycles);
    }
    for (int substep = 0; substep < max_expansions && unassigned > 0; ++substep) {
      claims.clear();
      for (const std::size_t region : frontier) {
        const std::int32_t owner = lowest_active_plate(sphere, partition.plate, expansions, region, substep);
        if (owner != invalid_region) claims.emplace_back(region, owner);
      }
      claimed.clear();
      for (const auto& [region, owner] : claims) {
        partition.plate[region] = owner;
        claimed.push_back(region);
      }
      unassigned -= std::min(unassigned, claims.size());
      std::erase_if(frontier, [&](std::size_t region) { return partition.plate[region] != invalid_region; });
      extend_frontier(sphere, partition.plate, claimed, on_frontier, frontier);
    }
  }
  return partition;
}

// The seed code's TectonicPlate: its edge list and whether it has stopped growing.
struct LegacyPlate {
  std::vector<std::int32_t> edge;
  bool finished = false;
};

// expand(): one BFS ring, first come first served (digest §4.4.2).
bool expand_legacy(const CubeSphere& sphere, std::int32_t index, LegacyPlate& plate, std::vector<std::int32_t>& plate_of) {
  if (plate.finished) return false;
  bool added = false;
  const std::size_t present = plate.edge.size();
  std::size_t position = 0;
  for (std::size_t visit = 0; visit < present; ++visit) {
    const std::int32_t region = plate.edge[position];
    bool on_edge = false;
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region) continue;
      if (plate_of[neighbour] == invalid_region) {
        plate_of[neighbour] = index;
        plate.edge.push_back(neighbour);
        added = true;
      } else if (plate_of[neighbour] != index) {
        on_edge = true;
      }
    }
    if (on_edge) {
      ++position;
    } else {
      plate.edge.erase(plate.edge.begin() + static_cast<std::ptrdiff_t>(position));
    }
  }
  if (!added) plate.finished = true;
  return added;
}

// stepExpandPlate as coded: "while rate > 0: expand; rate −= 1", returning when an expand adds
// nothing, then the extra expand that `random > rate` always allows. Whether the plate grew.
bool step_legacy(const CubeSphere& sphere, std::int32_t index, float rate, LegacyPlate& plate,
                 std::vector<std::int32_t>& plate_of) {
  bool grew = false;
  for (; rate > 0.0f; rate -= 1.0f) {
    if (!expand_legacy(sphere, index, plate, plate_of)) return grew;
    grew = true;
  }
  return expand_legacy(sphere, index, plate, plate_of) || grew;
}

// The state of the seed code's fill: the partition, the rates and each plate's edge list.
struct LegacyFill {
  PlatePartition partition;
  std::vector<float> rates;
  std::vector<LegacyPlate> plates;

  explicit LegacyFill(const PlanetParams& params) : rates(plate_rates(params)), plates(rates.size()) {
    partition.plate = seeded_plates(params);
    const auto seeds = plate_seeds(params);
    for (std::size_t index = 0; index < seeds.size(); ++index) plates[index].edge = {seeds[index]};
  }
  // stepExpandPlate of plate `index`; whether it grew.
  bool step(const CubeSphere& sphere, std::size_t index) {
    return step_legacy(sphere, static_cast<std::int32_t>(index), rates[index], plates[index], partition.plate);
  }
};

// randomDriven: one random plate per pick until every plate has finished.
PlatePartition grow_legacy_random(const CubeSphere& sphere, const PlanetParams& params) {
  LegacyFill fill(params);
  const auto all_finished = [&] {
    return std::all_of(fill.plates.begin(), fill.plates.end(), [](const LegacyPlate& plate) { return plate.finished; });
  };
  for (; !all_finished(); ++fill.partition.cycles) {
    fill.step(sphere, random_u32(params.seed, static_cast<std::uint32_t>(fill.partition.cycles), 0,
                                 planet_stream_random_driven) % fill.plates.size());
  }
  return fill.partition;
}

// Even mode: every plate in index order each cycle, until a cycle in which none grew.
PlatePartition grow_legacy(const CubeSphere& sphere, const PlanetParams& params) {
  LegacyFill fill(params);
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t index = 0; index < fill.plates.size(); ++index) grew = fill.step(sphere, index) || grew;
    if (grew) ++fill.partition.cycles;
  }
  return fill.partition;
}

}  // namespace

std::vector<std::int32_t> plate_seeds(const PlanetParams& params) {
  const auto region_count = static_cast<std::uint32_t>(params.region_count());
  std::vector<bool> taken(region_count, false);
  std::vector<std::int32_t> seeds;
  for (int plate = 0; plate < params.plates; ++plate) {
    std::uint32_t region = region_count;
    for (int attempt = 0; attempt < plate_seed_attempts && region == region_count; ++attempt) {
      const std::uint32_t candidate = random_u32(params.seed, static_cast<std::uint32_t>(plate),
                                                 static_cast<std::uint32_t>(attempt), planet_stream_plate_seed) %
                                      region_count;
      // Mutant planet.plates.seeds_repeat (both twins): the first draw is taken, free or not.
      if (!taken[candidate] || mutant_active("planet.plates.seeds_repeat")) region = candidate;
    }
    if (region == region_count) region = static_cast<std::uint32_t>(std::find(taken.begin(), taken.end(), false) - taken.begin());
    taken[region] = true;
    seeds.push_back(static_cast<std::int32_t>(region));
  }
  return seeds;
}

std::vector<float> plate_rates(const PlanetParams& params) {
  const PlateRateBounds bounds = plate_rate_bounds(params);
  std::vector<float> rates;
  for (int plate = 0; plate < params.plates; ++plate) {
    const float rate = bounds.low + (bounds.high - bounds.low) * draw(params, plate, 0, planet_stream_rate);
    rates.push_back(std::max(rate, minimum_plate_rate));
  }
  return rates;
}

int plate_expansions(const PlanetParams& params, const std::vector<float>& rates, int plate, int cycle) {
  // Mutant planet.plates.ceil_rate (both twins): whole rings rounded up, so no extra draw can win.
  const float whole = mutant_active("planet.plates.ceil_rate") ? std::ceil(rates[plate]) : std::floor(rates[plate]);
  const bool extra = draw(params, plate, static_cast<std::uint32_t>(cycle), planet_stream_expansion) < rates[plate] - whole;
  return static_cast<int>(whole) + (extra ? 1 : 0);
}

PlatePartition grow_plates(const CubeSphere& sphere, const PlanetParams& params) {
  PlatePartition partition = params.plate_rule == PlateRule::legacy          ? grow_legacy(sphere, params)
                             : params.plate_rule == PlateRule::legacy_random ? grow_legacy_random(sphere, params)
                                                                             : grow_synchronously(sphere, params);
  partition.is_edge = edge_regions(sphere, partition.plate);
  return partition;
}

std::vector<std::uint8_t> edge_regions(const CubeSphere& sphere, const std::vector<std::int32_t>& plate) {
  // Mutant planet.plates.edges_without_diagonals (both twins): only the 4 cardinal neighbours (even
  // places of the table) are looked at.
  const std::size_t stride = mutant_active("planet.plates.edges_without_diagonals") ? 2 : 1;
  std::vector<std::uint8_t> is_edge(plate.size(), 0);
  for (std::size_t region = 0; region < plate.size(); ++region) {
    const auto& around = sphere.neighbours(region);
    for (std::size_t place = 0; place < around.size(); place += stride) {
      if (around[place] != invalid_region && plate[around[place]] != plate[region]) is_edge[region] = 1;
    }
  }
  return is_edge;
}

}  // namespace gt::reference
