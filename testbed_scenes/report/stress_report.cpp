#include "report/stress_report.hpp"

#include <map>
#include <ostream>

#include "report/format.hpp"
#include "report/json.hpp"

namespace dyop::report {

using experiments::Invariance;
using experiments::invariance_count;
using experiments::StressRecord;
using workloads::InputClass;

Records stress_records(const std::vector<StressRecord>& records) {
  std::vector<Column> columns = {{"precision", "precision", "prec", -6},
                                 {"class", "class", "", -16},
                                 {"method", "method", "", -14},
                                 {"pairs", "pairs", "", 6},
                                 {"rejected", "rejected", "rej", 5},
                                 {"err_max", "err max", "", 9},
                                 {"err_p99", "err p99", "", 9},
                                 {"nonfinite", "NaN/inf", "nonfin", 6},
                                 {"misclassified", "misclassified", "miscl", 5}};
  // One column per invariance check: `invariance_translation` (inv_t), ...
  const char* abbreviations[invariance_count] = {"inv_t", "inv_r", "inv_o", "inv_s"};
  for (int k = 0; k < invariance_count; ++k) {
    const std::string check = name(static_cast<Invariance>(k));
    columns.push_back({"invariance_" + check, check + " violations", abbreviations[k], 5});
  }
  columns.push_back({"invalid_by_design", "invalid by design", "design", 6});
  columns.push_back({"invalid", "invalid", "", 7});
  columns.push_back({"worst_pair", "worst pair", "", 0, where::json});
  Records out(std::move(columns));
  for (const StressRecord& r : records) {
    std::vector<Value> row = {Value::text(workloads::name(r.precision)),
                              Value::text(workloads::name(r.cls)),
                              Value::text(adapters::name(r.method)),
                              Value::count(r.pairs),
                              Value::count(r.rejected),
                              Value::number(r.err_max, "%.2e"),
                              Value::number(r.err_p99, "%.2e"),
                              Value::count(r.nonfinite),
                              Value::count(r.misclassified)};
    for (int k = 0; k < invariance_count; ++k) row.push_back(Value::count(r.invariance[k]));
    row.push_back(Value::count(r.invalid_by_design));
    row.push_back(Value::count(r.invalid));
    row.push_back(Value::text(r.worst_pair));
    out.add(std::move(row));
  }
  return out;
}

Records convex_stress_records(const std::vector<experiments::ConvexStressRecord>& records) {
  Records out({{"precision", "precision", "prec", -6},
               {"class", "class", "", -11},
               {"family", "pairs of", "", -15},
               {"pairs", "pairs", "", 6},
               {"err_max", "err max", "", 9},
               {"err_p99", "err p99", "", 9},
               {"nonfinite", "NaN/inf", "nonfin", 6},
               {"misclassified", "misclassified", "miscl", 5},
               {"winding", "winding violations", "wind", 5}});
  for (const experiments::ConvexStressRecord& r : records) {
    out.add({Value::text(workloads::name(r.precision)), Value::text(workloads::name(r.cls)),
             Value::text(experiments::name(r.family)), Value::count(r.pairs),
             Value::number(r.err_max, "%.2e"), Value::number(r.err_p99, "%.2e"),
             Value::count(r.nonfinite), Value::count(r.misclassified), Value::count(r.winding)});
  }
  return out;
}

void write_markdown(const std::vector<StressRecord>& records, std::ostream& out) {
  std::vector<std::string> classes;
  for (InputClass c : workloads::stress_classes) classes.push_back(workloads::name(c));
  for (const workloads::Precision p : {workloads::Precision::Double, workloads::Precision::Float}) {
    const char* precision = workloads::name(p);
    std::map<std::string, std::map<std::string, const StressRecord*>> by_method;
    std::vector<std::string> methods;
    for (const StressRecord& r : records) {
      if (r.precision != p) continue;
      const std::string method = adapters::name(r.method);
      if (by_method.find(method) == by_method.end()) methods.push_back(method);
      by_method[method][workloads::name(r.cls)] = &r;
    }
    if (methods.empty()) continue;
    out << "\nMax (99th percentile) |separation error| / pair size, " << precision
        << ":\n\n| method |";
    for (const std::string& c : classes) out << ' ' << c << " |";
    out << "\n|---|";
    for (std::size_t i = 0; i < classes.size(); ++i) out << "---|";
    out << '\n';
    for (const std::string& m : methods) {
      out << "| " << m << " |";
      for (const std::string& c : classes) {
        const auto it = by_method[m].find(c);
        if (it == by_method[m].end()) {
          out << " |";
          continue;
        }
        out << ' ' << fmt("%.1e", it->second->err_max) << " (" << fmt("%.0e", it->second->err_p99)
            << ") |";
      }
      out << '\n';
    }
    out << "\nCounts over the " << classes.size() << " categories, " << precision
        << " (invariance: translation / rotation / reorder / swap):\n\n"
           "| method | pairs | rejected | NaN/inf | misclassified | invariance violations | "
           "invalid by design | invalid |\n|---|---|---|---|---|---|---|---|\n";
    for (const std::string& m : methods) {
      StressRecord sum;
      for (const auto& [cls, r] : by_method[m]) {
        sum.pairs += r->pairs;
        sum.rejected += r->rejected;
        sum.nonfinite += r->nonfinite;
        sum.misclassified += r->misclassified;
        for (int k = 0; k < invariance_count; ++k) sum.invariance[k] += r->invariance[k];
        sum.invalid_by_design += r->invalid_by_design;
        sum.invalid += r->invalid;
      }
      out << "| " << m << " | " << sum.pairs << " | " << sum.rejected << " | " << sum.nonfinite
          << " | " << sum.misclassified << " | " << sum.invariance[0] << " / " << sum.invariance[1]
          << " / " << sum.invariance[2] << " / " << sum.invariance[3] << " | "
          << sum.invalid_by_design << " | " << sum.invalid << " |\n";
    }
  }
}

}  // namespace dyop::report
