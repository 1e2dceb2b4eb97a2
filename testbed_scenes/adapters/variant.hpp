#pragma once
/// \file
/// A method as a comparison runs it: a warm-startable method (`MethodInfo::warm_start`) either
/// cold, every query from no state, or warm, each query from the state the pair's previous query
/// left; the others one way only. Its spelling names the way only where there are two
/// ("lin-canny-cold", "lin-canny-warm"; "dyop").

#include <vector>

#include "dyop/method.hpp"

namespace dyop::adapters {

/// One way of running one of the registry's methods.
struct Variant {
  Method method = Method::Dyop;  ///< the registry's row
  bool warm = false;             ///< warm-startable methods only: from the previous query's state
};

/// The spellings of the warm-startable methods' two runs: one row per method whose
/// `info(method).warm_start()` holds (tests/method_registry_test.cpp checks it).
struct WarmStartSpelling {
  Method method;     ///< the registry's row
  const char* cold;  ///< its run from no state
  const char* warm;  ///< its run from the pair's previous query
};
inline constexpr WarmStartSpelling warm_start_spellings[] = {
    {Method::LinCanny, "lin-canny-cold", "lin-canny-warm"},
};

/// The spelling of `m` run cold (`warm == false`) or warm-started: the row of
/// `warm_start_spellings` for a warm-startable method, `name(m)` for the others.
constexpr const char* variant_name(Method m, bool warm) {
  for (const WarmStartSpelling& row : warm_start_spellings) {
    if (row.method == m) return warm ? row.warm : row.cold;
  }
  return name(m);
}

/// `variant_name(v.method, v.warm)`: "lin-canny-cold", "lin-canny-warm", "dyop", ...
constexpr const char* name(const Variant& v) { return variant_name(v.method, v.warm); }

/// True when `x` and `y` are the same way of running the same method.
constexpr bool operator==(const Variant& x, const Variant& y) {
  return x.method == y.method && x.warm == y.warm;
}
/// True when `x` and `y` differ in method or warmth.
constexpr bool operator!=(const Variant& x, const Variant& y) { return !(x == y); }

/// Every variant of the rows `keep(row)` accepts, in registry order, cold before warm.
template <class Keep>
std::vector<Variant> variants(Keep keep) {
  std::vector<Variant> out;
  for (const MethodInfo& row : method_table) {
    if (!keep(row)) continue;
    out.push_back({row.method, false});
    if (row.warm_start()) out.push_back({row.method, true});
  }
  return out;
}

}  // namespace dyop::adapters
