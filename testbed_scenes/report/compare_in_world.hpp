#pragma once
/// \file
/// `dyop compare`'s in-world section: every Box2D scene selected, under each backend of
/// `experiments::in_world_backends`, against Box2D's own contact (the plug-in not installed), runs
/// alternating in one process (`experiments/in_world.hpp`).

#include <ostream>
#include <vector>

#include "report/compare_section.hpp"
#include "report/records.hpp"
#include "experiments/in_world.hpp"

namespace dyop::report {

class InWorldSection : public CompareSection {
 public:
  const char* section_name() const override { return "in-world"; }
  void run(const SectionContext& context) override;
  bool measured() const override { return !rows_.empty(); }
  void write_tables(std::ostream& out) const override;
  void write_files(ReportDirectory& dir, Charts& charts) const override;
  void write_markdown(std::ostream& o, const Charts& charts) const override;
  std::string files() const override;
  void summarize(SummaryFigures& figures) const override;

  /// One row per scene and backend, in run order.
  const std::vector<experiments::InWorldRatio>& rows() const { return rows_; }

 private:
  bool quick_ = false;
  std::vector<experiments::InWorldRatio> rows_;
};

/// The records, column by column, one per scene and backend (the Markdown table, the CSV).
Records in_world_records(const std::vector<experiments::InWorldRatio>& rows);

}  // namespace dyop::report
