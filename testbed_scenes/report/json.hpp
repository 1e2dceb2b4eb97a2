#pragma once
/// \file
/// The reports' JSON, through nlohmann-json: keys stay in the order they are written. Declared
/// only (nlohmann's forward header): a file that builds or reads values includes
/// `<nlohmann/json.hpp>` itself, so that the many files that only pass a value on do not compile
/// the library.

#include <iosfwd>
#include <nlohmann/json_fwd.hpp>

namespace dyop::report {

/// A JSON value whose object keys keep the order they were written in.
using Json = nlohmann::ordered_json;

/// A figure as JSON: null when non-finite (JSON has no NaN or infinity).
Json json_number(double v);

/// `document` indented by two spaces, then a newline.
void write_json_document(const Json& document, std::ostream& out);

}  // namespace dyop::report
