#include "report/thread_scaling_report.hpp"

#include <sstream>

#include "report/format.hpp"
#include "report/machine.hpp"

namespace dyop::report {

using scenes::ThreadScalingRecord;

void write_thread_scaling_table(const std::vector<ThreadScalingRecord>& records,
                                const std::string& scene, std::ostream& out) {
  out << "Worlds of '" << scene << "' on as many threads (" << machine_description() << "):\n";
  out << table_line("%-10s %7s %6s %10s %12s %8s\n", "runner", "threads", "steps", "seconds",
                    "steps/s", "x_own");
  for (const ThreadScalingRecord& r : records) {
    out << table_line("%-10s %7d %6d %10.3f %12.0f %8.3f\n", r.runner.c_str(), r.threads,
                      r.steps, r.seconds, r.steps_per_second, r.ratio_vs_own);
  }
}

void write_thread_scaling_csv(const std::vector<ThreadScalingRecord>& records,
                              std::ostream& out) {
  out << "runner,threads,steps,seconds,steps_per_second,ratio_vs_own\n";
  for (const ThreadScalingRecord& r : records) {
    out << r.runner << ',' << r.threads << ',' << r.steps << ',' << fmt("%.6g", r.seconds) << ','
        << fmt("%.6g", r.steps_per_second) << ',' << fmt("%.6g", r.ratio_vs_own) << '\n';
  }
}

std::string write_thread_scaling_outputs(const std::vector<ThreadScalingRecord>& records,
                                         const std::string& scene, ReportDirectory& dir) {
  dir.write("threads.csv", [&](std::ostream& o) { write_thread_scaling_csv(records, o); });
  return thread_scaling_markdown(records, scene);
}

std::string thread_scaling_markdown(const std::vector<ThreadScalingRecord>& records,
                                    const std::string& scene) {
  std::ostringstream md;
  md << "## Worlds on threads\n\nCopies of `" << scene << "`, one world per thread, "
     << (records.empty() ? 0 : records.front().steps)
     << " steps each, the plug-in's `dyop` installed against Box2D's own contact (the plug-in not "
        "installed), runs alternating in one process; the fastest run of each is kept. Steps per "
        "second count the steps of all worlds. Measured on "
     << machine_description()
     << ": more threads than cores share them.\n\n"
        "| runner | threads | seconds | steps per second | × own |\n|---|---|---|---|---|\n";
  for (const ThreadScalingRecord& r : records) {
    md << "| " << r.runner << " | " << r.threads << " | " << fmt("%.3f", r.seconds) << " | "
       << fmt("%.0f", r.steps_per_second) << " | " << fmt("%.3f", r.ratio_vs_own) << " |\n";
  }
  return md.str();
}

}  // namespace dyop::report
