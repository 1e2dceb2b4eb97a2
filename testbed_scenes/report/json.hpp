#pragma once
/// \file
/// The reports' JSON, through nlohmann-json: keys stay in the order they are written.

#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

namespace dyop::report {

/// A JSON value whose object keys keep the order they were written in.
using Json = nlohmann::ordered_json;

/// A figure as JSON: null when non-finite (JSON has no NaN or infinity).
inline Json json_number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

/// `document` indented by two spaces, then a newline.
inline void write_json_document(const Json& document, std::ostream& out) {
  out << document.dump(2) << '\n';
}

}  // namespace dyop::report
