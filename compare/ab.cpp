#include "compare/ab.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/report/images.hpp"
#include "compare/report/report_common.hpp"
#include "compare/sweep.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/json_keys.hpp"

namespace gt {
namespace {

using report_detail::case_anchor;
using report_detail::escape_markup;

std::string parameter_of(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError(fmt::format("'{}': expected name=value", assignment));
  }
  return assignment.substr(0, equals);
}

// The first ref<double> field a case wrote (compare/field_files.hpp), read back; nullopt when it
// wrote none.
std::optional<Heightmap> cpu_field(const std::filesystem::path& folder, const CaseResult& result) {
  const auto sidecar = folder / result.name / "fields.json";
  if (!std::filesystem::exists(sidecar)) return std::nullopt;
  std::ifstream in(sidecar);
  const nlohmann::json fields = parse_json_bounded(in, sidecar.string());
  for (const auto& file : fields.at("files")) {
    if (file.at("backend") == "cpu") {
      return read_heightmap(folder / result.name / (file.at("stem").get<std::string>() + ".exr")).heights;
    }
  }
  return std::nullopt;
}

struct MetricRow {
  std::string name;
  std::optional<double> a, b;
  bool moved() const { return a.has_value() != b.has_value() || (a && *a != *b); }
};

std::string number_cell(const std::optional<double>& value) { return value ? fmt::format("{:.6g}", *value) : "–"; }

// B - A, and how far that is from A (a relative change reads faster than two 6-digit numbers).
std::string change_cells(const MetricRow& row) {
  if (!row.a || !row.b) return "<td class=\"n\">–</td><td class=\"n\">–</td>";
  const double change = *row.b - *row.a;
  const std::string relative = *row.a != 0.0 ? fmt::format("{:+.3g} %", 100.0 * change / std::abs(*row.a)) : "–";
  return fmt::format("<td class=\"n\">{:.6g}</td><td class=\"n\">{}</td>", change, relative);
}

// The metrics as a reader takes them in: the results' terrain descriptors, then the checks, then
// the timings apart (one run each, so their differences are mostly noise); in each group the rows
// that moved first, most moved first (metrics_by_movement).
void write_metric_tables(std::ofstream& html, const std::vector<MetricRow>& rows) {
  struct Group {
    MetricGroup holds;
    const char* title;
    const char* note;
  };
  const Group groups[] = {
      {MetricGroup::descriptor, "Terrain descriptors of the results",
       "ref<double>'s result of each variant, measured as `groundtruth stats` does."},
      {MetricGroup::check, "Checks", "Each variant's checks (a check's outcome is in the report, linked above)."},
      {MetricGroup::timing, "Timings",
       "One run of each variant: differences within about 25 % are the machine's noise; time variants with "
       "`groundtruth bench` or repeated runs before reading a speed-up here."},
  };
  for (const Group& group : groups) {
    std::vector<const MetricRow*> members;
    for (const MetricRow& row : rows) {
      if (metric_group(row.name) == group.holds) members.push_back(&row);
    }
    if (members.empty()) continue;
    const auto moved = std::count_if(members.begin(), members.end(), [](const MetricRow* row) { return row->moved(); });
    html << "<h3>" << escape_markup(group.title) << "</h3>\n<p>" << escape_markup(group.note) << " " << moved << " of "
         << members.size() << " moved (highlighted).</p>\n<table><tr><th>metric</th><th>unit</th><th>A</th><th>B</th>"
         << "<th>B - A</th><th>change</th></tr>\n";
    for (const MetricRow* row : members) {
      const MetricLabel label = metric_label(row->name);
      html << "<tr" << (row->moved() ? " class=\"moved\"" : "") << "><td title=\"" << escape_markup(row->name) << "\">"
           << escape_markup(label.label) << "</td><td>" << escape_markup(label.unit) << "</td><td class=\"n\">"
           << number_cell(row->a) << "</td><td class=\"n\">" << number_cell(row->b) << "</td>" << change_cells(*row)
           << "</tr>\n";
    }
    html << "</table>\n";
  }
}

void write_page(const Sweep& ab, const CaseResult& a, const CaseResult& b, const std::vector<MetricRow>& rows,
                const std::optional<Artifact>& difference, const std::filesystem::path& folder) {
  std::ofstream html(folder / (ab.ab_stem + ".html"));
  html << report_detail::page_head("A/B of " + a.algorithm,
                                   std::string(report_detail::colour_bar_style) +
                                       "body{font-family:sans-serif}table{border-collapse:collapse}td,th{border:1px "
                                       "solid #ccc;padding:4px}td.n{text-align:right}img{width:320px;image-"
                                       "rendering:pixelated}tr.moved{background:#fff6d6}figure{margin:0}"
                                       ".colourbar,.scalebar{width:320px}")
       << "<h1>A/B of " << escape_markup(a.algorithm) << "</h1>\n<table><tr><th></th><th>A</th><th>B</th></tr>\n";
  const auto assignments = [](const AdHocCase& variant) {
    std::string text;
    for (const auto& assignment : variant.assignments) text += (text.empty() ? "" : ", ") + assignment;
    return escape_markup(text.empty() ? "defaults" : text);
  };
  html << "<tr><th>parameters</th><td>" << assignments(ab.variants[0]) << "</td><td>" << assignments(ab.variants[1])
       << "</td></tr>\n<tr><th>outcome</th><td><a href=\"index.html#" << case_anchor(a.name) << "\">"
       << outcome_name(a.status) << "</a></td><td><a href=\"index.html#" << case_anchor(b.name) << "\">"
       << outcome_name(b.status) << "</a></td></tr>\n<tr><th>result</th>";
  for (const CaseResult* result : {&a, &b}) {
    const std::string picture = result_picture(*result);
    html << "<td>" << (picture.empty() ? "" : "<img src=\"" + escape_markup(picture) + "\" alt=\"\">") << "</td>";
  }
  html << "</tr>\n</table>\n";
  if (difference) {
    html << "<figure><img src=\"" << escape_markup(difference->path) << "\" alt=\"B - A\">"
         << report_detail::colour_bar(difference->scale) << report_detail::scale_bar(difference->width_m)
         << "<figcaption>" << escape_markup(difference->caption) << "</figcaption></figure>\n";
  }
  html << "<h2>Metrics</h2>\n<p>The table as <a href=\"" << escape_markup(ab.ab_stem)
       << ".json\">JSON</a>; hover a metric for its key there.</p>\n";
  write_metric_tables(html, rows);
  html << "</body></html>\n";
}

}  // namespace

Sweep make_ab(const AdHocCase& base, const std::vector<std::string>& a, const std::vector<std::string>& b) {
  if (a.empty() && b.empty()) throw InputError("ab: give A's and B's parameters with --a name=value and --b name=value");
  std::vector<std::string> a_sorted = a, b_sorted = b;
  std::sort(a_sorted.begin(), a_sorted.end());
  std::sort(b_sorted.begin(), b_sorted.end());
  if (a_sorted == b_sorted) throw InputError("ab: A and B are the same variant; give them different parameters");
  for (const auto* side : {&a, &b}) {
    for (const auto& assignment : *side) {
      const std::string name = parameter_of(assignment);
      if (sets_parameter(base, name)) throw InputError(fmt::format("{} is both --set and --a/--b: choose one", name));
    }
  }
  const std::string input = ad_hoc_input_name(base);
  Sweep ab;
  ab.kind = SweepKind::ab;
  for (const auto& [label, assignments] : {std::pair{"a", &a}, std::pair{"b", &b}}) {
    AdHocCase variant = base;
    variant.assignments.insert(variant.assignments.end(), assignments->begin(), assignments->end());
    variant.name = fmt::format("ab.{}.{}.{}", base.algorithm, input, label);
    ab.variants.push_back(std::move(variant));
  }
  return ab;
}

void write_ab_summary(const Sweep& ab, Report& report, const std::filesystem::path& folder) {
  const auto find = [&](const AdHocCase& variant) -> const CaseResult* {
    for (const CaseResult& result : report.cases) {
      if (result.name == variant.name) return &result;
    }
    return nullptr;
  };
  const CaseResult* a = find(ab.variants[0]);
  const CaseResult* b = find(ab.variants[1]);
  if (a == nullptr || b == nullptr) return;  // a shard holds one of them only
  std::vector<MetricRow> rows;
  for (const auto& name : metrics_by_movement({a, b}, run_metric_names({a, b}))) {
    rows.push_back({name, run_metric(*a, name), run_metric(*b, name)});
  }
  std::stable_partition(rows.begin(), rows.end(), [](const MetricRow& row) { return row.moved(); });
  nlohmann::json table = {{"a", {{"case", a->name}, {"assignments", ab.variants[0].assignments},
                                 {"outcome", outcome_name(a->status)}}},
                          {"b", {{"case", b->name}, {"assignments", ab.variants[1].assignments},
                                 {"outcome", outcome_name(b->status)}}},
                          {"metrics", nlohmann::json::array()}};
  for (const MetricRow& row : rows) {
    const auto value = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    table["metrics"].push_back({{"name", row.name}, {"a", value(row.a)}, {"b", value(row.b)},
                                {"b_minus_a", row.a && row.b ? nlohmann::json(*row.b - *row.a) : nlohmann::json(nullptr)}});
  }
  std::optional<Artifact> difference;
  const auto field_a = cpu_field(folder, *a);
  const auto field_b = cpu_field(folder, *b);
  if (field_a && field_b && field_a->width == field_b->width && field_a->height == field_b->height) {
    const std::string picture = ab.ab_stem + "_difference.png";
    const DifferenceStats stats = write_difference_image(*field_a, *field_b, folder / picture);
    difference = Artifact{picture, "plot",
                          fmt::format("{}: B - A, ref<double>'s results: blue where B is lower, red where higher; "
                                      "rms {:.3g} (the page: {}.html)",
                                      ab.ab_stem, stats.rms, ab.ab_stem),
                          difference_scale(stats, field_a->vertical_unit),
                          map_width_m(field_a->width, field_a->cell_size_x)};
    table["difference"] = {{"max_abs", stats.max_abs}, {"rms", stats.rms}};
    report.plots.push_back(*difference);
  }
  write_file_atomically(folder / (ab.ab_stem + ".json"), table.dump(2) + '\n');
  write_page(ab, *a, *b, rows, difference, folder);
}

void write_case_ab_summaries(const std::vector<CaseSpec>& specs, Report& report, const std::filesystem::path& folder) {
  const auto assignments = [](const nlohmann::json& params) {
    std::vector<std::string> texts;
    for (const auto& [name, value] : params.items()) texts.push_back(assignment_text(name, value));
    return texts;
  };
  for (const CaseSpec& a : specs) {
    if (a.ab_side != "a") continue;
    const auto b = std::find_if(specs.begin(), specs.end(),
                                [&](const CaseSpec& spec) { return spec.ab_pair == a.ab_pair && spec.ab_side == "b"; });
    if (b == specs.end()) continue;  // a selection or a shard holding one side only
    Sweep pair;
    pair.kind = SweepKind::ab;
    pair.ab_stem = "ab." + a.ab_pair;
    for (const CaseSpec* side : {&a, &*b}) {
      AdHocCase variant;
      variant.algorithm = side->algorithm;
      variant.name = side->name;
      variant.assignments = assignments(side->ab_params);
      pair.variants.push_back(std::move(variant));
    }
    write_ab_summary(pair, report, folder);
  }
}

}  // namespace gt
