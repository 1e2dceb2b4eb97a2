#pragma once
/// \file
/// What went wrong while writing a report, as a value with a kind: a command chooses its exit code
/// from the kind (`program/exit_codes.hpp`), never from the wording of the message.

#include <cstdint>
#include <string>
#include <vector>

namespace dyop::report {

/// The kinds of problem a report meets.
enum class ProblemKind : std::uint8_t {
  NotWritten,     ///< a file or directory could not be created or written: the output is incomplete
  ChartNotDrawn,  ///< gnuplot is missing or failed: the chart's script and data are still written
};

/// One problem, said for the user.
struct Problem {
  ProblemKind kind = ProblemKind::NotWritten;  ///< what kind of problem
  std::string message;                         ///< what happened, naming the file
};

/// The problem of `path` (a file or a directory) that could not be written: "cannot write 'path'",
/// followed by ": `reason`" when one is known.
Problem not_written(const std::string& path, const std::string& reason = {});

/// True when no problem in `problems` is `ProblemKind::NotWritten` (charts not drawn are allowed).
bool all_written(const std::vector<Problem>& problems);

}  // namespace dyop::report
