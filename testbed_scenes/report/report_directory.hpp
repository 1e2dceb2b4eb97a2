#pragma once
/// \file
/// A report directory (`dyop bench --out`, `dyop compare --out`): the files written in it, the
/// charts drawn in it, and the problems met, as values.

#include <fstream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "report/problem.hpp"

namespace dyop::report {

/// A report directory, created (with its parents) when constructed.
class ReportDirectory {
 public:
  /// Creates `dir` if needed; when it cannot, the problem is the first of `problems()`.
  explicit ReportDirectory(std::string dir);

  /// The directory could be created (or existed).
  bool created() const { return created_; }
  /// `file` inside the directory.
  std::string path(const std::string& file) const { return dir_ + "/" + file; }
  /// `file` inside the directory as a gnuplot string, for a script's `plot` and `set output`.
  std::string quoted(const std::string& file) const;

  /// Writes `file` with `body(stream)`; false (and a `NotWritten` problem) if it failed.
  template <class Body>
  bool write(const std::string& file, Body&& body) {
    std::ofstream out(path(file));
    body(out);
    out.close();
    if (!out) problems_.push_back(not_written(path(file)));
    return static_cast<bool>(out);
  }

  /// Draws `name`.svg with gnuplot: the script (kept as `name`.gp) is `set terminal` with
  /// `terminal`, `set output` on the chart's quoted path, then `body`, which names its data files
  /// through `quoted`. False (and the problem) when the chart was not drawn.
  bool chart(const std::string& name, const std::string& terminal, const std::string& body);

  /// Adds a problem met elsewhere.
  void add(Problem problem) { problems_.push_back(std::move(problem)); }
  /// Every problem so far, in the order met.
  const std::vector<Problem>& problems() const { return problems_; }

 private:
  std::string dir_;
  bool created_ = false;
  std::vector<Problem> problems_;
};

}  // namespace dyop::report
