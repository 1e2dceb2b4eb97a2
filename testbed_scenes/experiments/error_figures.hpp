#pragma once
// Internal to the experiments: the figures of a list of errors that `dyop bench` and `dyop stress`
// report.

#include <algorithm>
#include <vector>

namespace dyop::experiments {

// The largest error and the 99th percentile (the value below which 99 % of them lie).
struct ErrorFigures {
  double max = 0;
  double p99 = 0;
};

// The figures of `errors`, which it sorts; zeros when there is none.
inline ErrorFigures error_figures(std::vector<double>& errors) {
  if (errors.empty()) return {};
  std::sort(errors.begin(), errors.end());
  const std::size_t p99 =
      std::min(errors.size() - 1, static_cast<std::size_t>(0.99 * errors.size()));
  return {errors.back(), errors[p99]};
}

}  // namespace dyop::experiments
