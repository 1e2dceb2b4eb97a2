#pragma once
/// \file
/// What a warm-startable method keeps between queries of the same pair (temporal coherence):
/// one `PairState` per pair, owned by the caller, handed back at the pair's next query. The
/// registry's per-pair entry points (`dyop/method.hpp`) all take one; the methods that keep no
/// state (`MethodInfo::warm_start()` false) ignore it. Value-initialised, it is cold: the next
/// query starts from nothing. It holds no heap memory and is trivially copyable (the Box2D
/// plug-in keeps one in every contact), and callers never look inside: a method's state is its
/// own business.

#include <type_traits>

#include "dyop/lin_canny.hpp"

namespace dyop {

/// The warm-start state of one pair, for every method that keeps one.
struct PairState {
  LinCannyCache lin_canny;  ///< `Method::LinCanny`: the last feature pair and depth axis
};

static_assert(std::is_trivially_copyable_v<PairState>, "a pair's state is copied as bytes");

}  // namespace dyop
