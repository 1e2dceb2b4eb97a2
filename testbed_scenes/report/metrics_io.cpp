#include "report/metrics_io.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <type_traits>

#include "report/json.hpp"
#include "scenes/skips.hpp"

namespace dyop::report {
namespace {

using scenes::SceneMetrics;
using scenes::SlideFigures;
using scenes::SliderFigures;

template <class T>
Json optional(const std::optional<T>& v) {
  if (!v) return Json(nullptr);
  if constexpr (std::is_floating_point_v<T>) {
    return json_number(*v);
  } else {
    return Json(*v);
  }
}

Json skip_config(const std::optional<box2d::Config>& config) {
  if (!config) return Json(nullptr);
  Json names = Json::array();
  for (const std::string& n : scenes::skip_names(*config)) names.push_back(n);
  return names;
}

Json manifold_errors(const std::optional<scenes::ManifoldErrors>& e) {
  if (!e) return Json(nullptr);
  Json j;
  j["touching"] = e->touching;
  j["kept_max"] = json_number(e->kept_max);
  j["stale"] = e->stale;
  j["checked"] = e->checked;
  j["depth_max"] = json_number(e->depth_max);
  j["normal_max"] = json_number(e->normal_max);
  return j;
}

Json skips(const std::optional<std::array<std::uint64_t, box2d::skip_count>>& counts) {
  if (!counts) return Json(nullptr);
  Json j;
  for (int s = 0; s < box2d::skip_count; ++s)
    j[box2d::name(static_cast<box2d::Skip>(s))] = (*counts)[s];
  return j;
}

Json slide(const std::optional<SlideFigures>& f) {
  if (!f) return Json(nullptr);
  Json j;
  j["max_vertical_speed"] = json_number(f->max_vertical_speed);
  j["max_angular_speed"] = json_number(f->max_angular_speed);
  j["min_travel"] = json_number(f->min_travel);
  Json sliders = Json::array();
  for (const SliderFigures& s : f->sliders) {
    Json one;
    one["body"] = s.body;
    one["ground"] = s.ground;
    one["rolling"] = s.rolling;
    one["max_vertical_speed"] = json_number(s.max_vertical_speed);
    one["max_angular_speed"] = json_number(s.max_angular_speed);
    one["travel"] = json_number(s.travel);
    sliders.push_back(one);
  }
  j["sliders"] = sliders;
  return j;
}

// A list of records (an array of objects, such as `slide.sliders`) has no CSV column: it is in
// the JSON, and `dyop compare` writes it in a CSV of its own.
bool json_only(const Json& value) {
  return value.is_array() && !value.empty() && value.front().is_object();
}

Json to_json(const SceneMetrics& m) {
  Json j;
  j["scene"] = m.scene;
  j["runner"] = scenes::name(m.runner);
  j["seed"] = m.seed;
  j["steps"] = m.steps;
  j["bodies"] = m.bodies;
  j["triangles"] = m.triangles;
  j["triangle_pairs"] = m.triangle_pairs;
  j["contact_updates"] = m.contact_updates;
  j["toi_swept"] = m.toi_swept;
  j["plugin_evaluations"] = optional(m.plugin_evaluations);
  j["fallbacks"] = optional(m.fallbacks);
  j["skip_config"] = skip_config(m.skip_config);
  j["skips"] = skips(m.skips);
  j["recycle_distance"] =
      m.skip_config ? json_number(m.skip_config->recycle_distance) : Json(nullptr);
  j["recycled"] = optional(m.recycled);
  j["step_ms_median"] = json_number(m.step_ms_median);
  j["step_ms_total"] = json_number(m.step_ms_total);
  j["narrowphase_ms_total"] = json_number(m.narrowphase_ms_total);
  j["narrowphase_ns_per_pair"] = json_number(m.narrowphase_ns_per_pair);
  j["solve_toi_ms_total"] = json_number(m.solve_toi_ms_total);
  j["max_penetration"] = json_number(m.max_penetration);
  j["mean_penetration"] = json_number(m.mean_penetration);
  j["pd_error_max"] = json_number(m.pd_error_max);
  j["pd_error_mean"] = json_number(m.pd_error_mean);
  j["misclassified"] = m.misclassified;
  j["invalid"] = m.invalid;
  j["kinetic_energy_final"] = json_number(m.kinetic_energy_final);
  j["top_displacement"] = optional(m.top_displacement);
  j["slide"] = slide(m.slide);
  j["manifold_errors"] = manifold_errors(m.manifold_errors);
  j["nan_detected"] = m.nan_detected || !all_finite(m);  // a null above means a NaN
  j["hash"] = hash_hex(m.hash);
  return j;
}

// A record with every optional figure present: its JSON has every key and sub-key.
const Json& full_record() {
  static const Json j = [] {
    SceneMetrics m;
    m.skip_config.emplace();
    m.skips.emplace();
    m.recycled.emplace();
    m.manifold_errors.emplace();
    m.slide.emplace();
    m.slide->sliders.emplace_back();
    return to_json(m);
  }();
  return j;
}

// One CSV cell: empty for null, strings bare, an array's strings separated by spaces.
std::string csv_cell(const Json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) return value.get<std::string>();  // names and hex digits: no commas
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_array()) {
    std::string out;
    for (const Json& v : value) out += (out.empty() ? "" : " ") + csv_cell(v);
    return out;
  }
  if (value.is_number_float()) {
    std::ostringstream number;
    number.precision(9);
    number << value.get<double>();
    return number.str();
  }
  return value.dump();
}

}  // namespace

const std::vector<std::string>& metrics_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const auto& item : full_record().items()) out.push_back(item.key());
    return out;
  }();
  return keys;
}

const std::vector<std::string>& csv_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> out;
    for (const auto& item : full_record().items()) {
      if (!item.value().is_object()) {
        out.push_back(item.key());
        continue;
      }
      for (const auto& sub : item.value().items()) {
        if (!json_only(sub.value())) out.push_back(item.key() + "." + sub.key());
      }
    }
    return out;
  }();
  return columns;
}

void write_json(const SceneMetrics& m, std::ostream& out) { out << to_json(m).dump(2) << '\n'; }

std::string csv_header() {
  std::string h;
  for (const std::string& column : csv_columns()) h += (h.empty() ? "" : ",") + column;
  return h;
}

std::string csv_row(const SceneMetrics& m) {
  const Json j = to_json(m);
  std::string row;
  bool first = true;
  auto cell = [&](const Json& value) {
    row += (first ? "" : ",") + csv_cell(value);
    first = false;
  };
  for (const auto& item : full_record().items()) {
    const Json& value = j.at(item.key());
    if (!item.value().is_object()) {
      cell(value);
      continue;
    }
    for (const auto& sub : item.value().items()) {
      if (!json_only(sub.value())) cell(value.is_null() ? Json(nullptr) : value.at(sub.key()));
    }
  }
  return row;
}

std::string hash_hex(std::uint64_t hash) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

}  // namespace dyop::report
