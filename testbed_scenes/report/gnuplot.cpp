#include "report/gnuplot.hpp"

#include <cstdlib>
#include <fstream>

namespace dyop::report {

ChartResult run_gnuplot(const std::string& script, const std::string& script_path) {
  ChartResult out;
  {
    std::ofstream file(script_path);
    file << script;
    if (!file) {
      out.message = "cannot write " + script_path;
      return out;
    }
  }
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    out.message = "gnuplot not found (Debian package gnuplot-nox): chart skipped, script kept at " +
                  script_path;
    return out;
  }
  const std::string command = "gnuplot '" + script_path + "' 2>&1";
  if (std::system(command.c_str()) != 0) {
    out.message = "gnuplot failed on " + script_path;
    return out;
  }
  out.ok = true;
  return out;
}

}  // namespace dyop::report
