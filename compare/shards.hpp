// Sharding a run over machines (issue 15): `--shard K/N` runs the K-th of N parts of the selected
// cases, and `groundtruth merge` joins the N report folders into one.
//
// Assignment: a case goes to shard 1 + (FNV-1a-64(case name) mod N), so a case stays on its shard
// across commits whatever else is added or removed. With a baseline report (--baseline), the cases
// it timed are instead dealt out longest first, each to the shard with the least time so far
// (ties: the lowest shard), so that shards finish together; cases it did not time keep their hash.
// Every shard computes the same assignment from the same selection and baseline.
//
// `--shard auto` takes K and N from the engine running the job, the first found of:
//   SLURM_ARRAY_TASK_ID, _COUNT, _MIN, _STEP  (Slurm job arrays --array=MIN-MAX[:STEP]:
//                                              K = (ID - MIN) / STEP + 1; a list like 1,2,4 is refused)
//   CI_NODE_INDEX, CI_NODE_TOTAL                                      (GitLab CI `parallel:`, 1-based)
//   JOB_COMPLETION_INDEX, GROUNDTRUTH_SHARD_COUNT                     (Kubernetes Indexed Jobs, 0-based;
//                                                                      the manifest sets the count)
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

// The most shards a run may be split into (--shard K/N, and a shard record read back by merge).
inline constexpr int max_shard_count = 10000;

struct ShardSpec {
  int index = 1;  // K, 1-based
  int count = 1;  // N
};

// "K/N" with 1 <= K <= N <= 10000, or "auto" (the environment above). Throws InputError otherwise
// ("3/2", "0/0", "auto" outside a job array), naming what was read.
ShardSpec parse_shard(const std::string& text);

std::uint64_t stable_hash(const std::string& text);

// The shard (1..N) of each name, in the order given; `baseline` is a report.json or null.
std::vector<int> assign_shards(const std::vector<std::string>& names, int count, const nlohmann::json& baseline);

struct MergeOptions {
  std::vector<std::filesystem::path> shards;  // report folders (or their report.json)
  std::filesystem::path out;
  bool quiet = false;
};

// `groundtruth merge`: checks that the shards are one complete set (the same selection and count,
// each index once, each case exactly once) and writes the joined report into `out` atomically,
// cases in the selection's order, each case's folder copied. Throws InputError for a missing,
// duplicated or foreign shard (nothing is written). Returns the exit status a run would have.
int merge_shards(const MergeOptions& options, const std::string& command_line);

}  // namespace gt
