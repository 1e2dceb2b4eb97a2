#pragma once
/// \file
/// `dyop compare`'s in-world section: every Box2D scene selected, under each backend of
/// `scenes::in_world_backends`, against Box2D's own contact (the plug-in not installed), runs
/// alternating in one process (`scenes/in_world.hpp`).

#include <ostream>
#include <vector>

#include "report/compare_section.hpp"
#include "scenes/in_world.hpp"

namespace dyop::report {

class InWorldSection : public CompareSection {
 public:
  void run(const SectionContext& context) override;
  bool measured() const override { return !rows_.empty(); }
  void write_tables(std::ostream& out) const override;
  void write_files(ReportDirectory& dir, Charts& charts) const override;
  void write_markdown(std::ostream& o, const Charts& charts) const override;
  std::string files() const override;

  /// One row per scene and backend, in run order.
  const std::vector<scenes::InWorldRatio>& rows() const { return rows_; }

 private:
  bool quick_ = false;
  std::vector<scenes::InWorldRatio> rows_;
};

/// The in-world table (Markdown): one row per scene and backend.
void write_in_world_table(const std::vector<scenes::InWorldRatio>& rows, std::ostream& out);

/// The in-world CSV (header and one line per scene and backend).
void write_in_world_csv(const std::vector<scenes::InWorldRatio>& rows, std::ostream& out);

}  // namespace dyop::report
