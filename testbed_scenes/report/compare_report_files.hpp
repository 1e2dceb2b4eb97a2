#pragma once
// Internal to the compare report (report/compare_*.cpp): the directory being written, the CSV
// writers the charts reuse for their data, and the lookups the charts and report.md share.

#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "report/compare_report.hpp"

namespace dyop::scenes::detail {

/// The report directory of one run: where its files go, what failed and which charts were drawn.
struct ReportFiles {
  const CompareRun& run;              ///< what is reported
  std::string dir;                    ///< `run.options.out_dir`
  ReportOutcome outcome;              ///< errors and warnings so far
  std::vector<std::string> charts;    ///< the SVG charts drawn (file names in `dir`)

  /// `file` inside the directory.
  std::string path(const std::string& file) const { return dir + "/" + file; }

  /// Writes `file` with `body(stream)`; false (and an error in `outcome`) if it failed.
  template <class F>
  bool write_file(const std::string& file, F&& body) {
    std::ofstream out(path(file));
    body(out);
    out.close();
    if (!out) {
      outcome.errors.push_back("cannot write " + path(file));
      return false;
    }
    return true;
  }
};

// compare_csv.cpp: the CSV files (and the Figure-7 data, which the chart reads with `sep` ' ').
void write_compare_csv(const CompareRun& run, std::ostream& o);
void write_skips_csv(const CompareRun& run, std::ostream& o);
void write_figure7_data(const CompareRun& run, std::ostream& o, char sep);
void write_paper_methods_csv(const CompareRun& run, std::ostream& o);

// compare_charts.cpp: every chart (gnuplot) and its data file; failures become warnings.
void draw_charts(ReportFiles& files);

// compare_markdown.cpp: report.md.
void write_markdown(const ReportFiles& files, std::ostream& o);

// compare_report.cpp: the scenes of the main table in run order, and one row of it (none if
// absent).
std::vector<std::string> scene_names(const CompareRun& run);
const SceneMetrics* row(const CompareRun& run, const std::string& scene,
                        const std::string& backend);

}  // namespace dyop::scenes::detail
