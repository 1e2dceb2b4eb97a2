#include "report/bench_sections.hpp"

#include <sstream>

#include "report/machine.hpp"

namespace dyop::report {

using experiments::ThreadScalingRecord;

Records thread_scaling_records(const std::vector<ThreadScalingRecord>& records) {
  Records out({{"runner", "runner", "", -10},
               {"threads", "threads", "", 7},
               {"steps", "steps", "", 6, where::table | where::files},
               {"seconds", "seconds", "", 10},
               {"steps_per_second", "steps per second", "steps/s", 12},
               {"ratio_vs_own", "× own", "x_own", 8}});
  for (const ThreadScalingRecord& r : records) {
    out.add({Value::text(scenes::name(r.runner)), Value::count(r.threads), Value::count(r.steps),
             Value::number(r.seconds, "%.3f"), Value::number(r.steps_per_second, "%.0f"),
             Value::number(r.ratio_vs_own, "%.3f")});
  }
  return out;
}

void write_thread_scaling_table(const std::vector<ThreadScalingRecord>& records,
                                const std::string& scene, std::ostream& out) {
  out << "Worlds of '" << scene << "' on as many threads (" << machine_description() << "):\n";
  thread_scaling_records(records).write_table(out);
}

std::string write_thread_scaling_outputs(const std::vector<ThreadScalingRecord>& records,
                                         const std::string& scene, ReportDirectory& dir) {
  dir.write("threads.csv", [&](std::ostream& o) { thread_scaling_records(records).write_csv(o); });
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
     << machine_description() << ": more threads than cores share them.\n\n";
  thread_scaling_records(records).write_markdown(md);
  return md.str();
}

}  // namespace dyop::report
