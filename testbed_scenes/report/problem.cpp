#include "report/problem.hpp"

#include <algorithm>

namespace dyop::report {

Problem not_written(const std::string& path, const std::string& reason) {
  return {ProblemKind::NotWritten,
          "cannot write '" + path + "'" + (reason.empty() ? std::string() : ": " + reason)};
}

bool all_written(const std::vector<Problem>& problems) {
  return std::none_of(problems.begin(), problems.end(),
                      [](const Problem& p) { return p.kind == ProblemKind::NotWritten; });
}

}  // namespace dyop::report
