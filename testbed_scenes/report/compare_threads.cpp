// `dyop compare`'s worlds-on-threads section: copies of `rain` stepped at once on 1, 2 and 4
// threads, the plug-in against Box2D's own contact (`experiments/thread_scaling.hpp`), as in
// `dyop bench`.
#include "report/compare_section.hpp"
#include "report/bench_sections.hpp"

namespace dyop::report {
namespace {

// Steps of each world and runs of each runner: `dyop bench`'s (10 s of rain, 5 runs), or 2 s and
// 3 runs with `--quick` (about 5 s in all); `--steps` sets the steps, as for every scene.
constexpr int kSteps = 600;
constexpr int kRuns = 5;
constexpr int kQuickSteps = 120;
constexpr int kQuickRuns = 3;

class ThreadSection : public CompareSection {
 public:
  const char* section_name() const override { return "threads"; }
  bool in_quick_run() const override { return false; }
  void run(const SectionContext& c) override {
    options_.scene = "rain";
    if (!c.selected(options_.scene)) return;
    options_.steps = c.options.steps.value_or(c.options.quick ? kQuickSteps : kSteps);
    options_.runs = c.options.quick ? kQuickRuns : kRuns;
    options_.seed = c.options.seed;
    records_ = experiments::run_thread_scaling(options_, c.progress);
  }

  bool measured() const override { return !records_.empty(); }

  void write_tables(std::ostream& out) const override {
    out << '\n';
    write_thread_scaling_table(records_, options_.scene, out);
  }

  void write_files(ReportDirectory& dir, Charts&) const override {
    dir.write("threads.csv",
              [&](std::ostream& o) { thread_scaling_records(records_).write_csv(o); });
  }

  void write_markdown(std::ostream& o, const Charts&) const override {
    o << thread_scaling_markdown(records_, options_.scene) << '\n';
  }

  std::string files() const override {
    return "`threads.csv` (worlds on threads, dyop against Box2D's own contact)";
  }

 private:
  experiments::ThreadScalingOptions options_;
  std::vector<experiments::ThreadScalingRecord> records_;
};

}  // namespace

std::unique_ptr<CompareSection> make_thread_section() { return std::make_unique<ThreadSection>(); }

}  // namespace dyop::report
