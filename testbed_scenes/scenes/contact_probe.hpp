#pragma once
/// \file
/// Measures a Box2D world's narrow phase from outside `b2World::Step`, without changing what the
/// step does.
///
/// Before a step, `ContactProbe::before_step` walks the world's contacts and picks exactly those
/// `b2ContactManager::Collide` is about to update (Box2D 2.4.1's rule: at least one body awake and
/// not static, and the two proxies' fat AABBs still overlapping; filters never change in the
/// scenes). It counts them, and re-evaluates every triangle pair among them twice, untimed, on the
/// plug-in's own inputs (A's vertices as stored, B's moved into A's body frame by
/// `b2MulT(xfA, xfB)`, in float):
/// - with the backend at `Level::Depth` (Lin–Canny warm-started by a cache per fixture pair that
///   lives as long as the contact does, like the plug-in's; `box2d`:
///   `dyop::box2d::collide_triangles`, the deepest point of `b2CollidePolygons`' manifold);
/// - with the exact reference, `dyop::sat` in double on the same float vertices.
/// The plug-in itself answers at `Level::Manifold`; the depth is the part of that answer the
/// exact reference can check.
///
/// After a step, `measure_penetration` takes the exact depth (`sat` in double, B moved into A's
/// frame in double) of every touching triangle pair: how far the cores overlap.

#include <box2d/b2_math.h>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "dyop/box2d.hpp"
#include "dyop/triangle.hpp"
#include "scenes/metrics.hpp"

class b2World;
class b2Fixture;
class b2Contact;

namespace dyop::scenes {

/// What the coming `b2World::Step` does with a contact in `b2ContactManager::Collide`.
enum class CollideAction : std::uint8_t {
  Skip,     ///< neither body awake and movable: the contact is left as it is
  Destroy,  ///< the two proxies' fat AABBs no longer overlap: the contact ends
  Update,   ///< `b2Contact::Update`, hence `Evaluate` (the narrow phase)
};

/// Box2D 2.4.1's rule in `b2ContactManager::Collide`, read from outside the step: a contact is
/// updated when at least one of its bodies is awake and not static and the two proxies' fat AABBs
/// still overlap (filters never change in the scenes, so the filter check never fires). The
/// proxies are read from the fixtures as `Collide` reads them: fixtures made or destroyed between
/// steps need no notice.
CollideAction collide_action(const b2World& world, const b2Contact& contact);

/// Box2D 2.4.1's rule in `b2World::SolveTOI`: a contact whose time of impact it computes
/// (`b2TimeOfImpact`), touching or not, is enabled, has no sensor, and has a body awake and not
/// static whose partner is static or kinematic, or a bullet. Read after a step, it names the
/// contacts that step's `SolveTOI` swept (but for those its sub-steps made or woke).
bool toi_swept(const b2Contact& contact);

/// The exact separation of triangles `a` and `b` (`sat` in double; metres) as an `ErrorTally`
/// reads it: minus the depth of a pair in contact, the distance of a pair apart by up to twice
/// `band` (the tally's touching band, metres), and for a pair apart farther a gap that proves it
/// (above twice `band`, at most the distance but for rounding: the tally counts the same from it).
double separation_as_tallied(const Triangle<double>& a, const Triangle<double>& b, double band);

class ContactProbe {
 public:
  /// Checks `backend`'s depths against the exact reference.
  explicit ContactProbe(box2d::Backend backend) : backend_(backend) {}

  /// What the next step's `Collide` will update.
  struct Updates {
    std::uint64_t contacts = 0;   ///< every contact
    std::uint64_t triangles = 0;  ///< triangle–triangle contacts
  };

  /// Counts the updates of the coming step and adds the triangle pairs' errors to `errors`.
  Updates before_step(const b2World& world, ErrorTally& errors);

  /// Adds the exact depth of every touching triangle pair to `depths`.
  static void measure_penetration(const b2World& world, PenetrationTally& depths);

 private:
  struct PairHash {
    std::size_t operator()(const std::pair<const b2Fixture*, const b2Fixture*>& p) const;
  };
  struct Cache {
    PairState cache;
    std::uint64_t seen = 0;           ///< the last pass that met the pair's contact
    std::array<b2Vec2, 3> a_at{};     ///< A's vertices `a` and `exact_a` were made from
    TriangleOrError<float> a;         ///< A's triangle as the plug-in's input
    TriangleOrError<double> exact_a;  ///< `a` widened, as the exact reference's input
  };

  box2d::Backend backend_;
  std::unordered_map<std::pair<const b2Fixture*, const b2Fixture*>, Cache, PairHash> caches_;
  std::uint64_t pass_ = 0;
};

}  // namespace dyop::scenes
