// The paper experiment's methods, from the registry: which run, and each behind one call.
#include "measure/pair_function.hpp"
#include "scenes/paper_harness.hpp"

namespace dyop::scenes::paper {

std::vector<Variant> experiment_methods() {
  return variants([](const MethodInfo& row) { return measure::runs_pairs<float>(row.method); });
}

Variant variant_of(box2d::Backend backend) { return {backend, info(backend).warm_start()}; }

PairCall call_of(const Variant& v) { return {measure::pair_function<float>(v.method), v.warm}; }

}  // namespace dyop::scenes::paper
