// The paper scene's methods: a backend's, and each behind one call.
#include "adapters/pair_function.hpp"
#include "scenes/paper_harness.hpp"

namespace dyop::scenes::paper {

Variant variant_of(box2d::Backend backend) { return {backend, info(backend).warm_start()}; }

PairCall call_of(const Variant& v) { return {adapters::pair_function<float>(v.method), v.warm}; }

}  // namespace dyop::scenes::paper
