// `dyop compare`'s paper section: the paper's Figure-7 experiment (`scenes/paper.hpp`), timed
// repeatedly when the `paper` scene is selected, with its tables, CSVs, chart and Markdown.
#include <algorithm>
#include <optional>
#include <sstream>

#include "report/compare_section.hpp"
#include "report/format.hpp"
#include "report/records.hpp"
#include "experiments/paper_experiment.hpp"
#include "experiments/progress.hpp"

namespace dyop::report {
namespace {

using namespace dyop::scenes;

const char* const kTerminal = "svg size 1000,520 dynamic font 'sans,11' background '#ffffff'";

class PaperSection : public CompareSection {
 public:
  const char* section_name() const override { return "paper"; }
  void run(const SectionContext& c) override {
    for (const SceneInfo* s : c.scenes) {
      if (std::string(s->name) != "paper") continue;
      const double start = c.elapsed();
      const int steps = c.steps(*s);
      const int reps = experiments::paper_repetitions(c.options.quick);
      experiment_ = experiments::paper::run_experiment(c.options.seed, steps, reps);
      c.progress << "[paper] Figure 7 experiment, " << steps << " steps, " << reps
                 << " repetitions of 8 methods: "
                 << experiments::detail::fixed(c.elapsed() - start, 1) << " s\n";
    }
  }

  bool measured() const override { return experiment_.has_value(); }

  void write_tables(std::ostream& out) const override {
    out << "\nThe paper's experiment (scene `paper`):\n\n";
    tables(out);
  }

  void write_files(ReportDirectory& dir, Charts& charts) const override {
    dir.write("paper_figure7.csv", [&](std::ostream& o) { figure7_data(o, ','); });
    dir.write("paper_methods.csv", [&](std::ostream& o) {
      method_records(figures({Method::Dyop, false})).write_csv(o);
    });
    dir.write("paper_figure7.dat", [&](std::ostream& o) { figure7_data(o, ' '); });
    std::ostringstream fig;
    fig << "set title 'The paper''s Figure 7 rebuilt: time to find the penetration depths of "
           "each triangle type over "
        << experiment_->steps << " steps'\n"
        << "set xlabel 'triangle type'\nset ylabel 'µs for all steps (median of "
        << experiment_->repetitions << " runs)'\nset xtics 1\nset xrange [0.5:10.5]\n"
        << "set yrange [0:*]\nset grid ytics\nset key outside right top\n"
        << "plot for [i=4:" << 3 + experiment_->methods.size() << "] "
        << dir.quoted("paper_figure7.dat")
        << " using 1:i with linespoints lw 2 pt 7 title columnheader(i)\n";
    charts.draw(dir, "paper_figure7", kTerminal, fig.str());
  }

  void write_markdown(std::ostream& o, const Charts& charts) const override {
    const experiments::paper::Experiment& e = *experiment_;
    o << "## The paper's experiment (scene `paper`)\n\n"
      << "The paper moves 10 pre-defined irregular triangle types on pre-defined paths for 90 "
         "steps, tests them against each other and plots per type the time DyOP-PD and "
         "Lin–Canny take to find the penetration depths (its Figure 7). It publishes neither the "
         "triangles nor the paths; ours follow. Every step, each pair whose bounding boxes "
         "overlap goes to every method, in float, at depth level; errors are against the exact "
         "rational reference. Seed "
      << e.seed << ", steps of " << fmt("%.4f", scenes::paper::step_seconds)
      << " s from t = " << fmt("%.1f", scenes::paper::start_time(e.seed)) << " s.\n\n"
      << "Triangle types (vertices about the centroid):\n\n| type | v0 | v1 | v2 | longest edge |\n"
      << "|--:|---|---|---|--:|\n";
    for (int k = 0; k < scenes::paper::type_count; ++k) {
      const auto& t = scenes::paper::triangle_types()[k];
      o << "| " << k + 1 << " |";
      for (int i = 0; i < 3; ++i) {
        o << " (" << fmt("%.3f", t[i].x()) << ", " << fmt("%.3f", t[i].y()) << ") |";
      }
      o << ' '
        << fmt("%.2f", std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()}))
        << " |\n";
    }
    o << "\nPaths: type k is at (cx + ax·sin(wx·t + phase), cy + ay·sin(wy·t)), turned by "
         "angle0 + spin·t:\n\n| type | cx | cy | ax | ay | wx | wy | phase | angle0 | spin |\n"
      << "|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (int k = 0; k < scenes::paper::type_count; ++k) {
      const scenes::paper::Path& p = scenes::paper::paths()[k];
      o << "| " << k + 1;
      for (double v : {p.cx, p.cy, p.ax, p.ay, p.wx, p.wy, p.phase, p.angle0, p.spin}) {
        o << " | " << fmt("%.2f", v);
      }
      o << " |\n";
    }
    o << '\n';
    tables(o);
    o << '\n';
    charts.image(o, "paper_figure7", "time per triangle type and method");
  }

  std::string files() const override { return "`paper_figure7.csv`, `paper_methods.csv`"; }

 private:
  // The Figure-7 table and the per-method summary (Markdown).
  void tables(std::ostream& out) const {
    const experiments::paper::Experiment& e = *experiment_;
    const auto& types = scenes::paper::triangle_types();
    out << "Time to compute the penetration depth of every bounding-box-overlapping pair a "
           "triangle type is in, over all "
        << e.steps << " steps (µs, median of " << e.repetitions << " repetitions):\n\n"
        << "| type | size | pairs |";
    for (const auto& m : e.methods) out << ' ' << adapters::name(m.method) << " |";
    out << " lin-canny-warm / dyop | lin-canny-cold / dyop |\n|--:|--:|--:|";
    for (std::size_t i = 0; i < e.methods.size() + 2; ++i) out << "--:|";
    out << '\n';
    const auto& dyop = figures({Method::Dyop, false});
    const auto& warm = figures({Method::LinCanny, true});
    const auto& cold = figures({Method::LinCanny, false});
    for (int k = 0; k < scenes::paper::type_count; ++k) {
      const auto& t = types[k];
      const double size =
          std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
      out << "| " << k + 1 << " | " << fmt("%.2f", size) << " | " << e.pairs_per_type[k] << " |";
      for (const auto& m : e.methods) out << ' ' << fmt("%.2f", m.us_per_type[k]) << " |";
      out << ' ' << fmt("%.2f", warm.us_per_type[k] / dyop.us_per_type[k]) << " | "
          << fmt("%.2f", cold.us_per_type[k] / dyop.us_per_type[k]) << " |\n";
    }
    out << "\nEvery method over the same pairs (" << e.pairs_tested
        << " bounding-box-overlapping pairs, " << e.pairs_penetrating
        << " of them penetrating; and all " << scenes::paper::pair_count << " pairs × " << e.steps
        << " steps without a broad phase), errors against the exact rational reference:\n\n"
        << "\n";
    method_records(dyop).write_markdown(out);
    out << "\nThe paper (its Figure 7): DyOP-PD 10.765 ms against Lin–Canny 23.259 ms on average "
           "over its 90 steps, Lin–Canny / DyOP = 2.16. Here, on the overlapping pairs: "
           "Lin–Canny warm-started / dyop = "
        << fmt("%.2f", warm.us_total / dyop.us_total)
        << ", cold / dyop = " << fmt("%.2f", cold.us_total / dyop.us_total)
        << "; the paper's literal method (dyop-paper) against warm Lin–Canny: "
        << fmt("%.2f", warm.us_total / figures({Method::DyopPaper, false}).us_total) << ".\n";
  }

  // type, size, then one column per method (µs); `sep` ',' for CSV, ' ' for gnuplot.
  void figure7_data(std::ostream& o, char sep) const {
    const experiments::paper::Experiment& e = *experiment_;
    o << "type" << sep << "size" << sep << "pairs";
    for (const auto& m : e.methods) o << sep << adapters::name(m.method);
    o << '\n';
    for (int k = 0; k < scenes::paper::type_count; ++k) {
      const auto& t = scenes::paper::triangle_types()[k];
      const double size =
          std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
      o << k + 1 << sep << fmt("%.4g", size) << sep << e.pairs_per_type[k];
      for (const auto& m : e.methods) o << sep << fmt("%.6g", m.us_per_type[k]);
      o << '\n';
    }
  }

  // The figures of `which` (the first method's when it did not run).
  const experiments::paper::MethodFigures& figures(const adapters::Variant& which) const {
    for (const auto& m : experiment_->methods) {
      if (m.method == adapters::NarrowPhase{which}) return m;
    }
    return experiment_->methods.front();
  }

  // Every method's figures over the same pairs; the ratios against `dyop` (its own figures).
  Records method_records(const experiments::paper::MethodFigures& dyop) const {
    const experiments::paper::Experiment& e = *experiment_;
    const unsigned shown = where::table | where::markdown;
    Records out({{"method", "method", "", -15},
                 {"us_overlapping_pairs", "µs, overlapping pairs", "us", 10},
                 {"ns_per_pair", "ns/pair", "", 8},
                 {"ratio_vs_dyop", "× dyop", "x_dyop", 7, shown},
                 {"us_all_pairs", "µs, all pairs", "us_all", 10},
                 {"all_pairs_ratio_vs_dyop", "× dyop", "x_dyop", 7, shown},
                 {"error_max", "depth error max", "err_max", 9},
                 {"error_mean", "depth error mean", "err_mean", 9},
                 {"misclassified", "misclassified", "miscl", 6},
                 {"invalid", "invalid", "", 7},
                 {"pairs_tested", "", "", 8, where::files},
                 {"pairs_penetrating", "", "", 8, where::files},
                 {"steps", "", "", 6, where::files},
                 {"repetitions", "", "", 6, where::files}});
    for (const auto& m : e.methods) {
      out.add(
          {Value::text(adapters::name(m.method)), Value::number(m.us_total, "%.1f"),
           Value::number(m.ns_per_pair, "%.1f"), Value::number(m.us_total / dyop.us_total, "%.2f"),
           Value::number(m.us_all_pairs, "%.1f"),
           Value::number(m.us_all_pairs / dyop.us_all_pairs, "%.2f"), Value::metres(m.error_max),
           Value::metres(m.error_mean), Value::count(static_cast<std::int64_t>(m.misclassified)),
           Value::count(static_cast<std::int64_t>(m.invalid)),
           Value::count(static_cast<std::int64_t>(e.pairs_tested)),
           Value::count(static_cast<std::int64_t>(e.pairs_penetrating)), Value::count(e.steps),
           Value::count(e.repetitions)});
    }
    return out;
  }

  std::optional<experiments::paper::Experiment> experiment_;
};

}  // namespace

std::unique_ptr<CompareSection> make_paper_section() { return std::make_unique<PaperSection>(); }

}  // namespace dyop::report
