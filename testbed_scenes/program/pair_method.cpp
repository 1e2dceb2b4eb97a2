#include "program/pair_method.hpp"

#include "adapters/pair_function.hpp"

namespace dyop::cli {
namespace {

Vec2<double> widen(const Vec2<float>& v) { return v.cast<double>(); }

}  // namespace

std::vector<PairMethod> pairs_methods() {
  std::vector<PairMethod> out;
  for (const adapters::NarrowPhase& p : adapters::narrow_phases(nullptr, true)) {
    const bool batch = adapters::call_of(p) == adapters::Call::Batch;
    if (!(batch || adapters::runs_pairs<float>(p)) || (p.method && p.method->warm)) continue;
    // Cold only: one way to run each here.
    // A method's own spelling ("lin-canny", not its cold variant's).
    const char* spelling = p.method ? dyop::name(p.method->method) : adapters::name(p);
    out.push_back(
        {p, spelling, adapters::pair_function<double>(p), adapters::pair_function<float>(p)});
  }
  return out;
}

Result<double> widen(const Result<float>& r) {
  Result<double> out;
  out.status = r.status;
  out.reason = r.reason;
  out.separation = r.separation;
  out.depth = r.depth;
  out.normal = widen(r.normal);
  out.witness_a = widen(r.witness_a);
  out.witness_b = widen(r.witness_b);
  out.feature_a = r.feature_a;
  out.feature_b = r.feature_b;
  out.iterations = r.iterations;
  out.manifold.point_count = r.manifold.point_count;
  out.manifold.reference_is_a = r.manifold.reference_is_a;
  out.manifold.reference_edge = r.manifold.reference_edge;
  out.manifold.incident_edge = r.manifold.incident_edge;
  out.manifold.normal = widen(r.manifold.normal);
  for (int i = 0; i < 2; ++i) {
    out.manifold.points[i].point = widen(r.manifold.points[i].point);
    out.manifold.points[i].separation = r.manifold.points[i].separation;
    out.manifold.points[i].key = r.manifold.points[i].key;
  }
  return out;
}

}  // namespace dyop::cli
