#include "dyop/sat.hpp"

#include "detail/certify_axes.hpp"

namespace dyop {

template <class T>
Result<T> sat(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query) {
  return detail::certify_axes(detail::PairFrame<T>(a, b), query);
}

template Result<float> sat(const Triangle<float>&, const Triangle<float>&, const Query<float>&);
template Result<double> sat(const Triangle<double>&, const Triangle<double>&,
                            const Query<double>&);

}  // namespace dyop
