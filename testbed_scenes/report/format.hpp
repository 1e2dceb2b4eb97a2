#pragma once
// Number formatting for the tables and reports (and the scenes' progress lines): header only.

#include <cmath>
#include <cstdio>
#include <string>

namespace dyop::scenes::detail {

/// `v` through printf's `format` (one conversion); "n/a" for a non-finite value.
inline std::string fmt(const char* format, double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

/// A length or an error in metres: "0" or three significant digits in exponent form.
inline std::string metres(double v) { return v == 0 ? "0" : fmt("%.2e", v); }

}  // namespace dyop::scenes::detail
