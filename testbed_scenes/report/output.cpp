#include "report/output.hpp"

#include <cerrno>
#include <cstring>

namespace dyop::report {

Output::Output(const std::string& path, std::ostream& standard)
    : path_(path), standard_(path == "-" ? &standard : nullptr) {
  if (standard_) return;
  file_.open(path);
  // errno is what the failed open left: a reason the user can act on (no such directory, ...).
  if (!file_.is_open()) open_error_ = std::strerror(errno);
}

std::optional<Problem> Output::open_problem() const {
  if (standard_ || file_.is_open()) return std::nullopt;
  return not_written(path_, open_error_);
}

std::ostream& Output::stream() { return standard_ ? *standard_ : file_; }

std::optional<Problem> Output::close() {
  if (standard_) {
    standard_->flush();
    if (!*standard_) return not_written("-", "standard output failed");
    return std::nullopt;
  }
  if (!file_.is_open()) return open_problem();
  file_.close();
  if (file_.fail()) return not_written(path_);
  return std::nullopt;
}

}  // namespace dyop::report
