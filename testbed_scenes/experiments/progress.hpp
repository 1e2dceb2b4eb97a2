#pragma once
// The runs' progress lines (standard error while a long run goes): seconds and ratios to a fixed
// number of decimals. The scenes write no report: tables and files are report/'s, with its own
// formatter.

#include <iomanip>
#include <sstream>
#include <string>

namespace dyop::experiments::detail {

/// `v` with `decimals` digits after the point, as printf's "%.<decimals>f" writes it.
inline std::string fixed(double v, int decimals) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << v;
  return out.str();
}

}  // namespace dyop::experiments::detail
