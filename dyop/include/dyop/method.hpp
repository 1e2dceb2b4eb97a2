#pragma once
/// \file
/// One dispatcher over every penetration-depth method, for callers that choose at run time.

#include <cstdint>
#include <optional>
#include <string_view>

#include "dyop/dyop.hpp"
#include "dyop/dyop_paper.hpp"
#include "dyop/epa.hpp"
#include "dyop/lin_canny.hpp"
#include "dyop/result.hpp"
#include "dyop/sat.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// The methods of the library; `name` gives each one's command-line spelling.
enum class Method : std::uint8_t {
  Dyop,       ///< `dyop`: DyOP-PD with certification, exact
  DyopFast,   ///< `dyop-fast`: the pivot heuristic alone, approximate
  DyopPaper,  ///< `dyop-paper`: the paper's equations literally, for reproduction
  LinCanny,   ///< `lin-canny`: closest-feature tracking, local-minimum depth
  Sat,        ///< `sat`: the exact reference
  Epa,        ///< `epa`: GJK + EPA
};

/// Every method, in declaration order.
inline constexpr Method all_methods[] = {Method::Dyop,     Method::DyopFast, Method::DyopPaper,
                                         Method::LinCanny, Method::Sat,      Method::Epa};

/// The command-line spelling: "dyop", "dyop-fast", "dyop-paper", "lin-canny", "sat", "epa".
const char* name(Method m);

/// The method spelt `s`, or nothing.
std::optional<Method> parse_method(std::string_view s);

/// Runs method `m`. `cache` is used by `LinCanny` only (nullptr: cold start).
template <class T>
Result<T> penetrate(Method m, const Triangle<T>& a, const Triangle<T>& b,
                    const Query<T>& query = {}, LinCannyCache* cache = nullptr);

extern template Result<float> penetrate(Method, const Triangle<float>&, const Triangle<float>&,
                                        const Query<float>&, LinCannyCache*);
extern template Result<double> penetrate(Method, const Triangle<double>&,
                                         const Triangle<double>&, const Query<double>&,
                                         LinCannyCache*);

}  // namespace dyop
