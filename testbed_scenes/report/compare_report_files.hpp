#pragma once
// Internal to the compare report (report/compare_*.cpp): the directory being written, the CSV
// writers the charts reuse for their data, and the lookups the charts and report.md share.

#include <ostream>
#include <string>
#include <vector>

#include "report/compare_report.hpp"
#include "report/report_directory.hpp"

namespace dyop::report::detail {

using scenes::CompareRun;
using scenes::SceneMetrics;

/// The report directory of one run: what is reported, where, and which charts were drawn.
struct ReportFiles {
  const CompareRun& run;            ///< what is reported
  ReportDirectory dir;              ///< `run.options.out_dir`, its files and problems
  std::vector<std::string> charts;  ///< the SVG charts drawn (file names in `dir`)
};

// compare_csv.cpp: the CSV files (and the Figure-7 data, which the chart reads with `sep` ' ').
void write_compare_csv(const CompareRun& run, std::ostream& o);
void write_skips_csv(const CompareRun& run, std::ostream& o);
void write_figure7_data(const CompareRun& run, std::ostream& o, char sep);
void write_paper_methods_csv(const CompareRun& run, std::ostream& o);
void write_slide_csv(const CompareRun& run, std::ostream& o);

// compare_charts.cpp: every chart (gnuplot) and its data file; failures become problems.
void draw_charts(ReportFiles& files);

// compare_markdown.cpp: report.md.
void write_markdown(const ReportFiles& files, std::ostream& o);

// compare_report.cpp: the scenes of the main table in run order, and one row of it (none if
// absent).
std::vector<std::string> scene_names(const CompareRun& run);
const SceneMetrics* row(const CompareRun& run, const std::string& scene,
                        const std::string& backend);

}  // namespace dyop::report::detail
