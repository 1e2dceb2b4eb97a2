#include "adapters/pair_function.hpp"

#include <type_traits>

#ifdef DYOP_WITH_BOX2D
#include "box2d_reference/collide_triangles.hpp"
#endif

namespace dyop::adapters {
namespace {

#ifdef DYOP_WITH_BOX2D
Result<float> box2d_pair(const Triangle<float>& a, const Triangle<float>& b, const Query<float>&,
                         PairState*) {
  return box2d::collide_triangles(a, b);
}
#endif

}  // namespace

template <class T>
PairFunction<T> pair_function(const NarrowPhase& p) {
  switch (call_of(p)) {
    case Call::PerPair:
      return info(p.method->method).run<T>();
    case Call::Batch:
      return nullptr;
    case Call::Box2D:
#ifdef DYOP_WITH_BOX2D
      if constexpr (std::is_same_v<T, float>) return &box2d_pair;
#endif
      return nullptr;
  }
  return nullptr;
}

template PairFunction<float> pair_function<float>(const NarrowPhase&);
template PairFunction<double> pair_function<double>(const NarrowPhase&);

}  // namespace dyop::adapters
