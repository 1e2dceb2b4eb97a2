#pragma once
/// \file
/// The machine a report's figures were measured on: wall-time ratios move between hosts of one
/// kind (AVX-512 or not), so every timed table names the CPU beside its figures.

#include <string>

namespace dyop::report {

/// The CPU's model name as the kernel reports it (`model name` in /proc/cpuinfo, as `lscpu`
/// shows it) and the number of hardware threads, e.g. "AMD EPYC, 2 hardware threads";
/// "unknown CPU, N hardware threads" where /proc/cpuinfo does not say.
std::string machine_description();

/// The batch kernel `penetrate_batch` runs here unless one is forced (`dyop::batch_kernel_used`),
/// as "batch kernel avx512": its time depends on the CPU's vector extensions.
std::string batch_kernel_description();

}  // namespace dyop::report
