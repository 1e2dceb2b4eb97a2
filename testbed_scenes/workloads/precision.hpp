#pragma once
/// \file
/// The scalar a workload is made for: its pairs are rounded to it, and a stress or bench run
/// measures the methods in it.

#include <type_traits>

namespace dyop::workloads {

enum class Precision { Double, Float };

/// "double", "float".
inline const char* name(Precision p) { return p == Precision::Float ? "float" : "double"; }

/// The precision of the scalar `T` (float or double).
template <class T>
constexpr Precision precision_of() {
  return std::is_same_v<T, float> ? Precision::Float : Precision::Double;
}

/// The bound of "exact", relative to the pair's size: double 1e-12; float 1e-5 (on float input).
/// Why: the figures; both are far above the rounding of an exact method (a few eps) and
/// far below the error of a wrong axis or feature. Also the tolerance of an invariance check.
constexpr double exact_bound(Precision p) { return p == Precision::Float ? 1e-5 : 1e-12; }

}  // namespace dyop::workloads
