#pragma once
/// \file
/// The Box2D 2.4 plug-in: routes the contacts of triangle pairs through DyOP-PD (or any other
/// method of the library) inside an unchanged Box2D program.
///
///     #include <dyop/box2d.hpp>
///     dyop::box2d::install(dyop::box2d::Backend::Dyop);  // at any moment
///
/// Only polygon–polygon pairs are dispatched through Box2D's contact registry. Of those, a pair of
/// two triangles (3-vertex `b2PolygonShape`s) goes to the installed backend; every other polygon
/// pair goes to `b2CollidePolygons` unchanged; circles, edges and chains keep Box2D's own contacts.
///
/// Conventions (Box2D's manifold contract, kept exactly):
/// - The manifold is `e_faceA` or `e_faceB`: `localNormal` is the reference polygon's own
///   `m_normals[edge]` and `localPoint` the midpoint of that face, both in the reference body's
///   frame; at most two `points[i].localPoint`, on the incident polygon, in the incident body's
///   frame; `id.key` names the feature pair (A's feature, B's) and stays equal from step to step
///   while the same features touch, also when the reference face passes from one polygon to the
///   other (warm starting matches on it, and Box2D's ids survive such flips too). The key is the
///   library's encoding (`ManifoldPoint::key`): compare keys, do not read `id.cf`.
/// - Points are reported up to a separation of `m_radius` of A + `m_radius` of B (the skins, so
///   contacts are speculative and Box2D's TOI works), on side planes extended by the same amount,
///   and B's face is the reference only when it beats A's by more than `face_hysteresis`, as in
///   `b2CollidePolygons`.
/// - Geometry is computed in A's body frame (B's vertices moved by `b2MulT(xfA, xfB)`), so float
///   accuracy is relative to the shapes' size, not to their distance from the world origin.
///
/// Threads and lifetimes. Box2D 2.4 steps separate worlds on separate threads (one thread per
/// world at a time; a world may move between threads between steps, as in a pool of
/// environments), and so does the plug-in:
/// - Everything the plug-in knows about a world lives in that world's contacts, and is found from
///   the world's own fixtures and broad phase: no table outside them, so a world's answers depend
///   on nothing but that world — not on worlds stepped on other threads, nor on worlds deleted
///   before it (`delete world;` without destroying its bodies is fine, whatever addresses its
///   allocator hands to the next world). Nothing is kept for a dead world.
/// - `install` and `uninstall` change Box2D's contact registry, which is process-wide and
///   unguarded in Box2D itself: call them when no thread is stepping a world, creating or
///   destroying bodies or fixtures (Box2D reads the registry there). Every other function may run
///   on any thread at any time.
/// - `stats()` sums the counts of every thread (each thread counts into its own block, so the
///   counting never serialises threads); `reset_stats()` and `install` clear them all, and are
///   exact only while no thread is stepping.

#include <box2d/b2_collision.h>
#include <box2d/b2_common.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "dyop/method.hpp"
#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop::box2d {

/// The narrow phase a triangle pair goes to: one of the library's methods fit for simulation
/// (the registry's `MethodInfo::simulation()` rows: every method but `DyopPaper`, kept for
/// reproducing the paper, and `Batch`, many pairs per call), in the registry's order, then
/// `Box2D`: Box2D's own `b2CollidePolygons` through the same path, for comparison.
enum class Backend : std::uint8_t {
  Dyop,      ///< `dyop`: DyOP-PD, exact (`Method::Dyop`)
  DyopFast,  ///< `dyop-fast`: the pivot heuristic alone (`Method::DyopFast`)
  LinCanny,  ///< `lin-canny`: closest features, warm-started per contact (`Method::LinCanny`)
  Sat,       ///< `sat`: the exact reference (`Method::Sat`)
  Epa,       ///< `epa`: GJK + EPA (`Method::Epa`)
  Box2D,     ///< `box2d`: Box2D 2.4's `b2CollidePolygons`, the production reference
};

/// Number of backends: the size of arrays indexed by `static_cast<int>(Backend)`.
inline constexpr int backend_count = 6;

/// Every backend, in `Backend` order: dyop, dyop-fast, lin-canny, sat, epa, box2d.
inline constexpr std::array<Backend, backend_count> all_backends = {
    Backend::Dyop, Backend::DyopFast, Backend::LinCanny, Backend::Sat, Backend::Epa,
    Backend::Box2D};

namespace detail {

// The library's method of each backend, in `Backend` order; `Box2D` has none.
inline constexpr std::optional<Method> backend_methods[backend_count] = {
    Method::Dyop, Method::DyopFast, Method::LinCanny, Method::Sat, Method::Epa, std::nullopt};

// The backends are exactly the registry's simulation rows, in its order.
constexpr bool backends_are_the_simulation_rows() {
  int k = 0;
  for (const MethodInfo& row : method_table) {
    if (!row.simulation()) continue;
    if (k >= backend_count || backend_methods[k] != row.method) return false;
    ++k;
  }
  return k == backend_count - 1 && !backend_methods[k];
}
static_assert(backends_are_the_simulation_rows(),
              "Backend must list the registry's simulation rows in order, then Box2D");

}  // namespace detail

/// The library's method behind `backend`; nothing for `Backend::Box2D`, Box2D's own code.
constexpr std::optional<Method> method_of(Backend backend) {
  return detail::backend_methods[static_cast<int>(backend)];
}

/// The backend that runs method `m`; nothing when the plug-in does not offer it (`DyopPaper`,
/// `Batch`).
constexpr std::optional<Backend> backend_of(Method m) {
  for (Backend b : all_backends) {
    if (method_of(b) == m) return b;
  }
  return std::nullopt;
}

/// A backend's one spelling: its method's name (`dyop::name`), or "box2d".
constexpr const char* name(Backend backend) {
  const std::optional<Method> m = method_of(backend);
  return m ? dyop::name(*m) : "box2d";
}

/// True when the backend keeps warm-start state per contact (`MethodInfo::warm_start()`:
/// `LinCanny`).
constexpr bool warm_start(Backend backend) {
  const std::optional<Method> m = method_of(backend);
  return m && info(*m).warm_start();
}

/// The backend spelt `s` (its `name`), or nothing: the registry's parser (`parse_method`) over the
/// simulation rows, and "box2d".
std::optional<Backend> parse_backend(std::string_view s);

/// B's face becomes the reference only when its separation beats A's best by more than this
/// (metres). Why this value: it is `b2CollidePolygons`' own `k_tol`, so the reference face flips
/// exactly where Box2D's does instead of flip-flopping between frames on near ties.
inline constexpr float face_hysteresis = 0.1f * b2_linearSlop;

/// How an `install` or `uninstall` went.
enum class InstallStatus : std::uint8_t {
  Done,               ///< the requested backend (or Box2D's own contact) is now registered
  UnsupportedMethod,  ///< refused: not a backend (`install(Method)` of a method not offered)
};

/// The outcome of `install` / `uninstall`, returned by value.
struct InstallResult {
  InstallStatus status = InstallStatus::Done;  ///< always valid
  const char* message = "";  ///< static, human-readable: what happened, or why it was refused
  bool ok() const { return status == InstallStatus::Done; }  ///< true when `status == Done`
};

/// `Config::recycle_distance` by default (metres): 1 mm, a fifth of Box2D 2.4's `b2_linearSlop`.
/// At it the depth error in falling piles is no larger than Box2D's own contact's
/// (the trade, measured: docs/design.md, "A kept manifold is sound").
inline constexpr float default_recycle_distance = 0.001f;

/// What a world's narrow phase may skip: each switch avoids work whose result nobody uses, and
/// never changes the arithmetic of the work it keeps. With an exact backend (`Dyop`, `Sat`, and
/// `Epa`, `Box2D` likewise) every skip leaves the simulation bit-identical; with `LinCanny`, a
/// skipped step leaves the warm-start cache where it was, and with `DyopFast`, whose manifold can
/// lie about far pairs, an early-out can change the answer. All on by default.
///
/// Not switches, because they always pay: each contact validates its two triangles once, when it
/// first evaluates, and then places the shapes' own vertices and normals (`b2PolygonShape` holds
/// them) without validating again; pairs apart beyond the skins get no Euclidean distance
/// (`Apart::Gap`). Sensors need nothing here: Box2D 2.4 never asks a sensor's contact for a
/// manifold (`b2Contact::Update` calls `b2TestOverlap` and skips `Evaluate`).
struct Config {
  /// A pair whose bounding circles are farther apart than a manifold can reach (`reach`) gets
  /// the empty manifold before any axis work. Box2D's broad phase lets through pairs whose fat
  /// AABBs (grown by 0.1 m) overlap, many of them apart.
  bool bounds_early_out = true;
  /// The face the pair was judged on last step is tried first: when it still separates the pair
  /// by more than the skins and `face_hysteresis`, the manifold is empty and no other work is done
  /// (DyOP's pivot choice, warm-started).
  bool warm_axis = true;
  /// `LinCanny` starts from the features the pair ended on last step; off: every step cold.
  bool lin_canny_cache = true;


  /// Not a skip: it changes the answer (on by default). A triangle fixture's edge group is the
  /// triangle fixtures of its body and, for a static body, of every static body (dynamic and
  /// kinematic bodies keep their edges to themselves). An edge is internal when the group's edges
  /// collinear with it and running the other way cover it wholly: a neighbour's same edge, or a
  /// refined neighbour's edges meeting it at T-junctions (an edge covered in part stays an outline
  /// edge). Points of two frames are one point within 16·FLT_EPSILON of the coordinates'
  /// magnitude (2 µm per metre from the origin: the rounding of placing each body's frame);
  /// within one frame the same rule holds, bit-for-bit shared vertices being the usual case. The
  /// outline's flat and reflex vertices next to internal edges (a vertex inside another
  /// triangle's edge takes that edge as the outline through it, straight), and vertices whose two
  /// edges are both internal, are closed: no other triangle may push there
  /// (`triangle_internal_edges` in `dyop/box2d_internal_edges.hpp` gives a fixture's masks). The
  /// exact backends (`Dyop`, `Sat`) never push along them (`Query::internal_edges`), so bodies
  /// slide over triangulated grounds, tile maps and chunked terrain without ghost collisions.
  /// Polygons of more than three vertices, circles, edges and chains keep Box2D's own handling and
  /// make no edge internal. A contact finds its two triangles' masks when the rule first needs
  /// them (its pair is not skipped), from the fixtures as they are then (the group's triangles
  /// near each one, from the world's broad phase), and keeps them in its `ContactMemory`; it finds
  /// them again after the frames of its static bodies changed, after fixtures near it changed (a
  /// contact made or ended), and after fixtures elsewhere in its world changed once it has moved
  /// 0.05 m toward them, and tells its moving body's other contacts with
  /// static bodies to do the same (`forget_internal_edges` in `dyop/box2d_internal_edges.hpp`
  /// for what it cannot see). The other backends ignore it and never look. Off: the world is
  /// bit-identical to Box2D's own handling of each fixture alone, as the plug-in was without the
  /// rule.
  bool internal_edges = true;

  /// Not a skip either: it may change the answer, within a bound (on by default:
  /// `default_recycle_distance`). Metres; 0: off, and the world is bit-identical to the plug-in
  /// without it. A world's contact keeps the manifold it computed
  /// (Box2D hands it back at every update) while the relative pose of its two triangles has moved
  /// less than this (a fifth of it for a pair with a static body: a body sinking deeper into
  /// static ground meets Box2D's time-of-impact pass) since it was computed: B's centroid against
  /// A plus the relative turn times a lever of the pair's extent
  /// (`|Δc| + |sin Δθ|·1.01·(3·radius_sum + reach)`), and never across a turn of more than about
  /// 11.5° (cosine 0.98). Sound in Box2D 2.4: manifolds are in body
  /// frames and the solver recomputes every separation from the current transforms, and the
  /// impulses carry over by `id.key`; what a kept manifold misses is a change of features (a
  /// vertex coming within the skins, a point sliding off a face), by at most about this distance.
  /// An empty manifold is kept only while the pose moved less than its judged face separates the
  /// pair beyond the skins' reach, so no new contact is missed; a fast body recomputes every step
  /// (it moves farther than the tolerance); another install (backend or config) and a change of
  /// the pair's internal-edge masks recompute; a fixture created or destroyed elsewhere in the
  /// world does not; a skipped evaluation is never kept. The library's
  /// methods only: `Backend::Box2D` answers afresh every time, bit-identical to Box2D's own
  /// contact. Counted in `Stats::recycled`. `collide_polygons` never keeps a manifold (it has no contact to keep it
  /// in).
  float recycle_distance = default_recycle_distance;

  /// Every skip on (the default), internal edges as by default.
  static Config all() { return {}; }
  /// Every skip off: the work of every evaluation done in full (internal edges and recycling, which
  /// change the answer, as by default: with an exact backend the world is the same as with every
  /// skip on).
  static Config none() {
    Config c;
    c.bounds_early_out = false;
    c.warm_axis = false;
    c.lin_canny_cache = false;
    return c;
  }
};

/// True when `x` and `y` switch the same skips, internal-edge rule and recycling.
inline bool operator==(const Config& x, const Config& y) {
  return x.bounds_early_out == y.bounds_early_out && x.warm_axis == y.warm_axis &&
         x.lin_canny_cache == y.lin_canny_cache && x.internal_edges == y.internal_edges &&
         x.recycle_distance == y.recycle_distance;
}

/// Beyond this distance no manifold point can exist (metres), for skins summing to `margin`:
/// points are kept up to `margin` in front of the reference face and `margin` beyond its ends,
/// and no deeper behind it than the face-choice `face_hysteresis`, so every kept point is within
/// sqrt(2)·margin + face_hysteresis of the other triangle; 2·margin + face_hysteresis is a bound.
inline float reach(float margin) { return 2 * margin + face_hysteresis; }

/// Why a triangle pair's evaluation was skipped (index of `Stats::skipped`).
enum class Skip : std::uint8_t {
  Bounds,    ///< bounding circles apart beyond `reach` (`Config::bounds_early_out`)
  WarmAxis,  ///< last step's face still separates beyond the skins (`Config::warm_axis`)
};

/// Number of skip reasons: the size of `Stats::skipped`.
inline constexpr int skip_count = 2;

/// "bounds", "warm-axis".
const char* name(Skip s);

/// What the plug-in remembers about one polygon pair between evaluations: 16 bytes, held inside
/// each of its contacts (no heap: `b2World`'s destructor frees contacts without destroying them).
/// A caller of `collide_polygons` that replays one pair's evaluations keeps one for it.
/// Default-constructed: nothing known yet (the first evaluation looks at the shapes).
struct ContactMemory {
  /// What the two shapes were found to be on the first evaluation (two triangles are validated
  /// on the first evaluation that runs the backend).
  enum class Shapes : std::uint8_t {
    Unchecked,         ///< not evaluated yet
    Triangles,         ///< two triangles accepted by `Triangle<float>::make`: the backend answers
    InvalidTriangles,  ///< two triangles, one rejected by `Triangle<float>::make`: Box2D answers
    /// Two triangles not validated yet: the skips answer them (they need only the shapes'
    /// centroids, radii and normals); the first evaluation that runs the backend validates them
    /// (then `Triangles` or `InvalidTriangles`). Most contacts of a rain never get that far.
    UnvalidatedTriangles,
    Polygons,          ///< a side with more than 3 vertices: `b2CollidePolygons` answers
  };
  /// The backend's warm-start state (`LinCanny`'s last features; `Config::lin_canny_cache`).
  PairState warm_start;
  /// The face the last evaluation judged the pair on: 0..2 A's edges, 3..5 B's, -1 none yet
  /// (`Config::warm_axis`).
  std::int8_t last_face = -1;
  Shapes shapes = Shapes::Unchecked;  ///< set by the first evaluation
  /// Triangles (validated or not): the sum, over the two shapes, of the distance from the
  /// shape's centroid (`m_centroid`) to its farthest vertex, metres, body frame
  /// (`Config::bounds_early_out`).
  float radius_sum = 0;
  /// The pair's internal-edge masks (`Query::internal_edges`, Box2D's vertex order: A's bits,
  /// then B's), used while the installed backend applies the rule (`Config::internal_edges`). A
  /// world's contact reads them from fixed edge data or finds them itself; a caller of
  /// `collide_polygons` sets them.
  InternalEdges internal_edges{};
};

/// Registers the plug-in's contact for polygon–polygon pairs, with `backend` (and `config`'s
/// skips) for triangle pairs, and resets `stats`. Never refused for a backend, and safe at any
/// moment no thread is stepping a world (see "Threads and lifetimes" above): before the first
/// step, between the steps of running worlds, with several worlds alive, after a world was
/// deleted. What holds:
/// - Box2D makes each contact with whatever is registered at that moment, and every contact is
///   freed as what it is: the plug-in's destroy function, registered from the first install on
///   (`uninstall` keeps it), frees its own contacts in their class of Box2D's block allocator and
///   hands Box2D's own to Box2D's own destroy function.
/// - Every contact the plug-in made follows the installed backend and skips from the next step
///   on; after `uninstall` it answers with `b2CollidePolygons`, exactly as Box2D's own contact.
/// - Contacts Box2D's own code made before the install keep Box2D's answer until they end (when
///   the two fixtures' fat AABBs stop overlapping): Box2D offers no way to replace a live contact.
/// Installing the installed backend with the same skips does nothing and succeeds. A value
/// outside `Backend` is refused (`UnsupportedMethod`) and changes nothing.
InstallResult install(Backend backend, const Config& config = Config::all());

/// `install(backend_of(method), config)`; refused (`UnsupportedMethod`) for a method the plug-in
/// does not offer (`DyopPaper`, `Batch`).
InstallResult install(Method method, const Config& config = Config::all());

/// Registers again what made polygon pairs' contacts before the plug-in was installed (Box2D's
/// own `b2PolygonContact`): contacts made from now on are Box2D's own, so a world made after it is
/// bit-identical to one that never saw the plug-in. The plug-in's destroy function stays
/// registered: the plug-in's contacts still alive are larger than Box2D's own (another class of
/// Box2D's block allocator), and it frees Box2D's own through Box2D's own function. Never refused,
/// safe at any moment `install` is; does nothing when not installed.
InstallResult uninstall();

/// The installed backend, or nothing when Box2D's own contact is registered.
std::optional<Backend> installed();

/// The skips of the installed backend (the last `install`'s).
Config installed_config();

/// The plug-in's answer for one polygon pair, exactly what its contact's `Evaluate` computes
/// with `config`: triangle pairs through `backend`, other polygon pairs through
/// `b2CollidePolygons`. `memory` is the pair's state from its previous evaluation (updated);
/// nullptr: nothing remembered, a cold evaluation. Counted in `stats`.
void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape& shape_a,
                      const b2Transform& xf_a, const b2PolygonShape& shape_b,
                      const b2Transform& xf_b, ContactMemory* memory = nullptr,
                      const Config& config = Config::all());

/// Counters since the last `install` or `reset_stats`, summed over every thread that evaluated
/// pairs (with one world, or worlds stepped one after another, the counts of those worlds).
struct Stats {
  /// Triangle pairs evaluated, per backend (index: `static_cast<int>(Backend)`).
  std::array<std::uint64_t, backend_count> triangle_pairs{};
  /// Other polygon pairs (a side with more than 3 vertices), passed to `b2CollidePolygons`.
  std::uint64_t polygon_pairs = 0;
  /// Triangle-pair evaluations that produced a non-empty manifold.
  std::uint64_t manifolds = 0;
  /// Triangle pairs the backend could not answer (`Status::Invalid`, or a triangle rejected by
  /// `Triangle<float>::make`), answered by `b2CollidePolygons` instead so that the simulation goes
  /// on. Nonzero means the backend's figures include Box2D's answers.
  std::uint64_t fallbacks = 0;
  /// Triangle-pair evaluations answered without running the backend, per reason (index:
  /// `static_cast<int>(Skip)`); they are included in `triangle_pairs`.
  std::array<std::uint64_t, skip_count> skipped{};
  /// Triangle-pair evaluations run by an exact backend with internal edges or closed vertices in
  /// force (`Config::internal_edges`): the pairs whose contact the rule may change.
  std::uint64_t internal_edge_pairs = 0;
  /// Triangle-pair evaluations that kept the contact's manifold (`Config::recycle_distance`);
  /// included in `triangle_pairs`.
  std::uint64_t recycled = 0;
  /// Triangle pairs evaluated by `b`.
  std::uint64_t triangles(Backend b) const { return triangle_pairs[static_cast<int>(b)]; }
  /// Evaluations skipped for reason `s`.
  std::uint64_t skips(Skip s) const { return skipped[static_cast<int>(s)]; }
};

/// The counters since the last `install` or `reset_stats`, every thread's summed (threads that
/// have ended included). Safe on any thread at any time; while other threads step, a snapshot.
Stats stats();

/// Sets every thread's counters to zero (exact while no thread is evaluating: an evaluation under
/// way on another thread may keep its count).
void reset_stats();

/// Why three points cannot make a `b2PolygonShape` triangle.
enum class ShapeError : std::uint8_t {
  None,              ///< a valid triangle
  Triangle,          ///< rejected by `Triangle<float>::make`: see `TriangleShape::triangle_error`
  VerticesTooClose,  ///< two vertices closer than 0.5·b2_linearSlop: Box2D would weld them
  AreaTooSmall,      ///< area below `min_triangle_area`: Box2D's centroid would assert
  TooLarge,          ///< a coordinate beyond `max_triangle_coordinate`: Box2D's inertia overflows
};

/// A static, human-readable description of `e`, naming the problem.
const char* describe(ShapeError e);

/// Smallest area `make_triangle` accepts (m²). Why: `b2PolygonShape::Set` asserts
/// `area > b2_epsilon` (FLT_EPSILON m²) in its centroid; Box2D computes that area in float from
/// reordered vertices, so twice the threshold keeps us clear of its rounding, and a triangle that
/// small (1 cm long, 48 µm high) has mass and inertia without useful digits anyway.
inline constexpr float min_triangle_area = 2 * b2_epsilon;

/// Largest body-frame coordinate magnitude `make_triangle` accepts (m). Why: Box2D computes a
/// polygon's inertia in float as density × size⁴ (plus mass × distance² to the body origin);
/// FLT_MAX is 3.4e38, so up to 1e9 m it stays finite for densities up to 100 kg/m², and beyond
/// ~5e9 m it is infinite even at density 1.
inline constexpr float max_triangle_coordinate = 1e9f;

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

}  // namespace dyop::box2d
