#include "report/bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

#include "report/format.hpp"
#include "report/gnuplot.hpp"
#include "report/json.hpp"
#include "report/machine.hpp"

namespace dyop::report {
namespace {

using experiments::BenchRecord;

// Points not dominated in both time and error: the methods worth choosing.
std::vector<const BenchRecord*> pareto_front(std::vector<const BenchRecord*> points) {
  std::sort(points.begin(), points.end(), [](const BenchRecord* x, const BenchRecord* y) {
    return x->ns_per_pair < y->ns_per_pair;
  });
  std::vector<const BenchRecord*> front;
  double best_error = INFINITY;
  for (const BenchRecord* p : points) {
    if (p->err_max < best_error) {
      front.push_back(p);
      best_error = p->err_max;
    }
  }
  return front;
}

}  // namespace

Records bench_records(const std::vector<BenchRecord>& records) {
  const unsigned shown = where::table | where::markdown;
  Records out({{"method", "method", "", -15},
               {"class", "class", "", -13},
               {"level", "level", "", -8},
               {"precision", "precision", "prec", -6},
               {"pairs", "pairs", "", 6, where::files},
               {"timed_pairs", "", "", 7, where::files},
               {"ns_per_pair", "ns/pair", "ns/pair", 9},
               {"ratio_vs_box2d", "× box2d", "xbox2d", 8},
               {"err_max", "err max", "", 10},
               {"err_mean", "err mean", "", 10},
               {"err_p99", "err p99", "", 10},
               {"exact_fraction", "", "", 7, where::files},
               {"exact_percent", "exact", "exact%", 7, shown},
               {"normal_err_max", "", "", 10, where::files},
               {"normal_err_mean", "", "", 10, where::files},
               {"misclassified", "misclassified", "miscl", 6},
               {"invalid", "invalid", "inval", 5}});
  for (const BenchRecord& r : records) {
    out.add({Value::text(adapters::name(r.method)), Value::text(workloads::name(r.cls)),
             Value::text(name(r.level)), Value::text(workloads::name(r.precision)),
             Value::count(r.pairs), Value::count(r.timed_pairs),
             Value::number(r.ns_per_pair, "%.1f"), Value::number(r.ratio_vs_box2d, "%.3f"),
             Value::number(r.err_max, "%.2e"), Value::number(r.err_mean, "%.2e"),
             Value::number(r.err_p99, "%.2e"), Value::number(r.exact_fraction, "%.3f"),
             Value::number(100 * r.exact_fraction, "%.1f%%"),
             Value::number(r.normal_err_max, "%.2e"), Value::number(r.normal_err_mean, "%.2e"),
             Value::count(r.misclassified), Value::count(r.invalid)});
  }
  return out;
}

void write_outputs(const std::vector<BenchRecord>& records, ReportDirectory& dir,
                   const std::string& sections) {
  if (!dir.created()) return;
  const Records described = bench_records(records);
  dir.write("bench.csv", [&](std::ostream& o) { described.write_csv(o); });
  dir.write("bench.json", [&](std::ostream& o) { write_json_document(described.json(), o); });

  // The chart: each method at the Depth level (Box2D: its only level) on the overlapping class,
  // float; errors at or below 1e-17 are drawn at 1e-17 ("exact": a log axis has no zero).
  std::vector<const BenchRecord*> points;
  for (const BenchRecord& r : records) {
    if (r.cls == workloads::InputClass::Overlapping && r.precision == workloads::Precision::Float &&
        (r.level == Level::Depth || r.method == adapters::NarrowPhase::box2d())) {
      points.push_back(&r);
    }
  }
  auto write_points = [](std::ostream& o, const std::vector<const BenchRecord*>& which) {
    for (const BenchRecord* p : which) {
      write_data_line(o, adapters::name(p->method), {p->ns_per_pair, std::max(p->err_max, 1e-17)});
    }
  };
  dir.write("time_vs_error.dat", [&](std::ostream& o) {
    o << "# method ns_per_pair err_max(floored at 1e-17)\n";
    write_points(o, points);
  });
  dir.write("pareto.dat", [&](std::ostream& o) { write_points(o, pareto_front(points)); });
  dir.chart("time_vs_error", "svg size 900,600 dynamic background rgb 'white'",
            "set title 'Run time against error: overlapping pairs, float, Depth level (box2d: "
            "full manifold)'\n"
            "set logscale xy\nset format y '10^{%L}'\nset xlabel 'ns per pair (median)'\n"
            "set ylabel 'max |depth error| / pair size (1e-17 = exact)'\nset grid\n"
            "set key top right\n"
            "plot " +
                dir.quoted("time_vs_error.dat") +
                " using 2:3 with points pt 7 ps 1.2 title 'methods', \\\n"
                "     '' using 2:3:1 with labels offset 1,1 left notitle, \\\n"
                "     " +
                dir.quoted("pareto.dat") + " using 2:3 with steps lw 2 title 'Pareto front'\n");

  dir.write("report.md", [&](std::ostream& o) {
    o << "# dyop bench\n\nRun time against error per method, input class, query level and "
         "precision. Times are medians over timed passes of 131,072 distinct pairs (more than a "
         "branch predictor learns; errors are checked on the first 8192); `xbox2d` is the "
         "ratio to Box2D's `b2CollidePolygons` (full manifold, float) on the same class in the "
         "same run. Errors are |depth − exact depth| / pair size against the exact rational "
         "reference. Measured on "
      << machine_description() << " (" << batch_kernel_description() << ")"
      << ": ratios move between hosts of one machine kind (AVX-512 or not), so name the CPU "
         "beside any figure taken from here.\n\n![time against error](time_vs_error.svg)\n\n";
    described.write_markdown(o);
    if (!sections.empty()) o << '\n' << sections;
  });
}

}  // namespace dyop::report
