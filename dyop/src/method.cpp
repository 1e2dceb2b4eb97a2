#include "dyop/method.hpp"

namespace dyop {

const char* name(Method m) {
  switch (m) {
    case Method::Dyop: return "dyop";
    case Method::DyopFast: return "dyop-fast";
    case Method::DyopPaper: return "dyop-paper";
    case Method::LinCanny: return "lin-canny";
    case Method::Sat: return "sat";
    case Method::Epa: return "epa";
  }
  return "unknown";
}

std::optional<Method> parse_method(std::string_view s) {
  for (Method m : all_methods) {
    if (s == name(m)) return m;
  }
  return std::nullopt;
}

template <class T>
Result<T> penetrate(Method m, const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query,
                    LinCannyCache* cache) {
  switch (m) {
    case Method::Dyop: return dyop(a, b, query);
    case Method::DyopFast: return dyop_fast(a, b, query);
    case Method::DyopPaper: return dyop_paper(a, b, query);
    case Method::LinCanny: return lin_canny(a, b, query, cache);
    case Method::Sat: return sat(a, b, query);
    case Method::Epa: return epa(a, b, query);
  }
  Result<T> invalid;
  invalid.reason = InvalidReason::UnknownMethod;
  return invalid;
}

template Result<float> penetrate(Method, const Triangle<float>&, const Triangle<float>&,
                                 const Query<float>&, LinCannyCache*);
template Result<double> penetrate(Method, const Triangle<double>&, const Triangle<double>&,
                                  const Query<double>&, LinCannyCache*);

}  // namespace dyop
