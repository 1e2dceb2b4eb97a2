#include "scenes/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace dyop::scenes {

void ErrorTally::add(Status status, double depth, double exact_separation, double band) {
  ++evaluated_;
  if (status == Status::Invalid) {
    ++invalid_;
    return;
  }
  const double exact_depth = std::max(0.0, -exact_separation);
  const double error = std::abs(depth - exact_depth);
  max_ = std::max(max_, error);
  // Pairs that are apart by both accounts (most of what a broad phase lets through) would only
  // dilute the mean with exact zeros.
  if (depth > 0 || exact_depth > 0) {
    sum_ += error;
    ++overlapping_;
  }
  const bool says_penetrating = status == Status::Penetrating;
  if ((says_penetrating && exact_separation > band) ||
      (!says_penetrating && exact_separation < -band)) {
    ++misclassified_;
  }
}

void PenetrationTally::add(double depth) {
  max_ = std::max(max_, depth);
  sum_ += depth;
  ++count_;
}

SlideFigures summarize_sliders(std::vector<SliderFigures> sliders) {
  SlideFigures f;
  bool first = true;
  for (const SliderFigures& s : sliders) {
    if (s.rolling) continue;
    f.max_vertical_speed = std::max(f.max_vertical_speed, s.max_vertical_speed);
    f.max_angular_speed = std::max(f.max_angular_speed, s.max_angular_speed);
    f.min_travel = first ? s.travel : std::min(f.min_travel, s.travel);
    first = false;
  }
  f.sliders = std::move(sliders);
  return f;
}

bool all_finite(const SceneMetrics& m) {
  std::vector<double> values = {m.step_ms_median,       m.step_ms_total,
                                m.narrowphase_ms_total, m.narrowphase_ns_per_pair,
                                m.max_penetration,      m.mean_penetration,
                                m.pd_error_max,         m.pd_error_mean,
                                m.kinetic_energy_final, m.top_displacement.value_or(0.0)};
  if (m.slide) {
    for (const SliderFigures& s : m.slide->sliders) {
      values.insert(values.end(), {s.max_vertical_speed, s.max_angular_speed, s.travel});
    }
  }
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

void add_accuracy(const ErrorTally& errors, const PenetrationTally& penetration, SceneMetrics& m) {
  m.max_penetration = penetration.max();
  m.mean_penetration = penetration.mean();
  m.pd_error_max = errors.max();
  m.pd_error_mean = errors.mean();
  m.misclassified = errors.misclassified();
  m.invalid = errors.invalid();
}

}  // namespace dyop::scenes
