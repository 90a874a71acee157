// index.html: a self-contained static page (inline CSS, no JavaScript) for reading a report.
//
// Layout: header with the environment (GL renderer first and large), summary badges, a table of
// all cases linking to their sections; per case its notes, then for a rendered-image comparison
// (report_common.hpp image_comparison: cpu.png, gpu.png, gpu_vs_cpu[_heat].png, gpu_vs_cpu_mask.png)
// one row of up to four equal panels — reference, GPU (or why it did not run), difference and
// verdicts (where the case has them) —
// each titled and captioned, with the *.gpu_vs_cpu metrics under them as tiles coloured by
// outcome (PSNR in dB, shares in percent, channel differences in 8-bit levels); then its
// parameters (name and value pairs in columns), its other image artifacts in a row (intended order: before / after CPU / after GPU /
// difference, as the caller lists them), other artifacts as links, the checks table and the
// timings; then the Performance section with the benchmark table and the report-level plots.
// Every piece of text goes through escape_markup.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/report/report_common.hpp"
#include "compare/report/writers.hpp"
#include "core/io/atomic_file.hpp"
#include "core/wording.hpp"

namespace gt {

namespace {

using namespace report_detail;

constexpr std::string_view style = R"(
body { font: 14px/1.45 system-ui, sans-serif; color: #222; max-width: 1280px; margin: 0 auto; padding: 1em 2em; }
h1 { margin-bottom: .2em; }
.renderer { font-size: 1.35em; font-weight: 600; margin: .2em 0 .6em; }
table { border-collapse: collapse; margin: .6em 0 1em; }
th, td { border: 1px solid #ddd; padding: .25em .6em; text-align: left; vertical-align: top; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.environment th { width: 9em; }
.badge { display: inline-block; min-width: 3em; text-align: center; padding: .05em .6em; border-radius: .8em;
         color: #fff; font-weight: 600; font-size: .9em; }
.badge.pass { background: #2e7d32; } .badge.fail { background: #c62828; } .badge.warn { background: #f9a825; color: #222; }
.badge.skip { background: #757575; } .badge.inconclusive { background: #0277bd; } .badge.error { background: #6a1b9a; }
.badge.flaky { background: #ef6c00; } .badge.zero { opacity: .35; }
.badge.info { background: #eceff1; color: #37474f; border: 1px solid #b0bec5; }
.badge.expected { background: #fff; color: #555; border: 1px dashed #888; font-weight: 500; }
section.failures table td { font-size: .95em; } section.failures .detail { color: #444; }
body.only-attention section.case.pass { display: none; } body.only-attention tr.case-row.pass { display: none; }
label.filter { font-weight: 600; cursor: pointer; }
details.more { margin: .6em 0; } details.more > summary { cursor: pointer; color: #1f4f8f; }
.summary .badge { font-size: 1.05em; margin-right: .4em; }
section.case { border-top: 2px solid #e4e4e4; margin-top: 2em; }
.note { color: #555; font-style: italic; }
.wide { overflow-x: auto; max-width: 100%; }
.fidelity th small { font-weight: normal; }
.fidelity td.toward, .fidelity span.toward { background: #e3f1e4; } .fidelity td.away, .fidelity span.away { background: #f8d7d7; }
.devices { font-weight: 600; }
.performance td:last-child { min-width: 26em; } /* the note: a few lines, not a column of words */
.performance tr.peer td { background: #f3f6fb; } .performance tr.superlinear td { background: #fbeaea; }
pre.error { background: #fbeaea; padding: .6em; white-space: pre-wrap; }
.figures { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }
figure { margin: 0; }
figure img { width: 280px; height: auto; image-rendering: pixelated; border: 1px solid #ccc; }
figure.image { width: 280px; }
figure.plot img { width: 100%; max-width: 1100px; image-rendering: auto; }
figcaption { text-align: center; font-size: .9em; color: #444; }
dl.params { display: grid; grid-template-columns: repeat(auto-fill, minmax(250px, 1fr)); gap: 0 1.2em; margin: .6em 0 1em;
            font-size: .9em; }
dl.params div { display: flex; justify-content: space-between; gap: .8em; border-bottom: 1px solid #eee; padding: .1em 0; }
dl.params dt { color: #555; } dl.params dd { margin: 0; font-variant-numeric: tabular-nums; overflow-wrap: anywhere; }
.comparison { margin: .8em 0 1.2em; }
.panels { display: grid; grid-template-columns: repeat(4, minmax(0, 1fr)); gap: .8em; align-items: start; }
.panel { margin: 0; }
.panel .role { font-weight: 600; font-size: .95em; margin-bottom: .25em; }
.panel img { width: 100%; height: auto; image-rendering: pixelated; border: 1px solid #ccc; display: block; }
.panel figcaption { text-align: left; font-size: .82em; margin-top: .2em; }
.panel.missing .placeholder { border: 1px dashed #bbb; color: #666; padding: 1em; font-size: .9em; aspect-ratio: 4 / 3; }
.metrics { display: grid; grid-template-columns: repeat(auto-fill, minmax(190px, 1fr)); gap: .5em; margin-top: .7em; }
.metric { background: #f6f6f6; border-left: 4px solid #2e7d32; padding: .3em .6em; }
.metric.fail { border-color: #c62828; background: #fbeaea; } .metric.warn { border-color: #f9a825; }
.metric.info { border-color: #b0bec5; } .metric.error { border-color: #6a1b9a; } .metric.skip { border-color: #757575; } .metric.inconclusive { border-color: #0277bd; } .metric.flaky { border-color: #ef6c00; }
.metric .label { font-size: .82em; color: #555; }
.metric .value { font-size: 1.15em; font-weight: 600; font-variant-numeric: tabular-nums; }
.metric .bound { font-size: .8em; color: #555; }
)";

std::string h(std::string_view text) { return escape_markup(text); }


// A relative path as a URL: bytes other than unreserved characters and '/' are percent-encoded.
std::string url(std::string_view path) {
  std::string encoded;
  for (char c : path) {
    encoded += unreserved(c) || c == '/' ? std::string(1, c) : fmt::format("%{:02X}", static_cast<unsigned char>(c));
  }
  return encoded;
}

std::string badge(Outcome outcome) {
  return fmt::format("<span class=\"badge {0}\">{0}</span>", outcome_name(outcome));
}

bool strictly_worse(Outcome a, Outcome b) { return a != b && worse(a, b) == a; }

// A check's badge: a value shown without a bound is `info` (neutral), never a green pass; an
// outcome the expectation list names is marked `expected`, with its reason on hover.
bool shown_without_bound(const Check& check);

std::string check_badge(const Check& check) {
  if (shown_without_bound(check)) return "<span class=\"badge info\">info</span>";
  if (met_expectation(check) && check.status != Outcome::pass) {
    return fmt::format("{} <span class=\"badge expected\" title=\"{}\">expected</span>", badge(check.status),
                       h(check.expectation));
  }
  return badge(check.status);
}

// The checks a reader must look at, worst first (error, fail, flaky, skip, inconclusive, warn):
// anything but a pass or a check the user left out (--backend cpu). Stable, so a case's own order
// holds within an outcome.
std::vector<const Check*> checks_needing_attention(const CaseResult& result) {
  std::vector<const Check*> checks;
  for (const Check& check : result.checks) {
    if (check.status != Outcome::pass && !left_out_by_request(check)) checks.push_back(&check);
  }
  std::stable_sort(checks.begin(), checks.end(),
                   [](const Check* a, const Check* b) { return strictly_worse(a->status, b->status); });
  return checks;
}

std::string anchor(const CaseResult& result) { return case_anchor(result.name); }

void append_digests(std::string& out, const std::string& title, const std::map<std::string, std::string>& digests) {
  if (digests.empty()) return;
  out += fmt::format("<details><summary>{} {}</summary>\n<table class=\"digests\">\n", digests.size(), h(title));
  for (const auto& [name, digest] : digests) out += fmt::format("<tr><td>{}</td><td><code>{}</code></td></tr>\n", h(name), digest);
  out += "</table>\n</details>\n";
}

void append_header(std::string& out, const Report& report) {
  const Environment& environment = report.environment;
  // The headline names what was graded: the GL renderer our GPU twins ran on, or the outside
  // implementation that stood in their place (a candidate run never touches the GPU twin).
  out += "<header>\n<h1>groundtruth report</h1>\n";
  if (environment.graded.empty()) {
    out += fmt::format("<div class=\"renderer\">GL renderer: {}</div>\n", h(environment.gl_renderer));
  } else {
    out += fmt::format("<div class=\"renderer\">Graded in the GPU twin's place: {}</div>\n<p>GL renderer of the "
                       "references and comparisons: {}</p>\n",
                       h(environment.graded), h(environment.gl_renderer));
  }
  out += "<details class=\"more\"><summary>Environment, shaders and data files</summary>\n<table class=\"environment\">\n";
  for (const auto& [label, value] : environment_fields(environment)) {
    if (value->empty()) continue;  // no mutant, nothing graded but our own twins
    out += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", label, h(*value));
  }
  out += "</table>\n";
  append_digests(out, "shader stages compiled (SHA-256 after #include expansion)", environment.shaders);
  append_digests(out, "data files read (SHA-256)", environment.data);
  out += "</details>\n<p>Also as <a href=\"report.json\">report.json</a>, <a href=\"report.md\">report.md</a>, "
         "<a href=\"junit.xml\">junit.xml</a>.</p>\n</header>\n";
}

void append_summary(std::string& out, const Report& report) {
  const OutcomeCounts counts = count_case_outcomes(report);
  out += "<section class=\"summary\">\n<h2>Summary</h2>\n<p>";
  for (Outcome outcome : all_outcomes) {
    out += fmt::format("<span class=\"badge {}{}\">{} {}</span>", outcome_name(outcome),
                       counts[outcome] == 0 ? " zero" : "", counts[outcome], outcome_name(outcome));
  }
  const bool failed = run_failed(report) || (report.mutation && !report.mutation->passed());
  out += fmt::format("</p>\n<p>{}, expected failures: {}. Run <span class=\"badge {}\">{}</span></p>\n",
                     counted(counts.total(), "case"), counts.expected_failures, failed ? "fail" : "pass", failed ? "failed" : "ok");
  if (!report.scope.empty()) out += fmt::format("<p class=\"scope\">{}</p>\n", h(report.scope));
  out += "<p><label class=\"filter\"><input type=\"checkbox\" "
         "onchange=\"document.body.classList.toggle('only-attention', this.checked)\"> show only the cases that did "
         "not pass</label></p>\n</section>\n";
}

// What failed and why, before anything else (pytest's short summary): every check that did not pass,
// worst first and unexpected before expected, with its case, value, bound and the one-line reason;
// every case that ended in an error without a failing check to say why; and the skipped checks
// counted by their reason (a run without a GPU skips every GPU check: one line, not hundreds).
void append_failures(std::string& out, const Report& report) {
  struct Row {
    const CaseResult* result;
    const Check* check;
  };
  std::vector<Row> rows;
  std::vector<const CaseResult*> errors_without_checks;
  std::map<std::string, std::size_t> skipped_by_reason;
  std::size_t left_out = 0;
  for (const CaseResult& result : report.cases) {
    left_out += std::count_if(result.checks.begin(), result.checks.end(), left_out_by_request);
    const auto checks = checks_needing_attention(result);
    for (const Check* check : checks) {
      if (check->status == Outcome::skip) {
        ++skipped_by_reason[check->detail];
      } else {
        rows.push_back({&result, check});
      }
    }
    if (result.status == Outcome::error && checks.empty()) errors_without_checks.push_back(&result);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    if (met_expectation(*a.check) != met_expectation(*b.check)) return !met_expectation(*a.check);
    return strictly_worse(a.check->status, b.check->status);
  });
  out += "<section class=\"failures\">\n<h2>What did not pass, and why</h2>\n";
  if (left_out > 0) out += fmt::format("<p class=\"note\">Not run, as asked: {} ({}).</p>\n", counted(left_out, "check"), gpu_not_requested);
  for (const auto& [reason, count] : skipped_by_reason) {
    out += fmt::format("<p>{} {}: {}</p>\n", badge(Outcome::skip), counted(count, "check"), h(reason));
  }
  if (rows.empty() && errors_without_checks.empty()) {
    out += skipped_by_reason.empty() && left_out == 0 ? "<p>Every check passed.</p>\n</section>\n"
                                     : "<p>Every check that ran passed.</p>\n</section>\n";
    return;
  }
  for (const CaseResult* result : errors_without_checks) {
    out += fmt::format("<p>{} <a href=\"#{}\">{}</a>: {}</p>\n", badge(result->status), anchor(*result), h(result->name),
                       h(result->error.empty() ? "no check ran" : result->error.substr(0, result->error.find('\n'))));
  }
  if (!rows.empty()) {
    out += "<table>\n<tr><th>status</th><th>case</th><th>check</th><th>value</th><th>bound</th><th>why</th></tr>\n";
    for (const Row& row : rows) {
      out += fmt::format("<tr><td>{}</td><td><a href=\"#{}\">{}</a></td><td>{}</td><td class=\"num\">{}</td>"
                         "<td class=\"num\">{}</td><td class=\"detail\">{}</td></tr>\n",
                         check_badge(*row.check), anchor(*row.result), h(row.result->name), h(row.check->name),
                         format_value(row.check->value), h(format_bounds(*row.check)),
                         h(met_expectation(*row.check) ? row.check->expectation : row.check->detail));
    }
    out += "</table>\n";
  }
  out += "</section>\n";
}

// The names of a case's checks that failed or errored, for the Cases table: the first three and a count.
std::string failing_check_names(const CaseResult& result) {
  std::vector<std::string> names;
  for (const Check* check : checks_needing_attention(result)) {
    if (check->status == Outcome::fail || check->status == Outcome::error) names.push_back(check->name);
  }
  std::string text;
  for (std::size_t i = 0; i < std::min<std::size_t>(names.size(), 3); ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > 3) text += fmt::format(" and {} more", names.size() - 3);
  return text;
}

void append_case_table(std::string& out, const Report& report) {
  out += "<section>\n<h2>Cases</h2>\n<table>\n<tr><th>status</th><th>case</th><th>algorithm</th><th>input</th>"
         "<th>size</th><th>cpu ms</th><th>gpu ms</th><th>checks</th><th>failing checks</th></tr>\n";
  for (const CaseResult& result : report.cases) {
    out += fmt::format(
        "<tr class=\"case-row {}\"><td>{}{}</td><td><a href=\"#{}\">{}</a></td><td>{}</td><td>{}</td><td class=\"num\">{}</td>"
        "<td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td><td>{}</td></tr>\n",
        outcome_name(result.status), badge(result.status),
        result.expected_failure.empty() ? "" : " <span class=\"badge expected\">expected</span>", anchor(result),
        h(result.name), h(result.algorithm), h(result.input), h(case_size_text(result)), format_ms(result.timings.cpu_ms),
        format_ms(result.timings.gpu_ms), h(format_counts(count_check_outcomes(result), " · ")),
        h(failing_check_names(result)));
  }
  out += "</table>\n</section>\n";
}

void append_params(std::string& out, const nlohmann::json& params) {
  if (!params.is_object()) {
    out += fmt::format("<pre>{}</pre>\n", h(params.dump(2, ' ', false, nlohmann::json::error_handler_t::replace)));
    return;
  }
  if (params.empty()) return;
  out += "<dl class=\"params\">\n";
  for (const auto& [key, value] : params.items()) {
    const std::string text =
        value.is_string() ? value.get<std::string>() : value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    out += fmt::format("<div><dt>{}</dt><dd>{}</dd></div>\n", h(key), h(text));
  }
  out += "</dl>\n";
}

void append_figure(std::string& out, const Artifact& artifact, std::string_view figure_class) {
  out += fmt::format("<figure class=\"{}\"><a href=\"{}\"><img loading=\"lazy\" src=\"{}\" alt=\"{}\"></a>{}"
                     "<figcaption>{}</figcaption></figure>\n",
                     figure_class, url(artifact.path), url(artifact.path), h(artifact.caption),
                     colour_bar(artifact.scale) + scale_bar(artifact.width_m), h(artifact.caption));
}

void append_panel(std::string& out, std::string_view role, const Artifact* artifact, std::string_view missing) {
  if (!artifact) {
    out += fmt::format("<figure class=\"panel missing\"><div class=\"role\">{}</div><div class=\"placeholder\">{}</div>"
                       "</figure>\n",
                       h(role), h(missing));
    return;
  }
  out += fmt::format("<figure class=\"panel\"><div class=\"role\">{}</div><a href=\"{}\"><img loading=\"lazy\" src=\"{}\" alt=\"{}\"></a>"
                     "{}<figcaption>{}</figcaption></figure>\n",
                     h(role), url(artifact->path), url(artifact->path), h(artifact->caption),
                     colour_bar(artifact->scale) + scale_bar(artifact->width_m), h(artifact->caption));
}

void append_comparison(std::string& out, const ImageComparison& comparison) {
  const std::string not_run = comparison.gpu_missing_reason.empty() ? "not run" : "not run: " + comparison.gpu_missing_reason;
  out += "<div class=\"comparison\">\n<div class=\"panels\">\n";
  append_panel(out, "Reference (CPU)", comparison.reference, "");
  append_panel(out, comparison.twin == "gpu" ? "GPU" : "Candidate", comparison.gpu, not_run);
  if (comparison.difference) append_panel(out, "Difference", comparison.difference, "");
  if (comparison.mask) append_panel(out, "Verdicts", comparison.mask, "");
  out += "</div>\n";
  if (!comparison.metrics.empty()) {
    out += "<div class=\"metrics\">\n";
    for (const Check* check : comparison.metrics) {
      const MetricText text = metric_text(*check);
      // A value without a bound is information, not a pass (neutral tile, "info").
      const std::string verdict = shown_without_bound(*check) ? "info" : outcome_name(check->status);
      out += fmt::format("<div class=\"metric {}\" title=\"{}\"><div class=\"label\">{}</div><div class=\"value\">{}</div>"
                         "<div class=\"bound\">{}{}</div></div>\n",
                         verdict, h(check->name + ": " + check->detail), h(text.label), h(text.value),
                         text.bound.empty() ? "" : h(text.bound) + " · ", verdict);
    }
    out += "</div>\n";
  }
  out += "</div>\n";
}

// The case's artifacts except those `shown` already (the comparison's pictures).
void append_artifacts(std::string& out, const CaseResult& result, const std::vector<const Artifact*>& shown) {
  std::string figures;
  std::string plots;
  std::string links;
  for (const Artifact& artifact : result.artifacts) {
    if (std::find(shown.begin(), shown.end(), &artifact) != shown.end()) continue;
    if (artifact.kind == "image") {
      append_figure(figures, artifact, "image");
    } else if (artifact.kind == "plot") {
      if (artifact.path.empty()) {
        plots += fmt::format("<p class=\"note\">{}</p>\n", h(artifact.caption));
      } else {
        append_figure(plots, artifact, "plot");
      }
    } else {
      links += fmt::format("<li><a href=\"{}\">{}</a> {}</li>\n", url(artifact.path), h(artifact.path),
                           h(artifact.caption));
    }
  }
  if (!figures.empty()) out += fmt::format("<div class=\"figures\">\n{}</div>\n", figures);
  if (!plots.empty()) out += fmt::format("<details class=\"more\"><summary>Plots</summary>\n<div class=\"figures\">\n{}</div>\n</details>\n", plots);
  if (!links.empty()) out += fmt::format("<details class=\"more\"><summary>Field files</summary>\n<ul class=\"files\">\n{}</ul>\n</details>\n", links);
}

bool shown_without_bound(const Check& check) {
  return check.status == Outcome::pass && !check.threshold && !check.loose_threshold;
}

void append_check_rows(std::string& out, const std::vector<const Check*>& checks) {
  for (const Check* check : checks) {
    out += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td><td>{}</td></tr>\n",
                       h(check->name), format_value(check->value), h(format_bounds(*check)), check_badge(*check),
                       h(check->detail));
  }
}

constexpr const char* check_table_head =
    "<table class=\"checks\">\n<tr><th>check</th><th>value</th><th>bound</th><th>status</th><th>detail</th></tr>\n";

// A case's checks: those needing attention first, worst first; then the passes and the values shown
// without a bound. A case with more rows than a screen holds keeps its passes and values in two
// collapsed lists (counted in their summaries), so that what did not pass is on screen; the checks
// the user left out (--backend cpu) come last.
void append_checks(std::string& out, const CaseResult& result) {
  if (result.checks.empty()) {
    out += "<p class=\"note\">No checks.</p>\n";
    return;
  }
  constexpr std::size_t rows_on_a_screen = 16;
  const std::vector<const Check*> attention = checks_needing_attention(result);
  std::vector<const Check*> passed, values, left_out;
  for (const Check& check : result.checks) {
    if (left_out_by_request(check)) {
      left_out.push_back(&check);
    } else if (check.status == Outcome::pass) {
      (shown_without_bound(check) ? values : passed).push_back(&check);
    }
  }
  const bool collapse = result.checks.size() > rows_on_a_screen;
  if (collapse && attention.empty()) {
    out += "<p class=\"note\">Nothing needs attention: every graded check passed.</p>\n";
  } else {
    out += check_table_head;
    append_check_rows(out, attention);
  }
  if (!collapse) {
    append_check_rows(out, passed);
    append_check_rows(out, values);
    append_check_rows(out, left_out);
    out += "</table>\n";
    return;
  }
  if (!attention.empty()) out += "</table>\n";
  const auto collapsed = [&](const std::vector<const Check*>& checks, const std::string& summary) {
    if (checks.empty()) return;
    out += fmt::format("<details class=\"more\"><summary>{}</summary>\n{}", h(summary), check_table_head);
    append_check_rows(out, checks);
    out += "</table>\n</details>\n";
  };
  collapsed(passed, fmt::format("{} passed within their bounds", counted(passed.size(), "check")));
  collapsed(values, fmt::format("{} shown without a bound (info)", counted(values.size(), "value")));
  collapsed(left_out, fmt::format("{} not run, as asked", counted(left_out.size(), "check")));
}

std::string optional_value(const std::optional<double>& value) { return value ? format_value(*value) : "—"; }

// The case's terrain descriptors: before, after and the real DEM side by side.
void append_descriptors(std::string& out, const CaseResult& result) {
  const auto table = descriptor_table(result);
  if (!table) return;
  out += "<table class=\"descriptors\">\n<tr><th>terrain descriptor</th><th>unit</th>";
  for (const auto& column : table->columns) out += fmt::format("<th>{}</th>", h(column));
  out += "</tr>\n";
  for (const auto& row : table->rows) {
    out += fmt::format("<tr><td>{}</td><td>{}</td>", h(row.label), h(row.unit));
    for (const auto& value : row.values) out += fmt::format("<td class=\"num\">{}</td>", optional_value(value));
    out += "</tr>\n";
  }
  out += "</table>\n";
}

// How far the descriptor moved toward the real DEM's, as a cell class: toward (green) from +5 %,
// away (red) from -5 %, neutral between (a descriptor measured on a few hundred cells moves a few
// percent by chance).
const char* fidelity_class(const std::optional<double>& moved) {
  if (!moved) return "";
  if (*moved >= 0.05) return " class=\"num toward\"";
  if (*moved <= -0.05) return " class=\"num away\"";
  return " class=\"num\"";
}

std::string fidelity_cell(const std::optional<FidelityTable::Cell>& cell) {
  if (!cell) return "<td>—</td>";
  return fmt::format("<td{}>{} → {}<br><b>{}</b></td>", fidelity_class(cell->moved), format_value(cell->before),
                     format_value(cell->after), cell->moved ? fmt::format("{:+.0f} %", 100.0 * *cell->moved) : "—");
}

// How far each erosion algorithm moved a generated terrain's descriptors toward a real DEM's: a
// row per descriptor (its words, the literature's range, the real DEM's value), a column per case.
void append_fidelity(std::string& out, const Report& report) {
  const auto table = fidelity_table(report);
  if (!table) return;
  out += "<section class=\"fidelity\">\n<h2>Fidelity: does it look like Earth?</h2>\n"
         "<p>Each cell: the descriptor before → after (CPU reference, double), and how far it moved toward "
         + h(table->real_name) + "'s value: <span class=\"toward\">green</span> toward it (100 %: reached it), "
         "<span class=\"away\">red</span> away from it, uncoloured within ±5 %. The range is the literature's for "
         "natural terrain (hover it for the source).</p>\n<div class=\"wide\"><table>\n<tr><th>descriptor</th>"
         "<th>range</th><th>" + h(table->real_name) + "</th>";
  for (const auto& row : table->rows) {
    std::string variant = row.case_name;
    if (variant.starts_with(row.algorithm + ".")) variant.erase(0, row.algorithm.size() + 1);
    // A line break allowed after each dot, so that six or more columns fit a 1,280 px page.
    std::string breakable;
    for (const char c : h(variant)) breakable += c == '.' ? std::string(".<wbr>") : std::string(1, c);
    out += fmt::format("<th><a href=\"#{}\">{}</a><br><small>{}</small></th>", case_anchor(row.case_name),
                       h(row.algorithm), breakable);
  }
  out += "</tr>\n";
  for (std::size_t index = 0; index < table->descriptors.size(); ++index) {
    const auto& target = table->targets[index];
    const std::string range =
        target ? fmt::format("<td class=\"num\" title=\"{}\">{:g}–{:g}</td>", h(target->source), target->low, target->high)
               : std::string("<td>—</td>");
    out += fmt::format("<tr><td title=\"{}\">{}</td>{}<td class=\"num\">{}</td>", h(table->descriptors[index]),
                       h(table->labels[index]), range, optional_value(table->real[index]));
    for (const auto& row : table->rows) out += fidelity_cell(row.cells[index]);
    out += "</tr>\n";
  }
  out += "</table></div>\n</section>\n";
}

// What changed against --baseline, at the top: the diff-reports summary.
void append_baseline(std::string& out, const Report& report) {
  if (!report.baseline_diff) return;
  out += fmt::format("<section class=\"baseline\">\n<h2>Against the baseline: {} regression{}</h2>\n<p>{}</p>\n<pre>{}</pre>\n</section>\n",
                     report.baseline_diff->regressions.size(), report.baseline_diff->regressions.size() == 1 ? "" : "s",
                     h(report.baseline_file), h(describe(*report.baseline_diff)));
}

void append_timings(std::string& out, const Timings& timings) {
  out += fmt::format("<p>Timings (median of one run): CPU reference {} ms over {} · GPU {} ms over {}</p>\n",
                     format_ms(timings.cpu_ms), counted(timings.cpu_reps, "rep"), format_ms(timings.gpu_ms),
                     counted(timings.gpu_reps, "rep"));
}

void append_case_section(std::string& out, const CaseResult& result) {
  out += fmt::format("<section class=\"case {}\" id=\"{}\">\n<h2>{} {}</h2>\n", outcome_name(result.status),
                     anchor(result), badge(result.status), h(result.name));
  const std::string grid = result.width == 0 && result.height == 0 ? "" : fmt::format(" ({})", case_size_text(result));
  out += fmt::format("<p>{} on {}{}</p>\n", h(result.algorithm), h(result.input), h(grid));
  if (!result.notes.empty()) {
    out += "<ul class=\"notes\">\n";
    for (const auto& note : result.notes) out += fmt::format("<li>{}</li>\n", h(note));
    out += "</ul>\n";
  }
  if (!result.expected_failure.empty()) {
    out += fmt::format("<p class=\"note\">Expected failure: {}</p>\n", h(result.expected_failure));
  }
  if (!result.error.empty()) out += fmt::format("<pre class=\"error\">{}</pre>\n", h(result.error));
  for (const auto& line : attempt_lines(result)) out += fmt::format("<p class=\"note\">{}</p>\n", h(line));
  append_checks(out, result);
  std::vector<const Artifact*> shown;
  if (const auto comparison = image_comparison(result)) {
    append_comparison(out, *comparison);
    shown = {comparison->reference, comparison->gpu, comparison->difference, comparison->mask};
  }
  append_artifacts(out, result, shown);
  append_params(out, result.params);
  append_descriptors(out, result);
  append_timings(out, result.timings);
  out += "</section>\n";
}

// The fitted exponent of time against work for every line of the table timed at enough sizes.
void append_scaling(std::string& out, const Report& report) {
  const auto fits = fit_scaling(report.benchmarks);
  out += fmt::format("<h3>Scaling</h3>\n<p class=\"note\">{}</p>\n", h(scaling_explanation()));
  if (fits.empty()) {
    out += fmt::format("<p class=\"note\">{}</p>\n", h(scaling_missing_text()));
    return;
  }
  out += "<table>\n<tr><th>device</th><th>algorithm</th><th>backend</th><th>sizes</th><th>exponent</th></tr>\n";
  for (const ScalingFit& fit : fits) {
    out += fmt::format("<tr{}><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td></tr>\n",
                       fit.linear() ? "" : " class=\"superlinear\"", h(fit.device), h(fit.algorithm),
                       h(scaling_line_text(fit)), h(scaling_sizes_text(fit)),
                       h(scaling_exponent_text(fit)));
  }
  out += "</table>\n";
}

void append_performance(std::string& out, const Report& report) {
  out += "<section class=\"performance\">\n<h2>Performance</h2>\n";
  if (report.benchmarks.empty()) {
    out += "<p class=\"note\">No benchmarks in this run.</p>\n";
  } else {
    const std::string devices = benchmark_devices_once(report.benchmarks);
    if (!devices.empty()) out += fmt::format("<p class=\"devices\">Devices: {}</p>\n", h(devices));
    const std::string device_heading = devices.empty() ? "<th>device</th>" : "";
    out += "<div class=\"wide\"><table>\n<tr>" + device_heading +
           "<th>algorithm</th><th>backend</th><th>size</th><th>iterations</th>"
           "<th>reps</th><th>median ms</th><th title=\"GPU over the CPU reference (double) on the same size\">GPU "
           "speed-up</th><th>Mcell-it/s (noise: M samples/s; cave: M voxels/s)</th>"
           "<th>M triangles/s</th><th>B/cell</th><th>× floor</th><th>× peer</th><th>note</th></tr>\n";
    for (const BenchmarkRow& row : report.benchmarks) {
      const std::string device = devices.empty() ? fmt::format("<td>{}</td>", h(row.device)) : "";
      out += fmt::format(
          "<tr{}>{}<td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
          "<td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
          "<td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
          "<td>{}</td><td>{}</td></tr>\n",
          row.peer.empty() ? "" : " class=\"peer\"", device, h(row.algorithm), h(benchmark_backend_text(row)),
          h(benchmark_size_text(row)), row.iterations, row.reps, h(benchmark_time_text(row)),
          h(benchmark_speedup_text(report.benchmarks, row)), h(benchmark_rate_text(row)),
          h(benchmark_triangle_rate_text(row)), h(benchmark_bytes_text(row)), h(benchmark_floor_text(row)),
          h(benchmark_peer_text(row)), h(benchmark_note_text(row)));
    }
    out += "</table></div>\n";
    append_scaling(out, report);
  }
  for (const Artifact& plot : report.plots) {
    if (plot.path.empty()) {
      out += fmt::format("<p class=\"note\">{}</p>\n", h(plot.caption));
    } else {
      append_figure(out, plot, "plot");
    }
  }
  out += "</section>\n";
}

// Broken rules of datasets/expectations.txt, each of which failed the run.
void append_expectation_problems(std::string& out, const Report& report) {
  if (report.expectation_problems.empty()) return;
  out += "<section>\n<h2>Expectations not met</h2>\n<ul>\n";
  for (const auto& problem : report.expectation_problems) out += fmt::format("<li>{}</li>\n", h(problem));
  out += "</ul>\n</section>\n";
}

// Beside the mutation score (sensitivity): the honest runs not failed (specificity), when measured.
void append_specificity(std::string& out, const MutationReport& mutation) {
  if (!mutation.specificity) return;
  const SpecificitySummary& specificity = *mutation.specificity;
  if (!specificity.problem.empty()) {
    out += fmt::format("<p>Specificity <span class=\"badge error\">not measured</span>: {}.</p>\n", h(specificity.problem));
    return;
  }
  out += fmt::format(
      "<p>Specificity <span class=\"badge {}\">{} of {} honest runs without a false alarm ({:.1f} %)</span>: each "
      "stepping algorithm with parameter sets drawn from plausible ranges, on two real DEMs; a fail or an error is "
      "a false alarm (<a href=\"{}{}\">which runs, with their parameters</a>).</p>\n",
      specificity.false_alarms == 0 ? "pass" : "fail", specificity.runs - specificity.false_alarms, specificity.runs,
      100.0 * specificity_share(specificity.false_alarms, specificity.runs), h(mutation.folder), h(specificity.page));
}

// Which graded check killed which mutant: a graded check (one with a bound in a baseline run) that
// killed none is not yet proved able to fail; those come first.
void append_kill_matrix(std::string& out, const MutationReport& mutation) {
  auto rows = mutation.kill_matrix();
  if (rows.empty()) return;
  std::stable_partition(rows.begin(), rows.end(), [](const KillRow& row) { return row.mutants.empty(); });
  const auto unproved = std::count_if(rows.begin(), rows.end(), [](const KillRow& row) { return row.mutants.empty(); });
  out += fmt::format(
      "<details{}><summary>Kill matrix: {} of {} graded checks killed a mutant of their kind{}</summary>\n<table>\n"
      "<tr><th>check</th><th>kills</th><th>mutants killed</th></tr>\n",
      unproved > 0 ? " open" : "", rows.size() - static_cast<std::size_t>(unproved), rows.size(),
      unproved > 0 ? fmt::format("; {} killed none (first)", unproved) : "");
  for (const auto& row : rows) {
    out += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td>{}</td></tr>\n", h(row.check),
                       row.mutants.empty() ? "<span class=\"badge warn\">none</span>" : std::to_string(row.mutants.size()),
                       h(fmt::format("{}", fmt::join(row.mutants, ", "))));
  }
  out += "</table>\n</details>\n";
}

// The mutation score: each registered mutant, its kind, and the checks that killed it.
void append_mutation(std::string& out, const Report& report) {
  if (!report.mutation) return;
  const MutationReport& mutation = *report.mutation;
  out += fmt::format(
      "<section class=\"mutation\" id=\"mutants\">\n<h2>Mutants</h2>\n<p>Mutation score <span class=\"badge {}\">{} of {} killed "
      "({:.0f} %)</span>. Each mutant is a deliberate bug run on its cases in a worker process; a one-twin mutant "
      "must be killed by a check comparing the twins (parity, pictures, reruns) or by the mutated twin's own ledger "
      "or invariant, a both-twins mutant by a check against what was asked (ledgers, spec vectors, invariants).</p>\n",
      mutation.passed() ? "pass" : "fail", mutation.killed(), mutation.bugs(), 100.0 * mutation.score());
  append_specificity(out, mutation);
  out += "<table>\n<tr><th>family</th><th>cases unmutated</th><th>problems</th></tr>\n";
  for (const auto& baseline : mutation.baselines) {
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", h(baseline.family),
                       baseline.clean ? "<span class=\"badge pass\">clean</span>" : "<span class=\"badge fail\">failed</span>",
                       h(fmt::format("{}", fmt::join(baseline.problems, "; "))));
  }
  out += "</table>\n<table>\n<tr><th>status</th><th>mutant</th><th>kind</th><th>the bug</th><th>killed by</th>"
         "<th>s</th></tr>\n";
  for (const auto& mutant : mutation.mutants) {
    std::string killed_by;
    if (!mutant.killed_by.empty()) {
      for (const auto& line : mutant.killed_by) killed_by += (killed_by.empty() ? "" : "<br>") + h(line);
    } else {
      killed_by = h(mutant.error);
    }
    out += fmt::format("<tr><td><span class=\"badge {}\">{}</span></td><td><a href=\"{}{}/index.html\">{}</a></td>"
                       "<td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{:.1f}</td></tr>\n",
                       mutant.as_expected() ? "pass" : "fail", h(mutant.status), h(mutation.folder), h(mutant.run_folder),
                       h(mutant.name), h(mutant.kind) + (mutant.must_survive ? "<br>must survive" : ""),
                       h(mutant.description), killed_by, mutant.seconds);
  }
  out += "</table>\n";
  append_kill_matrix(out, mutation);
  out += "</section>\n";
}

}  // namespace

void write_report_html(const Report& report, const std::filesystem::path& file) {
  std::string out = page_head("groundtruth report", std::string(style) + std::string(colour_bar_style));
  append_header(out, report);
  // `groundtruth mutants` or `bench` alone: the page is the mutation score or the performance table,
  // without the scaffolding of a case run ("0 cases", an empty Cases table, "No benchmarks"); each
  // mutant's run has its own report.
  const bool any_cases = !report.cases.empty();
  if (any_cases) {
    append_summary(out, report);
    append_failures(out, report);
  }
  append_baseline(out, report);
  append_expectation_problems(out, report);
  if (any_cases) append_case_table(out, report);
  append_mutation(out, report);
  append_fidelity(out, report);
  for (const CaseResult& result : report.cases) append_case_section(out, result);
  if (any_cases || !report.benchmarks.empty()) append_performance(out, report);
  out += "</body>\n</html>\n";
  write_file_atomically(file, out);
}

}  // namespace gt
