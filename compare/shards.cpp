// Sharding and merging; see compare/shards.hpp.
#include "compare/shards.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <numeric>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/output_folder.hpp"
#include "compare/provenance.hpp"
#include "compare/report/report_read.hpp"
#include "compare/report/writers.hpp"
#include "compare/report_diff.hpp"
#include "core/errors.hpp"
#include "core/io/text_file.hpp"
#include "core/memory.hpp"
#include "core/wording.hpp"

namespace gt {
namespace {

std::optional<long> whole_number(const std::string& text) {
  if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stol(text);
}

ShardSpec checked_shard(std::optional<long> index, std::optional<long> count, const std::string& what) {
  if (!index || !count || *count < 1 || *count > max_shard_count || *index < 1 || *index > *count) {
    throw InputError(fmt::format("--shard {}: expected K/N with 1 <= K <= N <= {} (K counts from 1)", what, max_shard_count));
  }
  return {static_cast<int>(*index), static_cast<int>(*count)};
}

std::optional<std::string> variable(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? std::optional<std::string>(value) : std::nullopt;
}

ShardSpec shard_from_environment() {
  if (const auto id = variable("SLURM_ARRAY_TASK_ID")) {
    const auto count = variable("SLURM_ARRAY_TASK_COUNT"), first = variable("SLURM_ARRAY_TASK_MIN");
    const auto step = variable("SLURM_ARRAY_TASK_STEP");
    const auto id_number = whole_number(*id), first_number = first ? whole_number(*first) : std::optional<long>(0);
    const auto step_number = step ? whole_number(*step) : std::optional<long>(1);
    std::optional<long> index;
    if (id_number && first_number && step_number && *step_number > 0 && *id_number >= *first_number &&
        (*id_number - *first_number) % *step_number == 0) {
      index = (*id_number - *first_number) / *step_number + 1;  // --array=MIN-MAX[:STEP]; a list (1,2,4) is refused
    }
    return checked_shard(index, count ? whole_number(*count) : std::nullopt,
                         fmt::format("auto (Slurm: SLURM_ARRAY_TASK_ID={}, SLURM_ARRAY_TASK_COUNT={}, "
                                     "SLURM_ARRAY_TASK_MIN={}, SLURM_ARRAY_TASK_STEP={}; submit --array=1-N)",
                                     *id, count.value_or("unset"), first.value_or("unset"), step.value_or("unset")));
  }
  if (const auto index = variable("CI_NODE_INDEX")) {
    const auto count = variable("CI_NODE_TOTAL");
    return checked_shard(whole_number(*index), count ? whole_number(*count) : std::nullopt,
                         fmt::format("auto (GitLab: CI_NODE_INDEX={}, CI_NODE_TOTAL={})", *index, count.value_or("unset")));
  }
  if (const auto index = variable("JOB_COMPLETION_INDEX")) {
    const auto count = variable("GROUNDTRUTH_SHARD_COUNT");
    const auto zero_based = whole_number(*index);
    return checked_shard(zero_based ? std::optional<long>(*zero_based + 1) : std::nullopt,
                         count ? whole_number(*count) : std::nullopt,
                         fmt::format("auto (Kubernetes: JOB_COMPLETION_INDEX={}, GROUNDTRUTH_SHARD_COUNT={})", *index,
                                     count.value_or("unset: set it to the Job's completions")));
  }
  throw InputError("--shard auto: no job array found (SLURM_ARRAY_TASK_ID, CI_NODE_INDEX or JOB_COMPLETION_INDEX); "
                   "give --shard K/N");
}

// Baseline case times in seconds, by name (cases without a recorded time are left out).
std::map<std::string, double> baseline_seconds(const nlohmann::json& baseline) {
  std::map<std::string, double> seconds;
  if (baseline.is_null()) return seconds;
  for (const auto& entry : baseline.value("cases", nlohmann::json::array())) {
    if (entry.contains("seconds") && entry["seconds"].is_number() && entry.contains("name")) {
      seconds[entry["name"].get<std::string>()] = entry["seconds"].get<double>();
    }
  }
  return seconds;
}

}  // namespace

ShardSpec parse_shard(const std::string& text) {
  if (text == "auto") return shard_from_environment();
  const auto slash = text.find('/');
  if (slash == std::string::npos) return checked_shard(std::nullopt, std::nullopt, "'" + text + "'");
  return checked_shard(whole_number(text.substr(0, slash)), whole_number(text.substr(slash + 1)), "'" + text + "'");
}

std::uint64_t stable_hash(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a, 64 bits
  for (unsigned char byte : text) {
    hash ^= byte;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::vector<int> assign_shards(const std::vector<std::string>& names, int count, const nlohmann::json& baseline) {
  std::vector<int> shard(names.size());
  for (std::size_t index = 0; index < names.size(); ++index) {
    shard[index] = 1 + static_cast<int>(stable_hash(names[index]) % static_cast<std::uint64_t>(count));
  }
  const auto seconds = baseline_seconds(baseline);
  std::vector<std::size_t> timed;
  for (std::size_t index = 0; index < names.size(); ++index) {
    if (seconds.contains(names[index])) timed.push_back(index);
  }
  std::stable_sort(timed.begin(), timed.end(), [&](std::size_t a, std::size_t b) {
    return seconds.at(names[a]) > seconds.at(names[b]) || (seconds.at(names[a]) == seconds.at(names[b]) && names[a] < names[b]);
  });
  std::vector<double> load(static_cast<std::size_t>(count), 0.0);
  for (std::size_t index : timed) {
    const auto least = std::min_element(load.begin(), load.end()) - load.begin();
    shard[index] = static_cast<int>(least) + 1;
    load[static_cast<std::size_t>(least)] += seconds.at(names[index]);
  }
  return shard;
}

namespace {

std::filesystem::path shard_folder(const std::filesystem::path& given) {
  return std::filesystem::is_directory(given) ? given : given.parent_path();
}

// Every shard's report is held at once, then joined and written: weighed together before the
// first is read, at the parse's 40 B a byte for each (an upper bound of what a report keeps).
void require_merge_memory(const std::vector<std::filesystem::path>& given) {
  double bytes = 0.0;
  for (const auto& shard : given) {
    std::error_code error;
    const auto size = std::filesystem::file_size(shard_folder(shard) / "report.json", error);
    if (!error) bytes += static_cast<double>(size);  // else the reader names what is wrong
  }
  require_memory(memory_for(bytes, "bytes of shard reports", json_document_limits.parse_bytes_per_byte), "merge");
}

struct LoadedShard {
  std::filesystem::path folder;
  Report report;
};

LoadedShard load_shard(const std::filesystem::path& given) {
  const auto folder = shard_folder(given);
  LoadedShard shard{folder, read_report(folder / "report.json")};
  if (!shard.report.shard) {
    throw InputError(fmt::format("merge: {} is not a shard's report (it was not run with --shard)", folder.string()));
  }
  return shard;
}

// A complete, consistent set: the same selection and count, each index once, each case once.
void check_shard_set(const std::vector<LoadedShard>& shards) {
  const ShardInfo& first = *shards.front().report.shard;
  std::map<int, std::filesystem::path> by_index;
  std::map<std::string, std::filesystem::path> case_owner;
  for (const auto& shard : shards) {
    const ShardInfo& info = *shard.report.shard;
    if (info.count != first.count || info.selection != first.selection || info.balanced_by != first.balanced_by) {
      throw InputError(fmt::format("merge: {} and {} are shards of different runs (another selection, count or "
                                   "balancing)", shards.front().folder.string(), shard.folder.string()));
    }
    if (!by_index.emplace(info.index, shard.folder).second) {
      throw InputError(fmt::format("merge: shard {}/{} is given twice ({} and {})", info.index, info.count,
                                   by_index[info.index].string(), shard.folder.string()));
    }
    for (const auto& result : shard.report.cases) {
      if (!case_owner.emplace(result.name, shard.folder).second) {
        throw InputError(fmt::format("merge: case {} is in two shards ({} and {})", result.name,
                                     case_owner[result.name].string(), shard.folder.string()));
      }
    }
  }
  std::vector<int> missing;
  for (int index = 1; index <= first.count; ++index) {
    if (!by_index.contains(index)) missing.push_back(index);
  }
  if (!missing.empty()) {
    throw InputError(fmt::format("merge: {} {} of {} {} missing; a merged report must hold every shard",
                                 missing.size() == 1 ? "shard" : "shards", fmt::join(missing, ", "), first.count,
                                 missing.size() == 1 ? "is" : "are"));
  }
  for (const auto& name : first.selection) {
    if (!case_owner.contains(name)) throw InputError(fmt::format("merge: no shard holds case {}", name));
  }
  if (case_owner.size() != first.selection.size()) {
    throw InputError("merge: the shards hold cases outside their selection");
  }
}

Report joined_report(const std::vector<LoadedShard>& shards, const std::string& command_line) {
  Report joined;
  joined.environment = shards.front().report.environment;
  joined.environment.command_line = command_line;
  std::map<std::string, const CaseResult*> cases;
  for (const auto& shard : shards) {
    merge_digests(joined.environment, shard.report.environment);
    joined.environment.run_started = std::min(joined.environment.run_started, shard.report.environment.run_started);
    for (const auto& result : shard.report.cases) cases[result.name] = &result;
    for (const auto& problem : shard.report.expectation_problems) joined.expectation_problems.push_back(problem);
  }
  for (const auto& name : shards.front().report.shard->selection) joined.cases.push_back(*cases.at(name));
  return joined;
}

// Copies a shard's case folder, files and folders only: a symbolic link or another special file is
// refused, since a report folder holds none and following one would copy what lies outside the
// shard into the merged report.
void copy_case_folder(const std::filesystem::path& from, const std::filesystem::path& to) {
  const auto refuse = [](const std::filesystem::path& entry, const std::filesystem::file_status& kind) {
    throw InputError(fmt::format("merge: {} is {}; a shard's report holds only files and folders", entry.string(),
                                 std::filesystem::is_symlink(kind) ? "a symbolic link" : "not a plain file"));
  };
  const auto kind = std::filesystem::symlink_status(from);
  if (!std::filesystem::exists(kind)) return;  // a case that wrote no files
  if (!std::filesystem::is_directory(kind)) refuse(from, kind);
  std::filesystem::create_directory(to);
  for (const auto& entry : std::filesystem::recursive_directory_iterator(from)) {
    const auto target = to / entry.path().lexically_relative(from);
    const auto entry_kind = entry.symlink_status();
    if (std::filesystem::is_directory(entry_kind)) {
      std::filesystem::create_directory(target);
    } else if (std::filesystem::is_regular_file(entry_kind)) {
      std::filesystem::copy_file(entry.path(), target);
    } else {
      refuse(entry.path(), entry_kind);
    }
  }
}

}  // namespace

int merge_shards(const MergeOptions& options, const std::string& command_line) {
  if (options.shards.empty()) throw InputError("merge: name the shards' report folders");
  for (const auto& given : options.shards) refuse_input_inside_output(options.out, given, "merge");
  require_merge_memory(options.shards);
  std::vector<LoadedShard> shards;
  for (const auto& given : options.shards) shards.push_back(load_shard(given));
  check_shard_set(shards);
  check_output_folder(options.out);
  const Report joined = joined_report(shards, command_line);
  write_folder_atomically(options.out, [&](const std::filesystem::path& folder) {
    for (const auto& shard : shards) {
      for (const auto& result : shard.report.cases) copy_case_folder(shard.folder / result.name, folder / result.name);
    }
    write_report_files(joined, folder);
  });
  if (!options.quiet) {
    fmt::print("groundtruth: merged {}, {}, into {}\n", counted(shards.size(), "shard"), counted(joined.cases.size(), "case"),
               (options.out / "index.html").string());
  }
  return run_failed(joined) ? 1 : 0;
}

}  // namespace gt
