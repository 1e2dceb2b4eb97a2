#pragma once
// Internal to the compare report (report/compare_report.cpp, compare_charts.cpp,
// compare_markdown.cpp): the directory being written and the lookups the charts and report.md
// share.

#include <ostream>
#include <string>
#include <vector>

#include "report/compare_report.hpp"
#include "report/compare_section.hpp"
#include "report/report_directory.hpp"

namespace dyop::report::detail {

using experiments::CompareRun;
using scenes::SceneMetrics;

/// The report directory of one run: what is reported, where, and which charts were drawn.
struct ReportFiles {
  const Comparison& comparison;  ///< what is reported
  ReportDirectory dir;           ///< `options.out_dir`, its files and problems
  Charts charts;                 ///< the charts drawn
};

// compare_charts.cpp: the main table's charts (gnuplot) and their data files.
void draw_charts(ReportFiles& files);

// compare_markdown.cpp: report.md.
void write_markdown(const ReportFiles& files, std::ostream& o);

// compare_report.cpp: the scenes of the main table in run order, and one row of it (none if
// absent).
std::vector<std::string> scene_names(const CompareRun& run);
const SceneMetrics* row(const CompareRun& run, const std::string& scene,
                        const scenes::Runner& runner);

}  // namespace dyop::report::detail
