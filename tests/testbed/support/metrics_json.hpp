#pragma once
// Test support: a scene's metrics as the report writes them, parsed back as JSON.

#include <nlohmann/json.hpp>
#include <sstream>

#include "report/metrics_io.hpp"
#include "scenes/metrics.hpp"

namespace dyop::scenes::testing {

// `m` written by `report::write_json` and parsed back (throws on invalid JSON).
inline nlohmann::json json_of(const SceneMetrics& m) {
  std::ostringstream out;
  report::write_json(m, out);
  return nlohmann::json::parse(out.str());
}

}  // namespace dyop::scenes::testing
