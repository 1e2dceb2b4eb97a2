#include "scenes/contact_probe.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cstring>
#include <functional>

#include "dyop/sat.hpp"
#include "adapters/pair_function.hpp"
#include "scenes/exact_pair.hpp"
#include "scenes/scene.hpp"
#include "scenes/world.hpp"

namespace dyop::scenes {
namespace {

const b2PolygonShape& polygon(const b2Fixture* f) {
  return *static_cast<const b2PolygonShape*>(f->GetShape());
}

Vec2<float> to_vec(const b2Vec2& v) { return {v.x, v.y}; }

// A fixture's broad-phase proxy for one child, as `b2ContactManager::Collide` reads it: the fixture
// keeps its proxies in a protected member, which a pointer to member formed in a derived class
// reads from any fixture.
struct FixtureProxies : b2Fixture {
  static int32 id(const b2Fixture& fixture, int32 child) {
    return (fixture.*(&FixtureProxies::m_proxies))[child].proxyId;
  }
};

// The exact depths of pairs, and for a pair apart only the proof (`Apart::Gap`): no search for
// its distance, which no tally reads (a depth of 0 either way).
const Query<double> gap_only = [] {
  Query<double> q;
  q.apart = Apart::Gap;
  return q;
}();

// A pair apart is handed to the tally by its gap when the gap exceeds the band by this factor.
// Why: the gap is at most the distance, but the two are rounded apart (by units in the last
// place): so far beyond the band, the distance is beyond it too.
constexpr double gap_beyond_band = 2;

// A triangle of float vertices in double.
TriangleOrError<double> widen(const Triangle<float>& t) {
  return Triangle<double>::make(t.vertex(0).cast<double>(), t.vertex(1).cast<double>(),
                                t.vertex(2).cast<double>());
}

// The same vertices to the bit (a signed zero or a NaN included).
bool same_points(const std::array<b2Vec2, 3>& p, const std::array<b2Vec2, 3>& q) {
  return std::memcmp(p.data(), q.data(), sizeof p) == 0;
}

// Collide skips a contact unless one of its bodies is awake and can move.
bool active(const b2Body* body) { return body->IsAwake() && body->GetType() != b2_staticBody; }

}  // namespace

double separation_as_tallied(const Triangle<double>& a, const Triangle<double>& b, double band) {
  const Result<double> r = sat(a, b, gap_only);
  if (r.status == Status::Separated && !(r.separation > gap_beyond_band * band)) {
    return sat(a, b).separation;
  }
  return r.separation;
}

std::size_t ContactProbe::PairHash::operator()(
    const std::pair<const b2Fixture*, const b2Fixture*>& p) const {
  const std::size_t a = std::hash<const void*>()(p.first);
  return a ^ (std::hash<const void*>()(p.second) + 0x9e3779b97f4a7c15ull + (a << 6) + (a >> 2));
}

CollideAction collide_action(const b2World& world, const b2Contact& contact) {
  const b2Fixture* fa = contact.GetFixtureA();
  const b2Fixture* fb = contact.GetFixtureB();
  if (!active(fa->GetBody()) && !active(fb->GetBody())) return CollideAction::Skip;
  const b2BroadPhase& bp = world.GetContactManager().m_broadPhase;
  if (!bp.TestOverlap(FixtureProxies::id(*fa, contact.GetChildIndexA()),
                      FixtureProxies::id(*fb, contact.GetChildIndexB()))) {
    return CollideAction::Destroy;
  }
  return CollideAction::Update;
}

bool toi_swept(const b2Contact& contact) {
  const b2Fixture* fa = contact.GetFixtureA();
  const b2Fixture* fb = contact.GetFixtureB();
  if (!contact.IsEnabled() || fa->IsSensor() || fb->IsSensor()) return false;
  const b2Body* a = fa->GetBody();
  const b2Body* b = fb->GetBody();
  if (!active(a) && !active(b)) return false;
  return a->IsBullet() || a->GetType() != b2_dynamicBody || b->IsBullet() ||
         b->GetType() != b2_dynamicBody;
}

ContactProbe::Updates ContactProbe::before_step(const b2World& world, ErrorTally& errors) {
  ++pass_;
  Updates u;
  for (const b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
    if (collide_action(world, *c) != CollideAction::Update) continue;
    const b2Fixture* fa = c->GetFixtureA();
    const b2Fixture* fb = c->GetFixtureB();
    ++u.contacts;
    if (!is_triangle(fa) || !is_triangle(fb)) continue;
    ++u.triangles;

    Cache& cache = caches_[{fa, fb}];
    const bool fresh = cache.seen + 1 != pass_;
    if (fresh) cache.cache = PairState{};  // a new contact starts cold
    cache.seen = pass_;

    // The plug-in's inputs: A as stored, B moved into A's body frame, in float. A's triangles are
    // made again when its vertices differ from those they were made from.
    const b2PolygonShape& a = polygon(fa);
    const b2PolygonShape& b = polygon(fb);
    const std::array<b2Vec2, 3> a_at = {a.m_vertices[0], a.m_vertices[1], a.m_vertices[2]};
    if (fresh || !same_points(a_at, cache.a_at)) {
      cache.a_at = a_at;
      cache.a = Triangle<float>::make(to_vec(a_at[0]), to_vec(a_at[1]), to_vec(a_at[2]));
      if (cache.a.ok()) cache.exact_a = widen(cache.a.triangle);
    }
    const b2Transform b_in_a = b2MulT(fa->GetBody()->GetTransform(), fb->GetBody()->GetTransform());
    const TriangleOrError<float> tb = Triangle<float>::make(to_vec(b2Mul(b_in_a, b.m_vertices[0])),
                                                            to_vec(b2Mul(b_in_a, b.m_vertices[1])),
                                                            to_vec(b2Mul(b_in_a, b.m_vertices[2])));
    if (!cache.a.ok() || !tb.ok()) {
      errors.add(Status::Invalid, 0, 0, 0);  // the plug-in falls back to Box2D on this pair
      continue;
    }
    const Triangle<float>& ta = cache.a.triangle;
    // The backend's depth, in float as the plug-in computes it (Lin–Canny warm-started from the
    // pair's cache; Box2D: the deepest point of its manifold).
    const Result<float> r = adapters::pair_function<float>(narrow_phase_of(backend_))(
        ta, tb.triangle, Query<float>{Level::Depth}, &cache.cache);
    const TriangleOrError<double>& xa = cache.exact_a;
    const TriangleOrError<double> xb = widen(tb.triangle);
    if (!xa.ok() || !xb.ok()) continue;  // valid in float, hence in double: never taken
    const double band = static_cast<double>(touching_tolerance<float>()) *
                        std::max(xa.triangle.size(), xb.triangle.size());
    errors.add(r.status, r.depth, separation_as_tallied(xa.triangle, xb.triangle, band), band);
  }
  // Contacts not met this pass are gone; forget their caches.
  for (auto it = caches_.begin(); it != caches_.end();) {
    it = it->second.seen == pass_ ? std::next(it) : caches_.erase(it);
  }
  return u;
}

void ContactProbe::measure_penetration(const b2World& world, PenetrationTally& depths) {
  for (const b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
    if (!c->IsTouching()) continue;
    if (const std::optional<ExactPair> pair = exact_pair(*c))
      depths.add(sat(pair->a, pair->b, gap_only).depth);
  }
}

}  // namespace dyop::scenes
