#pragma once
/// \file
/// The Box2D 2.4 plug-in: routes the contacts of triangle pairs through DyOP-PD (or any other
/// method of the library) inside an unchanged Box2D program.
///
///     #include <dyop/box2d.hpp>
///     dyop::box2d::install(dyop::box2d::Backend::Dyop);  // before the first step
///
/// Only polygon–polygon pairs are dispatched through Box2D's contact registry. Of those, a pair of
/// two triangles (3-vertex `b2PolygonShape`s) goes to the installed backend; every other polygon
/// pair goes to `b2CollidePolygons` unchanged; circles, edges and chains keep Box2D's own contacts.
///
/// Conventions (Box2D's manifold contract, kept exactly):
/// - The manifold is `e_faceA` or `e_faceB`: `localNormal` is the reference polygon's own
///   `m_normals[edge]` and `localPoint` the midpoint of that face, both in the reference body's
///   frame; at most two `points[i].localPoint`, on the incident polygon, in the incident body's
///   frame; `id.key` names the feature pair and stays equal from step to step while the same
///   features touch (warm starting matches on it). The key is the library's encoding
///   (`ManifoldPoint::key`), not `b2ContactFeature`'s: compare keys, do not read `id.cf`.
/// - Points are reported up to a separation of `m_radius` of A + `m_radius` of B (the skins, so
///   contacts are speculative and Box2D's TOI works), on side planes extended by the same amount,
///   and B's face is the reference only when it beats A's by more than `face_hysteresis`, as in
///   `b2CollidePolygons`.
/// - Geometry is computed in A's body frame (B's vertices moved by `b2MulT(xfA, xfB)`), so float
///   accuracy is relative to the shapes' size, not to their distance from the world origin.
///
/// Not thread-safe: Box2D's registry is process-wide, and so are `install`, the live-contact count
/// and `stats`. Use one thread for Box2D, as Box2D 2.4 itself requires.

#include <box2d/b2_collision.h>
#include <box2d/b2_common.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <array>
#include <cstdint>
#include <optional>

#include "dyop/lin_canny.hpp"
#include "dyop/method.hpp"
#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop::box2d {

/// The narrow phase a triangle pair goes to. Every exact or approximate method of the library
/// except `DyopPaper` (kept for reproducing the paper, not for simulation), and Box2D's own
/// `b2CollidePolygons` through the same path, for comparison.
enum class Backend : std::uint8_t {
  Dyop,      ///< `dyop`: DyOP-PD with certification, exact
  DyopFast,  ///< `dyop-fast`: the pivot heuristic alone, approximate (can miss penetrations)
  LinCanny,  ///< `lin-canny`: closest-feature tracking, warm-started by a cache in each contact
  Sat,       ///< `sat`: the exact reference
  Epa,       ///< `epa`: GJK + EPA
  Box2D,     ///< `box2d`: `b2CollidePolygons`, Box2D's own answer through the plug-in
};

/// Number of backends: the size of `Stats::triangle_pairs`.
inline constexpr int backend_count = 6;

/// Every backend, in declaration order.
inline constexpr Backend all_backends[backend_count] = {Backend::Dyop,     Backend::DyopFast,
                                                        Backend::LinCanny, Backend::Sat,
                                                        Backend::Epa,      Backend::Box2D};

/// The command-line spelling: "dyop", "dyop-fast", "lin-canny", "sat", "epa", "box2d".
const char* name(Backend b);

/// B's face becomes the reference only when its separation beats A's best by more than this
/// (metres). Why this value: it is `b2CollidePolygons`' own `k_tol`, so the reference face flips
/// exactly where Box2D's does instead of flip-flopping between frames on near ties.
inline constexpr float face_hysteresis = 0.1f * b2_linearSlop;

/// How an `install` or `uninstall` went.
enum class InstallStatus : std::uint8_t {
  Done,               ///< the requested backend (or Box2D's own contact) is now registered
  ContactsExist,      ///< refused: polygon contacts made by the plug-in still exist
  UnsupportedMethod,  ///< refused: the method is not offered to Box2D (`DyopPaper`)
};

/// The outcome of `install` / `uninstall`, returned by value.
struct InstallResult {
  InstallStatus status = InstallStatus::Done;  ///< always valid
  const char* message = "";  ///< static, human-readable: what happened, or why it was refused
  bool ok() const { return status == InstallStatus::Done; }  ///< true when `status == Done`
};

/// What a world's narrow phase may skip: each switch avoids work whose result nobody uses, and
/// never changes the arithmetic of the work it keeps. With an exact backend (`Dyop`, `Sat`, and
/// `Epa`, `Box2D` likewise) every skip leaves the simulation bit-identical; with `LinCanny`, a
/// skipped step leaves the warm-start cache where it was, and with `DyopFast`, whose manifold can
/// lie about far pairs, an early-out can change the answer. All on by default.
///
/// Sensors need nothing here: Box2D 2.4 never asks a contact of a sensor for a manifold
/// (`b2Contact::Update` calls `b2TestOverlap`, an overlap test only, and skips `Evaluate`).
struct Config {
  /// A pair whose bounding circles are farther apart than a manifold can reach (`reach`) gets
  /// the empty manifold before any axis work. Box2D's broad phase lets through pairs whose fat
  /// AABBs (grown by 0.1 m) overlap, many of them apart.
  bool bounds_early_out = true;
  /// Each triangle is validated and its normals computed once, in its body frame, when the
  /// contact is made, and only moved (rotated) into A's frame each step; off: redone every step.
  bool shape_cache = true;
  /// The face the pair was judged on last step is tried first: when it still separates the pair
  /// beyond `reach`, no other work is done (DyOP's pivot choice, warm-started).
  bool warm_axis = true;
  /// `LinCanny` starts from the features the pair ended on last step; off: every step cold.
  bool lin_canny_cache = true;
  /// A pair whose two bodies have not moved since its last evaluation (bit-identical transforms)
  /// keeps its manifold.
  bool reuse_unmoved = true;

  /// Every skip on (the default).
  static Config all() { return {}; }
  /// Every skip off: the work of every step done in full.
  static Config none() { return {false, false, false, false, false}; }
};

/// Beyond this distance no manifold point can exist (metres), for skins summing to `margin`:
/// points are kept up to `margin` in front of the reference face and `margin` beyond its ends,
/// and no deeper behind it than the face-choice `face_hysteresis`, so every kept point is within
/// sqrt(2)·margin + face_hysteresis of the other triangle; 2·margin + face_hysteresis is a bound.
inline float reach(float margin) { return 2 * margin + face_hysteresis; }

/// Why a triangle pair's evaluation was skipped (index of `Stats::skipped`).
enum class Skip : std::uint8_t {
  Bounds,    ///< bounding circles apart beyond `reach` (`Config::bounds_early_out`)
  WarmAxis,  ///< last step's face still separates beyond `reach` (`Config::warm_axis`)
  Unmoved,   ///< neither body moved since the last evaluation (`Config::reuse_unmoved`)
};

/// Number of skip reasons: the size of `Stats::skipped`.
inline constexpr int skip_count = 3;

/// "bounds", "warm-axis", "unmoved".
const char* name(Skip s);

/// Registers the plug-in's contact for polygon–polygon pairs, with `backend` for triangle pairs,
/// and resets `stats`. Installing the backend already installed does nothing and succeeds.
/// Refused (`ContactsExist`) while contacts made by the plug-in exist: Box2D frees a contact with
/// the size registered at the time it is destroyed, so the registration must not change under a
/// live contact. Call it before Box2D's own code has made any polygon contact (typically before
/// the first `b2World::Step`): contacts made by Box2D's own `b2PolygonContact` are not counted.
InstallResult install(Backend backend, const Config& config = Config::all());

/// `install` by library method: `Dyop`, `DyopFast`, `LinCanny`, `Sat`, `Epa`; `DyopPaper` is
/// refused (`UnsupportedMethod`).
InstallResult install(Method method, const Config& config = Config::all());

/// Restores what was registered for polygon pairs before the first `install` (Box2D's own
/// `b2PolygonContact`). Does nothing when not installed. Refused (`ContactsExist`) while
/// contacts made by the plug-in exist.
InstallResult uninstall();

/// The installed backend, or nothing when Box2D's own contact is registered.
std::optional<Backend> installed();

/// The skips of contacts made from now on (the last `install`'s).
Config installed_config();

/// Contacts made by the plug-in that Box2D has not destroyed yet. Note: `b2World`'s destructor
/// frees its contacts without destroying them, so they stay counted; to switch or uninstall after
/// deleting a world, destroy its bodies first (`b2World::DestroyBody` destroys their contacts).
int live_contacts();

/// The plug-in's answer for one polygon pair, exactly what its contact's `Evaluate` computes:
/// triangle pairs through `backend`, other polygon pairs through `b2CollidePolygons`. `cache` is
/// used by `LinCanny` only (nullptr: cold start). Counted in `stats`.
void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape* shape_a,
                      const b2Transform& xf_a, const b2PolygonShape* shape_b,
                      const b2Transform& xf_b, LinCannyCache* cache = nullptr);

/// Counters since the last `install` or `reset_stats`.
struct Stats {
  /// Triangle pairs evaluated, per backend (index: `static_cast<int>(Backend)`).
  std::array<std::uint64_t, backend_count> triangle_pairs{};
  /// Other polygon pairs (a side with more than 3 vertices), passed to `b2CollidePolygons`.
  std::uint64_t polygon_pairs = 0;
  /// Triangle-pair evaluations that produced a non-empty manifold.
  std::uint64_t manifolds = 0;
  /// Triangle pairs the backend could not answer (`Status::Invalid`, or a triangle too thin for
  /// `Triangle::make` once moved into A's frame), answered by `b2CollidePolygons` instead so that
  /// the simulation goes on. Nonzero means the backend's figures include Box2D's answers.
  std::uint64_t fallbacks = 0;
  /// Triangle-pair evaluations answered without running the backend, per reason (index:
  /// `static_cast<int>(Skip)`); they are included in `triangle_pairs`.
  std::array<std::uint64_t, skip_count> skipped{};
  /// Triangle pairs evaluated by `b`.
  std::uint64_t triangles(Backend b) const { return triangle_pairs[static_cast<int>(b)]; }
  /// Evaluations skipped for reason `s`.
  std::uint64_t skips(Skip s) const { return skipped[static_cast<int>(s)]; }
};

/// The counters since the last `install` or `reset_stats`.
Stats stats();

/// Sets every counter to zero.
void reset_stats();

/// Why three points cannot make a `b2PolygonShape` triangle.
enum class ShapeError : std::uint8_t {
  None,              ///< a valid triangle
  Triangle,          ///< rejected by `Triangle<float>::make`: see `TriangleShape::triangle_error`
  VerticesTooClose,  ///< two vertices closer than 0.5·b2_linearSlop: Box2D would weld them
  AreaTooSmall,      ///< area below `min_triangle_area`: Box2D's centroid would assert
};

/// A static, human-readable description of `e`, naming the problem.
const char* describe(ShapeError e);

/// Smallest area `make_triangle` accepts (m²). Why: `b2PolygonShape::Set` asserts
/// `area > b2_epsilon` (FLT_EPSILON m²) in its centroid; Box2D computes that area in float from
/// reordered vertices, so twice the threshold keeps us clear of its rounding, and a triangle that
/// small (1 cm long, 48 µm high) has mass and inertia without useful digits anyway.
inline constexpr float min_triangle_area = 2 * b2_epsilon;

/// The outcome of `make_triangle`: `shape` is meaningful only when `error == None`.
struct TriangleShape {
  ShapeError error = ShapeError::None;  ///< None when `shape` is a valid triangle
  /// `error == Triangle`: what `Triangle<float>::make` found (non-finite, too large, repeated
  /// vertex, degenerate); `None` otherwise.
  TriangleError triangle_error = TriangleError::None;
  /// Static, human-readable: `describe(triangle_error)` when `error == Triangle`, else
  /// `describe(error)`.
  const char* message = "";
  b2PolygonShape shape;  ///< valid only when `ok()`: 3 CCW vertices (Box2D's order), skin radius
  bool ok() const { return error == ShapeError::None; }  ///< true when `error == None`
};

/// A `b2PolygonShape` triangle from three body-frame points (any winding), or the reason it cannot
/// be one, checked before Box2D 2.4 can assert (thin triangles abort in its centroid) or silently
/// turn a bad hull into a 1×1 box. Box2D stores the vertices CCW starting from the rightmost one.
TriangleShape make_triangle(const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2);

/// Box2D's own answer for two triangles, under the library's conventions (`dyop/result.hpp`),
/// in float: `dyop pairs --method box2d`. Each triangle becomes a `b2PolygonShape` about its own
/// centroid, placed by a translation (a body whose origin is its centre of mass), with skin radius
/// 0 (`m_radius = 0`: pure geometry, no speculative margin). Then `b2CollidePolygons`:
/// - points: Penetrating or Touching; `separation` is the deepest point's, `normal` the manifold's
///   world normal (A to B), witnesses the deepest point and its projection on the reference face;
/// - no points: the distance from `b2Distance` (Box2D's GJK), its closest points and iterations;
///   Separated beyond `touching_tolerance`, else Touching (with a zero normal at distance 0).
/// Valid fields: those of `Level::Contact` except the features; `manifold` is left empty.
/// Invalid (with a reason) only if Box2D's float arithmetic gives a non-finite value.
Result<float> collide_triangles(const Triangle<float>& a, const Triangle<float>& b);

}  // namespace dyop::box2d
