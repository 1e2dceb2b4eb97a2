#include "report/json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

namespace dyop::report {

Json json_number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

void write_json_document(const Json& document, std::ostream& out) {
  out << document.dump(2) << '\n';
}

}  // namespace dyop::report
