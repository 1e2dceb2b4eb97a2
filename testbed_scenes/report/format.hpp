#pragma once
/// \file
/// The one number formatter of the reports (aligned tables, Markdown, CSV, charts' data): header
/// only, printf's conversions so that every figure reads the same wherever it is written.

#include <cmath>
#include <cstdio>
#include <string>

namespace dyop::report {

/// `v` through printf's `format` (one conversion); "n/a" for a non-finite value.
inline std::string fmt(const char* format, double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

/// A figure in a CSV file: six significant digits, "n/a" when non-finite.
inline std::string csv_number(double v) { return fmt("%.6g", v); }

/// A length or an error in metres: "0" or three significant digits in exponent form.
inline std::string metres(double v) { return v == 0 ? "0" : fmt("%.2e", v); }

/// One line of an aligned table: `args` through printf's `format` (which ends the line itself).
template <class... Args>
std::string table_line(const char* format, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

}  // namespace dyop::report
