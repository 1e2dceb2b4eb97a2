#include "scenes/metrics_io.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <type_traits>

namespace dyop::scenes {
namespace {

using Json = nlohmann::ordered_json;

Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

template <class T>
Json optional(const std::optional<T>& v) {
  if (!v) return Json(nullptr);
  if constexpr (std::is_floating_point_v<T>) {
    return number(*v);
  } else {
    return Json(*v);
  }
}

Json to_json(const SceneMetrics& m) {
  Json j;
  j["scene"] = m.scene;
  j["backend"] = m.backend;
  j["seed"] = m.seed;
  j["steps"] = m.steps;
  j["bodies"] = m.bodies;
  j["triangles"] = m.triangles;
  j["triangle_pairs"] = m.triangle_pairs;
  j["contact_updates"] = m.contact_updates;
  j["plugin_evaluations"] = optional(m.plugin_evaluations);
  j["fallbacks"] = optional(m.fallbacks);
  j["step_ms_median"] = number(m.step_ms_median);
  j["narrowphase_ms_total"] = number(m.narrowphase_ms_total);
  j["narrowphase_ns_per_pair"] = number(m.narrowphase_ns_per_pair);
  j["max_penetration"] = number(m.max_penetration);
  j["mean_penetration"] = number(m.mean_penetration);
  j["pd_error_max"] = number(m.pd_error_max);
  j["pd_error_mean"] = number(m.pd_error_mean);
  j["misclassified"] = m.misclassified;
  j["invalid"] = m.invalid;
  j["kinetic_energy_final"] = number(m.kinetic_energy_final);
  j["top_displacement"] = optional(m.top_displacement);
  j["nan_detected"] = m.nan_detected || !all_finite(m);  // a null above means a NaN
  j["hash"] = hash_hex(m.hash);
  return j;
}

}  // namespace

const std::vector<std::string>& metrics_keys() {
  static const std::vector<std::string> keys = [] {
    const Json j = to_json(SceneMetrics{});  // named: items() refers to it
    std::vector<std::string> out;
    for (const auto& item : j.items()) out.push_back(item.key());
    return out;
  }();
  return keys;
}

void write_json(const SceneMetrics& m, std::ostream& out) { out << to_json(m).dump(2) << '\n'; }

std::string csv_header() {
  std::string h;
  for (const std::string& key : metrics_keys()) h += (h.empty() ? "" : ",") + key;
  return h;
}

std::string csv_row(const SceneMetrics& m) {
  const Json j = to_json(m);
  std::ostringstream row;
  row.precision(9);
  bool first = true;
  for (const auto& [key, value] : j.items()) {
    if (!first) row << ',';
    first = false;
    if (value.is_null()) continue;
    if (value.is_string()) {
      row << value.get<std::string>();  // names and hex digits: no commas or quotes
    } else if (value.is_boolean()) {
      row << (value.get<bool>() ? "true" : "false");
    } else if (value.is_number_float()) {
      row << value.get<double>();
    } else {
      row << value.dump();
    }
  }
  return row.str();
}

std::string hash_hex(std::uint64_t hash) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

}  // namespace dyop::scenes
