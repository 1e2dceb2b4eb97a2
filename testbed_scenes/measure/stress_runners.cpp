#include "measure/stress_runners.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

#include "dyop/batch.hpp"
#include "dyop/method.hpp"
#include "workloads/finite_fields.hpp"
#ifdef DYOP_WITH_BOX2D
#include "box2d_reference/collide_triangles.hpp"
#endif

namespace dyop::report {
namespace {

std::optional<Method> method_of(StressRunner r) {
  switch (r) {
    case StressRunner::Dyop: return Method::Dyop;
    case StressRunner::DyopFast: return Method::DyopFast;
    case StressRunner::DyopPaper: return Method::DyopPaper;
    case StressRunner::LinCanny: return Method::LinCanny;
    case StressRunner::Sat: return Method::Sat;
    case StressRunner::Epa: return Method::Epa;
    default: return std::nullopt;
  }
}

using workloads::finite_at;

template <class T>
StressAnswer answer_of(const Result<T>& r, bool finite) {
  StressAnswer a;
  a.status = r.status;
  a.separation = static_cast<double>(r.separation);
  a.finite = finite;
  return a;
}

template <class T>
std::vector<StressAnswer> method_answers(Method m, const std::vector<workloads::RawPair>& pairs,
                                         bool with_manifold) {
  std::vector<StressAnswer> out(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto t = workloads::build<T>(pairs[k]);
    if (!t.a.ok() || !t.b.ok()) continue;
    LinCannyCache cache;
    const Result<T> r = penetrate(m, t.a.triangle, t.b.triangle, Query<T>{Level::Depth}, &cache);
    bool finite = finite_at(r, Level::Depth);
    if (with_manifold) {
      // A speculative margin of a hundredth of the larger triangle, as Box2D's skins are to a
      // metre-sized body: separated pairs within it get a manifold too.
      Query<T> q{Level::Manifold};
      q.margin = T(0.01) * std::max(t.a.triangle.size(), t.b.triangle.size());
      finite = finite && finite_at(penetrate(m, t.a.triangle, t.b.triangle, q, &cache), q.level);
    }
    out[k] = answer_of(r, finite);
  }
  return out;
}

template <class T>
std::vector<StressAnswer> batch_answers(const std::vector<workloads::RawPair>& pairs) {
  const std::size_t n = pairs.size();
  std::vector<T> c[12];
  for (auto& v : c) v.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      c[2 * i][k] = static_cast<T>(pairs[k].a[i].x());
      c[2 * i + 1][k] = static_cast<T>(pairs[k].a[i].y());
      c[6 + 2 * i][k] = static_cast<T>(pairs[k].b[i].x());
      c[7 + 2 * i][k] = static_cast<T>(pairs[k].b[i].y());
    }
  }
  const PairBatch<T> batch{c[0].data(), c[1].data(), c[2].data(), c[3].data(),
                           c[4].data(), c[5].data(), c[6].data(), c[7].data(),
                           c[8].data(), c[9].data(), c[10].data(), c[11].data(), n};
  std::vector<Status> status(n);
  std::vector<T> separation(n), nx(n), ny(n);
  std::vector<StressAnswer> out(n);
  if (penetrate_batch(batch, Level::Depth,
                      BatchOutput<T>{status.data(), separation.data(), nx.data(), ny.data()}) !=
      BatchError::None) {
    for (StressAnswer& a : out) a.verdict_mismatch = true;
    return out;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto t = workloads::build<T>(pairs[k]);
    const BatchRowError e = batch_row_error(batch, k);
    StressAnswer& a = out[k];
    a.verdict_mismatch = e.a != t.a.error || e.b != t.b.error ||
                         (status[k] == Status::Invalid) != !(t.a.ok() && t.b.ok());
    if (status[k] == Status::Invalid) continue;
    a.status = status[k];
    a.separation = static_cast<double>(separation[k]);
    a.finite = std::isfinite(separation[k]) && std::isfinite(nx[k]) && std::isfinite(ny[k]);
  }
  return out;
}

#ifdef DYOP_WITH_BOX2D
std::vector<StressAnswer> box2d_answers(const std::vector<workloads::RawPair>& pairs) {
  std::vector<StressAnswer> out(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto t = workloads::build<float>(pairs[k]);
    if (!t.a.ok() || !t.b.ok()) continue;
    const Result<float> r = box2d::collide_triangles(t.a.triangle, t.b.triangle);
    out[k] = answer_of(r, finite_at(r, Level::Contact));
  }
  return out;
}
#endif

}  // namespace

const char* name(StressRunner r) {
  if (const std::optional<Method> m = method_of(r)) return name(*m);
  return r == StressRunner::Batch ? "batch" : "box2d";
}

bool runs(StressRunner r, bool is_float) {
  if (r != StressRunner::Box2D) return true;
#ifdef DYOP_WITH_BOX2D
  return is_float;
#else
  (void)is_float;
  return false;
#endif
}

template <class T>
std::vector<StressAnswer> stress_answers(StressRunner r, const std::vector<workloads::RawPair>& pairs,
                                         bool with_manifold) {
  if (const std::optional<Method> m = method_of(r)) return method_answers<T>(*m, pairs, with_manifold);
  if (r == StressRunner::Batch) return batch_answers<T>(pairs);
#ifdef DYOP_WITH_BOX2D
  if constexpr (std::is_same_v<T, float>) return box2d_answers(pairs);
#endif
  return std::vector<StressAnswer>(pairs.size());
}

template std::vector<StressAnswer> stress_answers<float>(StressRunner,
                                                         const std::vector<workloads::RawPair>&, bool);
template std::vector<StressAnswer> stress_answers<double>(StressRunner,
                                                          const std::vector<workloads::RawPair>&, bool);

}  // namespace dyop::report
