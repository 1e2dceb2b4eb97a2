#include "report/report_directory.hpp"

#include <filesystem>

#include "report/gnuplot.hpp"

namespace dyop::report {

ReportDirectory::ReportDirectory(std::string dir) : dir_(std::move(dir)) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  created_ = !ec;
  if (ec) problems_.push_back(not_written(dir_, ec.message()));
}

std::string ReportDirectory::quoted(const std::string& file) const {
  return gnuplot_quote(path(file));
}

bool ReportDirectory::chart(const std::string& name, const std::string& terminal,
                            const std::string& body) {
  const std::string script =
      "set terminal " + terminal + "\nset output " + quoted(name + ".svg") + "\n" + body;
  std::optional<Problem> problem = run_gnuplot(script, path(name + ".gp"));
  if (problem) problems_.push_back(std::move(*problem));
  return !problem;
}

}  // namespace dyop::report
