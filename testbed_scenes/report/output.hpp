#pragma once
/// \file
/// An output named on the command line (`--json FILE|-`, `--output FILE`, ...): the file, or
/// standard output for "-". The file is opened at once, so that a command can refuse an unwritable
/// path before it runs anything.

#include <fstream>
#include <optional>
#include <ostream>
#include <string>

#include "report/problem.hpp"

namespace dyop::report {

/// A file opened for writing (truncated), or `standard` for "-".
class Output {
 public:
  /// Opens `path`; "-" writes to `standard` instead.
  Output(const std::string& path, std::ostream& standard);

  /// Why the file could not be opened; none for "-" or an opened file.
  std::optional<Problem> open_problem() const;
  /// Where to write (check `open_problem` first).
  std::ostream& stream();
  /// Flushes (and closes a file); the problem if anything written was lost.
  std::optional<Problem> close();

 private:
  std::string path_;
  std::ostream* standard_;  // "-" only
  std::ofstream file_;
  std::string open_error_;  // why the file did not open
};

/// Writes `write(stream)` to `path`, or to `standard` for "-"; the problem if it failed.
template <class Write>
std::optional<Problem> write_output(const std::string& path, std::ostream& standard,
                                    Write&& write) {
  Output out(path, standard);
  if (std::optional<Problem> p = out.open_problem()) return p;
  write(out.stream());
  return out.close();
}

}  // namespace dyop::report
