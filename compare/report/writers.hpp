// Report writers: one Report in, one file out per format (DESIGN.md "report.json (schema 1)").
//
//   report.json  machine-readable record, schema 1; non-finite numbers are written as null
//   report.md    environment, summary, case table, non-passing checks, benchmark table
//   junit.xml    one testsuite per algorithm, one testcase per case (for CI test views)
//   index.html   self-contained static page with images, checks, timings and benchmark plots
//
// Conventions
//   - Artifact paths are relative to the report folder; the writers never copy or check them.
//   - A plot artifact with an empty path stands for a plot that could not be made: its caption
//     ("plot unavailable: <reason>") is shown in its place.
//   - Each writer writes `file.tmp-<pid>` in the same folder and renames it over `file`, so a
//     reader never sees half a report. Failures throw std::runtime_error naming the file.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "compare/result.hpp"

namespace gt {

nlohmann::json report_to_json(const Report& report);

void write_report_json(const Report& report, const std::filesystem::path& file);
void write_report_markdown(const Report& report, const std::filesystem::path& file);
void write_report_junit(const Report& report, const std::filesystem::path& file);
void write_report_html(const Report& report, const std::filesystem::path& file);

// Writes report.json, report.md, junit.xml and index.html into `folder`, which must exist.
void write_report_files(const Report& report, const std::filesystem::path& folder);

}  // namespace gt
