#include "compare/progress.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unistd.h>

#include <fmt/format.h>

namespace gt {
namespace {

double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

// At most this many failing checks are listed under a case's line; the report has them all.
constexpr std::size_t failing_checks_listed = 5;

}  // namespace

std::string human_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  if (seconds < 60.0) return fmt::format("{:.1f} s", seconds);
  const auto whole = static_cast<long>(std::lround(seconds));
  if (whole < 3600) return fmt::format("{} min {} s", whole / 60, whole % 60);
  return fmt::format("{} h {} min", whole / 3600, (whole % 3600) / 60);
}

Progress::Progress(int total_cases, ProgressOptions options)
    : options_(std::move(options)),
      terminal_(options_.terminal.value_or(isatty(fileno(options_.sink)) != 0)),
      total_cases_(total_cases),
      run_started_(Clock::now()),
      last_line_(Clock::now()) {
  options_.workers = std::max(1, options_.workers);
  if (!options_.quiet) heartbeat_thread_ = std::thread([this] { heartbeat_loop(); });
}

Progress::~Progress() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (heartbeat_thread_.joinable()) heartbeat_thread_.join();
}

void Progress::start_case(const std::string& name) {
  std::lock_guard lock(mutex_);
  const auto now = Clock::now();
  running_[name] = {now, "", now};
  current_ = name;
  started_index_[name] = ++started_count_;
  print_line(fmt::format("[case {}/{}] {}", started_count_, total_cases_, name), false);
}

void Progress::stage(const std::string& what) {
  std::lock_guard lock(mutex_);
  const auto found = running_.find(current_);
  if (found == running_.end()) return;
  const auto now = Clock::now();
  found->second.stage = what;
  found->second.stage_started = now;
  if (!terminal_ && now - last_line_ < options_.heartbeat) return;
  print_line(fmt::format("[case {}/{}] {}: {} (case {})", started_index_[current_], total_cases_, current_, what,
                         human_duration(seconds_between(found->second.started, now))),
             false);
}

void Progress::end_case(const std::string& name, std::optional<Outcome> outcome, double seconds,
                        const std::vector<std::string>& failing_checks, const std::string& remark) {
  std::lock_guard lock(mutex_);
  running_.erase(name);
  ended_seconds_[name] = seconds;
  if (outcome) ++outcome_counts_[*outcome];
  std::string text = fmt::format("{} {} in {}{} [{}]", outcome ? outcome_name(*outcome) : "done", name,
                                 human_duration(seconds), remark.empty() ? "" : " " + remark, tally());
  for (std::size_t index = 0; index < failing_checks.size() && index < failing_checks_listed; ++index) {
    text += "\n    " + failing_checks[index];
  }
  if (failing_checks.size() > failing_checks_listed) {
    text += fmt::format("\n    and {} more failing checks (the report lists them)", failing_checks.size() - failing_checks_listed);
  }
  print_line(text, true);
}

void Progress::end_case(const CaseResult& result) {
  auto failing = failing_checks(result);
  if (!result.error.empty()) failing.insert(failing.begin(), "error: " + result.error);
  end_case(result.name, result.status, result.seconds, failing, options_.remark ? options_.remark(result) : "");
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (terminal_ && !options_.quiet) {
    fmt::print(options_.sink, "\r\033[K");
    std::fflush(options_.sink);
  }
}

std::optional<double> Progress::eta_seconds() const {
  std::lock_guard lock(mutex_);
  return eta_locked(Clock::now());
}

std::string Progress::tally() const {
  std::string counts;
  for (const auto& [outcome, count] : outcome_counts_) {
    counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", count, outcome_name(outcome));
  }
  const auto now = Clock::now();
  const auto eta = eta_locked(now);
  return fmt::format("{}/{}{}{}; {}{}", ended_seconds_.size(), total_cases_, counts.empty() ? "" : ": ", counts,
                     human_duration(seconds_between(run_started_, now)),
                     eta && *eta > 0.0 ? ", ETA " + human_duration(*eta) : "");
}

std::optional<double> Progress::eta_locked(Clock::time_point now) const {
  const int left = total_cases_ - static_cast<int>(ended_seconds_.size());
  if (left <= 0) return 0.0;
  // How the ended cases compared with what was expected of them (1 when none was expected).
  double expected_of_ended = 0.0;
  double actual_of_ended = 0.0;
  for (const auto& [name, seconds] : ended_seconds_) {
    if (const auto found = options_.expected.find(name); found != options_.expected.end() && found->second > 0.0) {
      expected_of_ended += found->second;
      actual_of_ended += seconds;
    }
  }
  const double pace = expected_of_ended > 0.0 ? actual_of_ended / expected_of_ended : 1.0;
  double per_unknown = 0.0;
  if (const auto mean = mean_expected_seconds(options_.planned, options_.expected)) {
    per_unknown = *mean;
  } else if (!ended_seconds_.empty()) {
    per_unknown = std::accumulate(ended_seconds_.begin(), ended_seconds_.end(), 0.0,
                                  [](double sum, const auto& entry) { return sum + entry.second; }) /
                  static_cast<double>(ended_seconds_.size());
  } else {
    return std::nullopt;
  }
  double remaining = 0.0;
  int counted = 0;
  for (const auto& name : options_.planned) {
    if (ended_seconds_.count(name) != 0) continue;
    const auto found = options_.expected.find(name);
    double expected = found != options_.expected.end() ? found->second * pace : per_unknown;
    if (const auto running = running_.find(name); running != running_.end()) {
      expected = std::max(0.0, expected - seconds_between(running->second.started, now));
    }
    remaining += expected;
    ++counted;
  }
  remaining += std::max(0, left - counted) * per_unknown;  // cases not named in `planned`
  return remaining / options_.workers;
}

void Progress::print_line(const std::string& text, bool permanent) {
  if (options_.quiet) return;
  last_line_ = Clock::now();
  if (terminal_) {
    fmt::print(options_.sink, "\r\033[K{}{}", text, permanent ? "\n" : "");
  } else {
    fmt::print(options_.sink, "groundtruth: {}\n", text);
  }
  std::fflush(options_.sink);
}

void Progress::heartbeat_loop() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    const auto due = last_line_ + options_.heartbeat;
    if (wake_.wait_until(lock, due, [this] { return stopping_; })) return;
    const auto now = Clock::now();
    if (now < last_line_ + options_.heartbeat || running_.empty()) {
      if (running_.empty()) last_line_ = now;  // nothing runs: no line is owed
      continue;
    }
    std::string cases;
    for (const auto& [name, running] : running_) {
      cases += fmt::format("{}{}{}{} (case {}{})", cases.empty() ? "" : "; ", name, running.stage.empty() ? "" : ": ",
                           running.stage, human_duration(seconds_between(running.started, now)),
                           running.stage.empty()
                               ? ""
                               : ", stage " + human_duration(seconds_between(running.stage_started, now)));
    }
    print_line(fmt::format("still running {} [{}]", cases, tally()), false);
  }
}

}  // namespace gt
