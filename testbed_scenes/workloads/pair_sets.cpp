#include "workloads/pair_sets.hpp"

#include <cmath>
#include <type_traits>

namespace dyop::workloads {

template <class T>
PairSet<T> make_pair_set(InputClass c, int count, std::uint64_t seed) {
  PairSet<T> set;
  // The next frame turns B by a thousandth of a radian about its first vertex and moves it by a
  // thousandth of the pair's size: the motion of one step of a simulation.
  const double turn = 1e-3;
  const Precision precision = std::is_same_v<T, float> ? Precision::Float : Precision::Double;
  for (const RawPair& q : make_pairs(c, count, seed, precision)) {
    const BuiltPair<T> now = build<T>(q);
    RawPair moved = q;
    const Vec2<double> pivot = q.b[0];
    const double step = 1e-3 * pair_size(q);
    for (Vec2<double>& v : moved.b) {
      const Vec2<double> d = v - pivot;
      v = pivot + Vec2<double>(std::cos(turn) * d.x() - std::sin(turn) * d.y() + step,
                               std::sin(turn) * d.x() + std::cos(turn) * d.y());
    }
    const BuiltPair<T> next = build<T>(moved);
    if (!now.a.ok() || !now.b.ok() || !next.b.ok()) continue;
    set.raw.push_back(q);
    set.a.push_back(now.a.triangle);
    set.b.push_back(now.b.triangle);
    set.b_next.push_back(next.b.triangle);
  }
  return set;
}

template PairSet<float> make_pair_set(InputClass, int, std::uint64_t);
template PairSet<double> make_pair_set(InputClass, int, std::uint64_t);

}  // namespace dyop::workloads
