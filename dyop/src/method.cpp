#include "dyop/method.hpp"

namespace dyop {

std::optional<Method> parse_method(std::string_view s, RowFilter keep) {
  for (const MethodInfo& row : method_table) {
    if (s == row.name && (keep == nullptr || keep(row))) return row.method;
  }
  return std::nullopt;
}

template <class T>
Result<T> penetrate(Method m, const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query,
                    PairState* state) {
  const PairFunction<T> run = info(m).run<T>();
  if (run == nullptr) {
    Result<T> invalid;
    invalid.reason = InvalidReason::NotPairMethod;
    return invalid;
  }
  return run(a, b, query, state);
}

template Result<float> penetrate(Method, const Triangle<float>&, const Triangle<float>&,
                                 const Query<float>&, PairState*);
template Result<double> penetrate(Method, const Triangle<double>&, const Triangle<double>&,
                                  const Query<double>&, PairState*);

}  // namespace dyop
