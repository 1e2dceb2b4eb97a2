#include "program/pair_backend.hpp"

#include "dyop/method.hpp"
#ifdef DYOP_WITH_BOX2D
#include "box2d_reference/collide_triangles.hpp"
#endif

namespace dyop::cli {
namespace {

template <Method M, class T>
Result<T> run_method(const Triangle<T>& a, const Triangle<T>& b) {
  return penetrate(M, a, b, Query<T>{Level::Depth});
}

template <Method M>
PairBackend method_backend() {
  return {name(M), &run_method<M, double>, &run_method<M, float>};
}

Vec2<double> widen(const Vec2<float>& v) { return v.cast<double>(); }

}  // namespace

std::vector<PairBackend> pair_backends() {
  std::vector<PairBackend> out = {method_backend<Method::Dyop>(),     method_backend<Method::DyopFast>(),
                                  method_backend<Method::DyopPaper>(), method_backend<Method::LinCanny>(),
                                  method_backend<Method::Sat>(),      method_backend<Method::Epa>()};
#ifdef DYOP_WITH_BOX2D
  out.push_back({"box2d", nullptr, &dyop::box2d::collide_triangles});
#endif
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
