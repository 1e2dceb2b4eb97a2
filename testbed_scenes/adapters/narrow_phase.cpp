#include "adapters/narrow_phase.hpp"

namespace dyop::adapters {
namespace {

// Box2D's spelling, and whether this build links it.
constexpr const char* kBox2DName = "box2d";
#ifdef DYOP_WITH_BOX2D
constexpr bool kBox2DBuilt = true;
#else
constexpr bool kBox2DBuilt = false;
#endif

}  // namespace

bool operator==(const NarrowPhase& x, const NarrowPhase& y) { return x.method == y.method; }

const char* name(const NarrowPhase& p) { return p.method ? adapters::name(*p.method) : kBox2DName; }

Call call_of(const NarrowPhase& p) {
  if (!p.method) return Call::Box2D;
  return info(p.method->method).entry == Entry::Batch ? Call::Batch : Call::PerPair;
}

bool has(const NarrowPhase& p, Level level) {
  return p.method ? info(p.method->method).has(level) : level == Level::Manifold;
}

bool runs_double(const NarrowPhase& p) { return p.method && info(p.method->method).runs_double(); }

bool built(const NarrowPhase& p) { return p.method || kBox2DBuilt; }

std::vector<NarrowPhase> narrow_phases(RowFilter keep, bool with_box2d) {
  std::vector<NarrowPhase> out;
  for (const Variant& v :
       variants([&](const MethodInfo& row) { return keep == nullptr || keep(row); })) {
    out.push_back({v});
  }
  if (with_box2d && kBox2DBuilt) out.push_back(NarrowPhase::box2d());
  return out;
}

std::optional<NarrowPhase> parse_narrow_phase(std::string_view s) {
  if (s == kBox2DName) return kBox2DBuilt ? std::optional(NarrowPhase::box2d()) : std::nullopt;
  const std::optional<Method> m = parse_method(s);
  return m ? std::optional(NarrowPhase::of(*m)) : std::nullopt;
}

}  // namespace dyop::adapters
