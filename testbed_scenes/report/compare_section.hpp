#pragma once
/// \file
/// A section of `dyop compare` beyond the main table: one experiment with its run, its records
/// and everything written from them (the table on standard output, its files in the report
/// directory, its part of `report.md`, its lines of the Problems list). Each section is one file,
/// `report/compare_<name>.cpp`, and one line of `compare_sections.cpp`'s list; a section that
/// measured nothing (none of its scenes selected) writes nothing.

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "report/report_directory.hpp"
#include "experiments/compare.hpp"

namespace dyop::report {

struct SummaryFigures;  // report/compare_summary.hpp

/// What a section runs with: the command's options, the scenes selected (catalogue order), and
/// where progress lines go.
struct SectionContext {
  const experiments::CompareOptions& options;
  const std::vector<const scenes::SceneInfo*>& scenes;
  std::ostream& progress;
  /// Seconds since the whole run started (for the progress lines' totals).
  std::function<double()> elapsed;
  /// The scene's step count under the options (`experiments::compare_steps`).
  int steps(const scenes::SceneInfo& s) const { return experiments::compare_steps(options, s); }
  /// True when scene `name` is selected.
  bool selected(const std::string& name) const;
};

/// The charts drawn so far in the report directory, for `report.md`'s images.
class Charts {
 public:
  /// Draws chart `name` (`ReportDirectory::chart`) and remembers it when drawn.
  void draw(ReportDirectory& dir, const std::string& name, const std::string& terminal,
            const std::string& script);
  /// `![alt](name.svg)`, or a note that it was not drawn (its data is in the CSV files).
  void image(std::ostream& o, const std::string& name, const std::string& alt) const;

 private:
  std::vector<std::string> drawn_;
};

class CompareSection {
 public:
  virtual ~CompareSection() = default;
  /// Its `--section` name, e.g. "in-world".
  virtual const char* section_name() const = 0;
  /// Runs the section's measurements for the scenes selected, after the main table.
  virtual void run(const SectionContext& context) = 0;
  /// True when it measured something: only then is anything of it written.
  virtual bool measured() const = 0;
  /// Its tables on standard output, under a title line.
  virtual void write_tables(std::ostream& out) const = 0;
  /// Its files in the report directory (CSV, snapshots, chart data) and its charts.
  virtual void write_files(ReportDirectory& dir, Charts& charts) const = 0;
  /// Its part of `report.md`: a `##` heading, what is measured, its tables and charts.
  virtual void write_markdown(std::ostream& o, const Charts& charts) const = 0;
  /// Its files for `report.md`'s file list, e.g. "`slide.csv` (every slider under every
  /// runner)".
  virtual std::string files() const = 0;
  /// True when `--quick` runs it without being named by `--section` (the main command's run is
  /// kept to seconds; the full run has every section).
  virtual bool in_quick_run() const { return true; }
  /// Its lines of `report.md`'s Problems list (none by default).
  virtual void problems(std::vector<std::string>& lines) const { (void)lines; }
  /// Its figures for the summary the command opens with (none by default).
  virtual void summarize(SummaryFigures& figures) const { (void)figures; }
};

/// The sections, in the order they run and are reported: the one list of them.
std::vector<std::unique_ptr<CompareSection>> make_compare_sections();

/// `dyop compare`'s whole run: the main table and every section.
struct Comparison {
  experiments::CompareRun main;                           ///< every scene under every backend
  std::vector<std::unique_ptr<CompareSection>> sections;  ///< `make_compare_sections()`, run
  double seconds = 0;                                     ///< wall time of the whole run

  /// The section of type `S`, or nullptr (for tests that look at one section's records).
  template <class S>
  const S* section() const {
    for (const auto& s : sections) {
      if (const auto* found = dynamic_cast<const S*>(s.get())) return found;
    }
    return nullptr;
  }
};

/// The `--section` names of every section, in order.
std::vector<std::string> compare_section_names();

/// Runs the main table, then every section (those of `options.sections`, when given); progress
/// lines on `progress`. Throws what the scenes
/// throw (a refused installation).
Comparison run_comparison(const experiments::CompareOptions& options, std::ostream& progress);

}  // namespace dyop::report
