#include "report/bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>

#include "dyop/sat.hpp"
#include "exact_reference/exact_reference.hpp"
#include "measure/bench_runners.hpp"
#include "report/format.hpp"
#include "report/gnuplot.hpp"
#include "report/json.hpp"

namespace dyop::report {
namespace {

constexpr std::uint64_t kSeed = 2026;
// A depth error at or below this fraction of the pair's size counts as exact: far above double
// rounding (1e-16), far below any error a heuristic makes.
constexpr double kExactRelTol = 1e-9;

// The reference answers of one class in one precision: the exact separation and sat's normal.
struct Reference {
  std::vector<double> separation;
  std::vector<int> sign;
  std::vector<Vec2<double>> normal;
  std::vector<double> size;
};

template <class T>
Reference reference_of(const workloads::PairSet<T>& set) {
  Reference ref;
  for (const workloads::RawPair& p : set.raw) {
    const workloads::ExactAnswer exact = workloads::exact_separation(p);
    ref.separation.push_back(exact.separation);
    ref.sign.push_back(exact.sign);
    const auto t = workloads::build<double>(p);
    ref.normal.push_back(sat(t.a.triangle, t.b.triangle).normal);
    ref.size.push_back(workloads::pair_size(p));
  }
  return ref;
}

template <class T>
void measure_errors(const std::vector<measure::Answer<T>>& got, const Reference& ref, BenchRecord& rec) {
  std::vector<double> errors;
  double angle_sum = 0;
  int angles = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    if (got[k].status == Status::Invalid) {
      ++rec.invalid;
      continue;
    }
    const double size = ref.size[k];
    const double band = 4 * touching_tolerance<T>() * size;
    const bool exact_penetrating = ref.sign[k] < 0;
    if (std::abs(ref.separation[k]) > band &&
        exact_penetrating != (got[k].status == Status::Penetrating)) {
      ++rec.misclassified;
    }
    const double depth = std::max(0.0, -static_cast<double>(got[k].separation));
    const double exact_depth = std::max(0.0, -ref.separation[k]);
    errors.push_back(std::abs(depth - exact_depth) / size);
    if (exact_penetrating && got[k].status == Status::Penetrating && exact_depth > 1e-6 * size) {
      const double c = std::clamp(got[k].normal.template cast<double>().dot(ref.normal[k]), -1.0, 1.0);
      const double angle = std::acos(c);
      rec.normal_err_max = std::max(rec.normal_err_max, angle);
      angle_sum += angle;
      ++angles;
    }
  }
  rec.normal_err_mean = angles ? angle_sum / angles : 0;
  if (errors.empty()) return;
  std::sort(errors.begin(), errors.end());
  rec.err_max = errors.back();
  double sum = 0;
  int exact = 0;
  for (double e : errors) {
    sum += e;
    exact += e <= kExactRelTol;
  }
  rec.err_mean = sum / static_cast<double>(errors.size());
  rec.err_p99 = errors[std::min(errors.size() - 1, static_cast<std::size_t>(0.99 * errors.size()))];
  rec.exact_fraction = static_cast<double>(exact) / static_cast<double>(errors.size());
}

template <class T>
void run_precision(const BenchOptions& options, workloads::InputClass c,
                   std::map<std::string, double>& box2d_ns, std::vector<BenchRecord>& records,
                   std::ostream& progress) {
  constexpr bool is_float = std::is_same_v<T, float>;
  const char* precision = is_float ? "float" : "double";
  const int passes = options.quick ? 5 : 21;
  const workloads::PairSet<T> set = workloads::make_pair_set<T>(c, options.pairs, kSeed);
  const Reference ref = reference_of(set);
  for (const Variant& v : measure::bench_variants()) {
    BenchRecord base;
    base.method = name(v);
    base.cls = workloads::name(c);
    base.precision = precision;
    base.pairs = static_cast<int>(set.size());
    bool any = false;
    for (Level l : all_levels) {
      if (!measure::supports(v, l, is_float)) continue;
      if (!any) measure_errors(measure::answers(v, set), ref, base);
      any = true;
      BenchRecord rec = base;
      rec.level = name(l);
      rec.ns_per_pair = measure::time_per_pair(v, set, l, passes);
      if (v.method == Method::Box2D) box2d_ns[rec.cls] = rec.ns_per_pair;
      records.push_back(rec);
    }
    if (any) {
      progress << "dyop bench: " << base.cls << " " << precision << " " << base.method << " done\n";
    }
  }
}

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

std::vector<BenchRecord> run_bench(const BenchOptions& options, std::ostream& progress) {
  std::vector<BenchRecord> records;
  std::map<std::string, double> box2d_ns;
  for (workloads::InputClass c : workloads::bench_classes) {
    run_precision<float>(options, c, box2d_ns, records, progress);
    run_precision<double>(options, c, box2d_ns, records, progress);
  }
  for (BenchRecord& r : records) {
    const auto it = box2d_ns.find(r.cls);
    r.ratio_vs_box2d = it != box2d_ns.end() && it->second > 0 ? r.ns_per_pair / it->second : 0;
  }
  return records;
}

void write_table(const std::vector<BenchRecord>& records, std::ostream& out) {
  out << table_line("%-15s %-13s %-8s %-6s %9s %8s %10s %10s %10s %7s %6s %5s\n", "method",
                    "class", "level", "prec", "ns/pair", "xbox2d", "err_max", "err_p99",
                    "err_mean", "exact%", "miscl", "inval");
  for (const BenchRecord& r : records) {
    out << table_line("%-15s %-13s %-8s %-6s %9.1f %8.3f %10.2e %10.2e %10.2e %7.1f %6d %5d\n",
                      r.method.c_str(), r.cls.c_str(), r.level.c_str(), r.precision.c_str(),
                      r.ns_per_pair, r.ratio_vs_box2d, r.err_max, r.err_p99, r.err_mean,
                      100 * r.exact_fraction, r.misclassified, r.invalid);
  }
}

void write_csv(const std::vector<BenchRecord>& records, std::ostream& out) {
  out << "method,class,level,precision,pairs,ns_per_pair,ratio_vs_box2d,err_max,err_mean,err_p99,"
         "exact_fraction,normal_err_max,normal_err_mean,misclassified,invalid\n";
  for (const BenchRecord& r : records) {
    out << r.method << ',' << r.cls << ',' << r.level << ',' << r.precision << ',' << r.pairs
        << ',' << fmt("%.6g", r.ns_per_pair) << ',' << fmt("%.6g", r.ratio_vs_box2d) << ','
        << fmt("%.6g", r.err_max) << ',' << fmt("%.6g", r.err_mean) << ','
        << fmt("%.6g", r.err_p99) << ',' << fmt("%.6g", r.exact_fraction) << ','
        << fmt("%.6g", r.normal_err_max) << ',' << fmt("%.6g", r.normal_err_mean) << ','
        << r.misclassified << ',' << r.invalid << '\n';
  }
}

void write_json(const std::vector<BenchRecord>& records, std::ostream& out) {
  Json list = Json::array();
  for (const BenchRecord& r : records) {
    list.push_back({{"method", r.method},
                    {"class", r.cls},
                    {"level", r.level},
                    {"precision", r.precision},
                    {"pairs", r.pairs},
                    {"ns_per_pair", json_number(r.ns_per_pair)},
                    {"ratio_vs_box2d", json_number(r.ratio_vs_box2d)},
                    {"err_max", json_number(r.err_max)},
                    {"err_mean", json_number(r.err_mean)},
                    {"err_p99", json_number(r.err_p99)},
                    {"exact_fraction", json_number(r.exact_fraction)},
                    {"normal_err_max", json_number(r.normal_err_max)},
                    {"normal_err_mean", json_number(r.normal_err_mean)},
                    {"misclassified", r.misclassified},
                    {"invalid", r.invalid}});
  }
  write_json_document(list, out);
}

void write_outputs(const std::vector<BenchRecord>& records, ReportDirectory& dir,
                   const std::string& sections) {
  if (!dir.created()) return;
  dir.write("bench.csv", [&](std::ostream& o) { write_csv(records, o); });
  dir.write("bench.json", [&](std::ostream& o) { write_json(records, o); });

  // The chart: each method at the Depth level (Box2D: its only level) on the overlapping class,
  // float; errors at or below 1e-17 are drawn at 1e-17 ("exact": a log axis has no zero).
  std::vector<const BenchRecord*> points;
  for (const BenchRecord& r : records) {
    if (r.cls == "overlapping" && r.precision == "float" &&
        (r.level == "depth" || r.method == "box2d")) {
      points.push_back(&r);
    }
  }
  auto write_points = [](std::ostream& o, const std::vector<const BenchRecord*>& which) {
    for (const BenchRecord* p : which) {
      write_data_line(o, p->method, {p->ns_per_pair, std::max(p->err_max, 1e-17)});
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
            "plot " + dir.quoted("time_vs_error.dat") +
                " using 2:3 with points pt 7 ps 1.2 title 'methods', \\\n"
                "     '' using 2:3:1 with labels offset 1,1 left notitle, \\\n"
                "     " + dir.quoted("pareto.dat") +
                " using 2:3 with steps lw 2 title 'Pareto front'\n");

  dir.write("report.md", [&](std::ostream& o) {
    o << "# dyop bench\n\nRun time against error per method, input class, query level and "
         "precision. Times are medians over timed passes of 8192 distinct pairs; `xbox2d` is the "
         "ratio to Box2D's `b2CollidePolygons` (full manifold, float) on the same class in the "
         "same run. Errors are |depth − exact depth| / pair size against the exact rational "
         "reference.\n\n![time against error](time_vs_error.svg)\n\n";
    o << "| method | class | level | precision | ns/pair | × box2d | err max | err p99 | err mean "
         "| exact | misclassified | invalid |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const BenchRecord& r : records) {
      o << "| " << r.method << " | " << r.cls << " | " << r.level << " | " << r.precision << " | "
        << fmt("%.1f", r.ns_per_pair) << " | " << fmt("%.3f", r.ratio_vs_box2d) << " | "
        << fmt("%.2e", r.err_max) << " | " << fmt("%.2e", r.err_p99) << " | "
        << fmt("%.2e", r.err_mean) << " | " << fmt("%.1f%%", 100 * r.exact_fraction) << " | "
        << r.misclassified << " | " << r.invalid << " |\n";
    }
    if (!sections.empty()) o << '\n' << sections;
  });
}

}  // namespace dyop::report
