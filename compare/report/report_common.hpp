// Helpers shared by the report writers (internal to compare/report/): outcome counts, number
// formatting, markup escaping and the write-then-rename file output.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/benchmark_table.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/result.hpp"

namespace gt::report_detail {

// The "benchmarks" array of report.json (also the input of plot_timings.py).
nlohmann::json benchmarks_to_json(const std::vector<BenchmarkRow>& rows);

// The environment's fields with their labels, GL renderer first.
struct LabelledField {
  const char* label;
  const std::string* value;
};
std::array<LabelledField, 14> environment_fields(const Environment& environment);

// A retried case's earlier attempts, one line each: "attempt 1: fail: check = value (bound)", and
// for a flaky case what it was ("known flake: REASON" or that it is a new flake).
std::vector<std::string> attempt_lines(const CaseResult& result);

// Every outcome in the order the writers list them.
inline constexpr std::array<Outcome, 7> all_outcomes = {Outcome::pass, Outcome::warn,  Outcome::inconclusive,
                                                        Outcome::skip, Outcome::flaky, Outcome::fail,
                                                        Outcome::error};

struct OutcomeCounts {
  std::array<int, all_outcomes.size()> by_outcome{};  // indexed like all_outcomes
  int expected_failures = 0;                         // cases with an expectation entry

  int& operator[](Outcome outcome);
  int operator[](Outcome outcome) const;
  int total() const;
};

OutcomeCounts count_case_outcomes(const Report& report);
OutcomeCounts count_check_outcomes(const CaseResult& result);

// "pass 3 · warn 1" style list of the non-zero counts; "none" when all are zero.
std::string format_counts(const OutcomeCounts& counts, std::string_view separator);

// %.3g, with "nan", "inf", "-inf" for non-finite values.
std::string format_value(double value);
// Milliseconds: whole numbers from 1000 ms up, %.3g below; "–" when absent.
std::string format_ms(std::optional<double> ms);

// The case's grid, "87×61", or "—" for cases without one (meshes, the cave: see their input).
std::string case_size_text(const CaseResult& result);

// "512×512" for a grid, "128³" for a volume.
std::string benchmark_size_text(const BenchmarkRow& row);

// Time and throughput columns: median ms, "Mcell-it/s" and "M triangles/s" (empty when the row
// has none), "—" for a row that did not run; its note column says why ("not run: ...").
std::string benchmark_time_text(const BenchmarkRow& row);
std::string benchmark_rate_text(const BenchmarkRow& row);
std::string benchmark_triangle_rate_text(const BenchmarkRow& row);
std::string benchmark_note_text(const BenchmarkRow& row);
// "gpu", "cpu", "peer: VTK 9.1.0 vtkFlyingEdges3D (...)" for a peer's row, or "published: <the
// machine>" for a figure from a paper.
std::string benchmark_backend_text(const BenchmarkRow& row);
// Bytes read plus written per cell and iteration ("24"), "" where not counted.
std::string benchmark_bytes_text(const BenchmarkRow& row);
// "3.1×" (median over the memory-bound floor, median over the fastest peer's), "" without one.
std::string benchmark_floor_text(const BenchmarkRow& row);
std::string benchmark_peer_text(const BenchmarkRow& row);
// A GPU row's speed-up over the CPU reference (double) timed on the same algorithm, size and
// iterations in the same table: "41×" (the reference's median over the GPU's), "" for other rows.
std::string benchmark_speedup_text(const std::vector<BenchmarkRow>& rows, const BenchmarkRow& row);
// The devices of a table, "gpu: llvmpipe (...); cpu: AMD EPYC ..." (each backend once), when every
// backend we measured ran on one device (published figures name theirs in their backend cell): the table then names them once above it instead of in every row.
// Empty when a backend ran on several devices (a merged report): each row names its own then.
std::string benchmark_devices_once(const std::vector<BenchmarkRow>& rows);
// The scaling table's introduction (what the exponent and × floor mean), its line when no line
// has enough sizes, and its backend cell ("cpu", or "peer: NAME").
std::string scaling_explanation();
std::string scaling_missing_text();
std::string scaling_line_text(const ScalingFit& fit);
// The scaling table's cells: "32³–256³ (4)" and "1.07 linear" or "1.42 superlinear (> 1.15)".
std::string scaling_sizes_text(const ScalingFit& fit);
std::string scaling_exponent_text(const ScalingFit& fit);
// "≤ threshold" plus "(warn ≤ loose)" when a loose bound exists; "" when neither exists.
std::string format_bounds(const Check& check);

// The pictures of a rendered-image comparison between the CPU reference and the GPU twin, found by
// file name among a case's "image" artifacts (what compare/render_case.cpp and
// compare/algorithms/render_heightmap.cpp write):
//   reference   .../cpu.png
//   gpu         .../gpu.png
//   difference  .../gpu_vs_cpu_heat.png (heat map) or .../gpu_vs_cpu.png (signed difference)
//   mask        .../gpu_vs_cpu_mask.png (neighbourhood verdicts)
// A case is such a comparison when it has a reference picture and either a difference picture or,
// when the GPU did not run, a skipped check named *.gpu_vs_cpu (whose detail says why). Other cases
// (field twins' before/after, noise fields) are not. metrics are the case's checks named
// *.gpu_vs_cpu that did not skip, in the case's order; others are the case's image artifacts that
// are not part of the comparison.
struct ImageComparison {
  std::string twin = "gpu";  // the image graded against the reference: "gpu", or "candidate" (run --candidate)
  const Artifact* reference = nullptr;
  const Artifact* gpu = nullptr;  // the twin's picture
  const Artifact* difference = nullptr;
  const Artifact* mask = nullptr;
  std::string gpu_missing_reason;  // when gpu is null
  std::vector<const Check*> metrics;
  std::vector<const Artifact*> others;
};

// Pointers into `result`, which must outlive the answer.
std::optional<ImageComparison> image_comparison(const CaseResult& result);

// A metric of an image comparison as it is shown under the pictures: a short label, the value in
// its unit (PSNR in dB from image.psnr's -PSNR, shares in percent, the largest channel difference
// with its 8-bit levels) and the bound in the same terms ("" when informative).
struct MetricText {
  std::string label, value, bound;
};
MetricText metric_text(const Check& check);

// A case's terrain descriptors (CaseResult::descriptors) as a table: a column per terrain (before,
// after on each backend, the real DEM), a row per scalar descriptor in the order first met.
struct DescriptorTable {
  struct Row {
    std::string label;
    std::string unit;
    std::vector<std::optional<double>> values;  // one per column
  };
  std::vector<std::string> columns;
  std::vector<Row> rows;
};
std::optional<DescriptorTable> descriptor_table(const CaseResult& result);

// The fidelity table across algorithms: for each case whose "expect" asked for fidelity, each
// target descriptor (compare/case_descriptors.hpp fidelity_targets(), plus HI: the scale-free ones)
// before and after (ref<double>) and how far it moved toward the real DEM's value:
// moved = (|before - real| - |after - real|) / |before - real| (1: reached it, 0: no closer,
// negative: further away; absent when before already equals real).
struct FidelityTable {
  struct Cell {
    double before = 0.0;
    double after = 0.0;
    std::optional<double> moved;
  };
  struct Row {
    std::string case_name;
    std::string algorithm;
    std::vector<std::optional<Cell>> cells;  // one per descriptor
  };
  std::string real_name;
  std::vector<std::string> descriptors;        // ScalarDescriptor names
  std::vector<std::string> labels;             // each one's label in words ("hypsometric integral HI")
  std::vector<std::optional<FidelityTarget>> targets;  // each one's range from the literature, where it has one
  std::vector<std::optional<double>> real;     // the real DEM's value of each
  std::vector<Row> rows;
};
std::optional<FidelityTable> fidelity_table(const Report& report);

// Escapes & < > " ' for HTML and XML text and attributes; control characters that XML 1.0
// forbids become U+FFFD.
std::string escape_markup(std::string_view text);

// The start of a page of the report folder, through <body>: the doctype, UTF-8, `title`
// (escaped here) and `style` (CSS, as given).
std::string page_head(std::string_view title, std::string_view style);

// ASCII letters, digits and - . _ ~ (RFC 3986 unreserved characters).
bool unreserved(char c);

// The id of a case's section in index.html: "case-" and its name, other characters as '_'.
std::string case_anchor(const std::string& case_name);

// A map's colour bar as HTML (class "colourbar", styled by colour_bar_style): the palette from its
// low end to its high end as a CSS gradient, the ends (and 0 of a diverging map) labelled in the
// map's unit; "" without a scale.
std::string colour_bar(const std::optional<ColourScale>& scale);
// A map's scale bar as HTML (class "scalebar"): a bar of a round length (1, 2 or 5 × 10^k m, about a
// quarter of the map's width) drawn at its share of the picture's width and labelled in m or km;
// "" without a width.
std::string scale_bar(const std::optional<double>& width_m);
inline constexpr std::string_view colour_bar_style = R"(
.colourbar { width: 280px; font-size: .78em; color: #333; margin-top: .15em; }
.panel .colourbar { width: 100%; }
.colourbar .ramp { display: block; height: 10px; border: 1px solid #999; }
.colourbar .ticks { display: flex; justify-content: space-between; font-variant-numeric: tabular-nums; }
.scalebar { font-size: .78em; color: #333; margin-top: .2em; display: flex; align-items: center; gap: .4em; }
.scalebar .bar { display: inline-block; height: 4px; border: 1px solid #333; border-top: none; }
)";

}  // namespace gt::report_detail
