#include "workloads/raw_pair.hpp"

namespace dyop::workloads {
namespace {

using V = Vec2<double>;

}  // namespace

bool valid_in_double(const std::array<V, 3>& t) {
  return Triangle<double>::make(t[0], t[1], t[2]).ok();
}

bool valid_in_double(const RawPair& p) { return valid_in_double(p.a) && valid_in_double(p.b); }

PairBox pair_box(const RawPair& p) {
  PairBox box{p.a[0], p.a[0]};
  for (const auto* t : {&p.a, &p.b}) {
    for (const V& v : *t) {
      box.lo = box.lo.cwiseMin(v);
      box.hi = box.hi.cwiseMax(v);
    }
  }
  return box;
}

double pair_size(const RawPair& p) {
  const PairBox box = pair_box(p);
  return (box.hi - box.lo).norm();
}

// Through a volatile float: GCC 12.2 at -O2 folds a vectorised double → float → double round trip
// of two coordinates into nothing (wrong code; found by the stress tests, where the rounding went
// missing).
double rounded_to(Precision p, double x) {
  if (p == Precision::Double) return x;
  const volatile float f = static_cast<float>(x);
  return f;
}

V rounded_to(Precision precision, const V& v) {
  return {rounded_to(precision, v.x()), rounded_to(precision, v.y())};
}

RawPair rounded_to(Precision precision, const RawPair& p) {
  RawPair out = p;
  for (auto* t : {&out.a, &out.b}) {
    for (V& v : *t) v = rounded_to(precision, v);
  }
  return out;
}

RawPair rounded_to_float(const RawPair& p) { return rounded_to(Precision::Float, p); }

}  // namespace dyop::workloads
