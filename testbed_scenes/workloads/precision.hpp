#pragma once
/// \file
/// The scalar a workload is made for: its pairs are rounded to it, and a stress or bench run
/// measures the methods in it.

namespace dyop::workloads {

enum class Precision { Double, Float };

/// "double", "float".
inline const char* name(Precision p) { return p == Precision::Float ? "float" : "double"; }

}  // namespace dyop::workloads
