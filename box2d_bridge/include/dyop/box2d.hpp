#pragma once
/// \file
/// The Box2D 2.4 plug-in: routes the contacts of triangle pairs through DyOP-PD (or any other
/// method of the library), and those of every other polygon pair, polygon–circle pair and edge or
/// chain pair through the exact solver, inside an unchanged Box2D program.
///
///     #include <dyop/box2d.hpp>
///     dyop::box2d::install(dyop::box2d::Backend::Dyop);  // at any moment
///
/// The plug-in registers its contact in Box2D's contact registry for polygon–polygon,
/// polygon–circle, edge–polygon, edge–circle, chain–polygon and chain–circle pairs. A pair of two
/// triangles (3-vertex `b2PolygonShape`s) goes to the installed backend; every other pair to
/// `dyop::collide` (`dyop/convex_pair.hpp`), with the internal-edge rule, under every backend but
/// `Box2D` (Box2D's own functions). `Config::edges_and_chains` off leaves edges and chains to
/// Box2D, `Config::triangles_only` everything but triangle pairs. Circle–circle pairs keep Box2D's
/// own contact.
///
/// Edges and chains (A, as Box2D orders them; a chain pair is one of its child edges): a one-sided
/// edge (`SetOneSided`, every chain's edge) keeps Box2D's one-sided meaning (a body whose centroid,
/// a circle's centre, lies behind it gets no contact) and takes the rule from its ghost vertices:
/// no push along its back, and none from an end where the chain goes on flat or turns concave
/// (beyond the rule's flat-face tolerance, 1e-3 rad). A two-sided edge (`SetTwoSided`) that meets
/// other edges or polygons end to end takes the same rule from its neighbours on the side its
/// contact's body was on when the contact began (its centroid against the edge's line, ties to the
/// normal's side), so that bodies glide on either side; alone, it answers both sides, as Box2D's.
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
/// Threads and lifetimes: separate worlds may step on separate threads; everything the plug-in
/// knows about a world lives in that world's contacts. `install` and `uninstall` change Box2D's
/// process-wide registry: call them while no thread steps a world or creates or destroys
/// fixtures; every other function may run on any thread at any time (docs/box2d-plugin.md).

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_common.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "dyop/convex_pair.hpp"
#include "dyop/method.hpp"
#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop::box2d {

/// The narrow phase a triangle pair goes to (other pairs: the exact solver, or Box2D's own
/// functions for `Box2D`): one of the library's methods fit for simulation
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
    Backend::Dyop, Backend::DyopFast, Backend::LinCanny,
    Backend::Sat,  Backend::Epa,      Backend::Box2D};

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

/// `Config::recycle_distance` by default (metres): 1 mm, a fifth of Box2D 2.4's `b2_linearSlop`,
/// where the depth error in falling piles is Box2D's own contact's (docs/measurements.md).
inline constexpr float default_recycle_distance = 0.001f;

/// What `install` sets up for every pair the plug-in answers (polygons, circles, edges, chains):
/// the skips (work whose result nobody uses; with an exact backend the world is bit-identical with
/// them on or off), the internal-edge rule, manifold recycling and which pairs the exact solver
/// answers. Presets: `all()` (the default), `no_skips()`, `off()`. Each field's rationale:
/// docs/box2d-plugin.md, "`Config`".
struct Config {
  /// Skip: a pair whose bounding circles are farther apart than `reach` gets the empty manifold
  /// before any axis work. On by default.
  bool bounds_early_out = true;
  /// Skip: when the face the pair was judged on last step still separates it beyond the skins and
  /// `face_hysteresis`, the manifold is empty. On by default.
  bool warm_axis = true;
  /// `LinCanny` starts from the features the pair ended on last step; off: every step cold.
  /// On by default.
  bool lin_canny_cache = true;

  /// The internal-edge rule: the exact answers (triangle pairs under `Dyop` and `Sat`, every other
  /// pair under every backend but `Box2D`) never push along edges shared inside a body or a
  /// static ground, nor into their closed vertices, so bodies slide without ghost collisions.
  /// Changes the answer; on by default; off: Box2D's fixture-by-fixture handling
  /// (docs/box2d-plugin.md).
  bool internal_edges = true;

  /// Manifold recycling (metres): a contact keeps its manifold while its pair's relative pose moved
  /// less than this (a fifth of it with a static body). Default `default_recycle_distance` (1 mm);
  /// 0: off, bit-identical to the plug-in without it (docs/box2d-plugin.md).
  float recycle_distance = default_recycle_distance;

  /// Only triangle pairs go to the backend, as in version 0.1: other polygon pairs to
  /// `b2CollidePolygons`, polygon–circle, edge and chain pairs keep Box2D's own contacts. Off by
  /// default: every other polygon pair, polygon–circle pair and (with `edges_and_chains`) edge and
  /// chain pair is answered exactly (`dyop::collide`), with the internal-edge rule.
  bool triangles_only = false;

  /// Edge and chain pairs (`b2EdgeShape`, `b2ChainShape` against polygons and circles) are
  /// answered exactly with the internal-edge rule (see the file's head). Off: Box2D's own contacts
  /// for them. On by default.
  bool edges_and_chains = true;

  /// The default: every skip on, the internal-edge rule on, recycling at
  /// `default_recycle_distance`, every pair family answered exactly.
  static Config all() { return {}; }
  /// Every skip off (`bounds_early_out`, `warm_axis`, `lin_canny_cache`); the internal-edge rule,
  /// recycling and the routing as by default. With an exact backend the world is bit-identical to
  /// `all()`'s: for measuring what the skips save.
  static Config no_skips() {
    Config c;
    c.bounds_early_out = false;
    c.warm_axis = false;
    c.lin_canny_cache = false;
    return c;
  }
  /// Everything off: every skip, the internal-edge rule and recycling (`recycle_distance` 0); the
  /// routing as by default (`triangles_only` off, `edges_and_chains` on). Each pair then gets its
  /// plain answer every step, fixture by fixture as Box2D collides them.
  static Config off() {
    Config c = no_skips();
    c.internal_edges = false;
    c.recycle_distance = 0;
    return c;
  }
  /// `no_skips()`, by its old name: it never turned the rule or recycling off (`off()` does).
  [[deprecated("use Config::no_skips()")]] static Config none() { return no_skips(); }
};

/// True when `x` and `y` switch the same skips, internal-edge rule and recycling.
inline bool operator==(const Config& x, const Config& y) {
  return x.bounds_early_out == y.bounds_early_out && x.warm_axis == y.warm_axis &&
         x.lin_canny_cache == y.lin_canny_cache && x.internal_edges == y.internal_edges &&
         x.recycle_distance == y.recycle_distance && x.triangles_only == y.triangles_only &&
         x.edges_and_chains == y.edges_and_chains;
}

/// Beyond this distance no manifold point can exist (metres), for skins summing to `margin`:
/// points are kept up to `margin` in front of the reference face and `margin` beyond its ends,
/// and no deeper behind it than the face-choice `face_hysteresis`, so every kept point is within
/// sqrt(2)·margin + face_hysteresis of the other shape; 2·margin + face_hysteresis is a bound.
inline float reach(float margin) { return 2 * margin + face_hysteresis; }

/// Why an evaluation was skipped: its manifold proved empty without running the solver (index of
/// `Stats::skipped`, which counts the triangle pairs' skips).
enum class Skip : std::uint8_t {
  Bounds,    ///< bounding circles apart beyond `reach` (`Config::bounds_early_out`)
  WarmAxis,  ///< last step's face still separates beyond the skins (`Config::warm_axis`)
};

/// Number of skip reasons: the size of `Stats::skipped`.
inline constexpr int skip_count = 2;

/// "bounds", "warm-axis".
const char* name(Skip s);

/// What a two-sided edge's ends meet, seen from either side (`edge_ends`,
/// dyop/box2d_internal_edges.hpp): the outline of its group through each end (end 0 `m_vertex1`, 1
/// `m_vertex2`; side 0 the front, right of `m_vertex1` → `m_vertex2`, 1 the back).
/// Value-initialised (`{}`): an edge that meets nothing.
struct EdgeEnds {
  std::uint8_t closed_front;  ///< bit k: from the front, the outline at end k is flat or reflex
  std::uint8_t closed_back;   ///< bit k: the same from the back
  /// [end][side], at an end that meets the outline: where the free space beside the edge is a
  /// corner narrower than a half-turn, the cosine of its angle in 127ths, rounded down (the corner
  /// a little wider); −127 elsewhere. A body whose centroid lies beyond that corner's other edge
  /// faces that other edge, not this one.
  std::int8_t corner_cos[2][2];
  /// Bit k: end k meets the outline (then it is closed from one side at least).
  std::uint8_t neighbours() const { return static_cast<std::uint8_t>(closed_front | closed_back); }
};

/// What the plug-in remembers about one polygon pair between evaluations (16 bytes, inside each of
/// its contacts, no heap). A caller of `collide_polygons` keeps one per pair; default: nothing
/// known yet.
struct ContactMemory {
  /// What the two shapes were found to be (triangles are validated by the first evaluation that
  /// runs the backend).
  enum class Shapes : std::uint8_t {
    Unchecked,         ///< not evaluated yet
    Triangles,         ///< two triangles accepted by `Triangle<float>::make`: the backend answers
    InvalidTriangles,  ///< two triangles, one rejected by `Triangle<float>::make`: Box2D answers
    /// Two triangles not validated yet: only skips have answered them so far (then `Triangles` or
    /// `InvalidTriangles` once the backend runs).
    UnvalidatedTriangles,
    /// A side with more than 3 vertices, both accepted by `Polygon<float>::check`: the exact
    /// solver answers (`dyop::collide`; `b2CollidePolygons` under `Backend::Box2D` or
    /// `Config::triangles_only`).
    Polygons,
    InvalidPolygons,   ///< a side with more than 3 vertices that `Polygon<float>` refuses: Box2D
    PolygonAndCircle,  ///< a polygon (A) and a circle (B): `dyop::collide`, or Box2D's own
    InvalidPolygonAndCircle,  ///< a polygon and a circle, one refused (`ConvexError`): Box2D
    /// An edge or a chain's edge (A) and a polygon on its front: the side a two-sided edge's pair
    /// keeps (decided by the first look), a one-sided edge's only side. `dyop::collide`, or
    /// Box2D's.
    EdgeAndPolygon,
    EdgeBackAndPolygon,     ///< a two-sided edge and a polygon on its back (see `EdgeAndPolygon`)
    InvalidEdgeAndPolygon,  ///< an edge and a polygon, one refused (`ConvexError`): Box2D
    EdgeAndCircle,          ///< an edge and a circle on its front (see `EdgeAndPolygon`)
    EdgeBackAndCircle,      ///< a two-sided edge and a circle on its back
    InvalidEdgeAndCircle,   ///< an edge and a circle, one refused (`ConvexError`): Box2D
  };
  union {
    /// Triangle pairs: the backend's warm-start state (`LinCanny`'s last features;
    /// `Config::lin_canny_cache`).
    PairState warm_start{};
    /// Two-sided edge pairs with the rule on: the edge's ends (`edge_ends`); a world's contact
    /// finds them with its masks, a caller of `collide_edge_and_polygon` may set them. Where they
    /// are known, a body that goes around an end changes sides, and one beyond a corner's other
    /// edge gets no contact.
    EdgeEnds edge_ends;
  };
  /// The face the last evaluation judged the pair on: A's edges first (0 to A's vertex count − 1),
  /// then B's; -1 none yet (`Config::warm_axis`).
  std::int8_t last_face = -1;
  Shapes shapes = Shapes::Unchecked;  ///< set when a world's contact is made, or by the first call
  /// The sum of the two shapes' bounding radii about their centroids (a circle's: its radius)
  /// (metres; `Config::bounds_early_out`, and a bound on the shapes' sizes for the exact solver).
  float radius_sum = 0;
  /// The pair's internal-edge masks (`Query::internal_edges`, Box2D's vertex order: A's bits, then
  /// B's); a world's contact finds them itself, a caller of `collide_polygons` sets them. For a
  /// pair beyond two triangles, `edges` and `closed_vertices` hold A's masks (`ShapeMasks`, up to
  /// 8 bits; an edge's: `Segment`'s, bit 0 its front, 1 its back, vertices `m_vertex1`,
  /// `m_vertex2`) and `masks_b` B's.
  InternalEdges internal_edges{};
  /// B's masks of a pair beyond two triangles (`ShapeMasks`; unused for triangle pairs).
  ShapeMasks masks_b{};
};

/// Registers the plug-in's contact for every pair family it answers (polygon–polygon,
/// polygon–circle, edge and chain against polygons and circles), with `backend` for triangle pairs
/// and `config` for all, and resets `stats`. Safe at any moment no thread is stepping a world, even
/// mid-simulation: the plug-in's contacts follow it from the next step, contacts Box2D made before
/// it keep Box2D's answer until they end (docs/box2d-plugin.md). A value outside `Backend` is
/// refused (`UnsupportedMethod`) and changes nothing.
InstallResult install(Backend backend, const Config& config = Config::all());

/// `install(backend_of(method), config)`; refused (`UnsupportedMethod`) for a method the plug-in
/// does not offer (`DyopPaper`, `Batch`).
InstallResult install(Method method, const Config& config = Config::all());

/// Registers Box2D's own `b2PolygonContact` again: a world made after it is bit-identical to one
/// that never saw the plug-in, and the plug-in's live contacts answer as Box2D's own. Safe
/// whenever `install` is; does nothing when not installed.
InstallResult uninstall();

/// The installed backend, or nothing when Box2D's own contact is registered.
std::optional<Backend> installed();

/// The skips of the installed backend (the last `install`'s).
Config installed_config();

/// The plug-in's answer for one polygon pair, exactly what its contact's `Evaluate` computes
/// with `config`: triangle pairs through `backend`, other polygon pairs exactly (`dyop::collide`,
/// with `memory`'s masks: `ContactMemory::internal_edges` A's, `masks_b` B's), or through
/// `b2CollidePolygons` for `Backend::Box2D` and `Config::triangles_only`. `memory` is the pair's
/// state from its previous evaluation (updated); nullptr: nothing remembered, a cold evaluation.
/// Counted in `stats`.
void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape& shape_a,
                      const b2Transform& xf_a, const b2PolygonShape& shape_b,
                      const b2Transform& xf_b, ContactMemory* memory = nullptr,
                      const Config& config = Config::all());

/// The plug-in's answer for one polygon–circle pair (the polygon as fixture A, as Box2D orders
/// them), exactly what its contact's `Evaluate` computes with `config`: the exact solver
/// (`dyop::collide`) with `memory`'s masks (`ContactMemory::internal_edges` holds the polygon's),
/// or Box2D's `b2CollidePolygonAndCircle` for `Backend::Box2D` and `Config::triangles_only`.
/// Counted in `stats`.
void collide_polygon_and_circle(b2Manifold* manifold, Backend backend,
                                const b2PolygonShape& polygon, const b2Transform& xf_a,
                                const b2CircleShape& circle, const b2Transform& xf_b,
                                ContactMemory* memory = nullptr,
                                const Config& config = Config::all());

/// The plug-in's answer for an edge (or a chain's child edge, from `b2ChainShape::GetChildEdge`) as
/// fixture A and a polygon, exactly what its contact's `Evaluate` computes with `config`: the exact
/// solver with Box2D's one-sided rules and, for a one-sided edge, the masks of its ghost vertices
/// (set in `memory` by the first call); for a two-sided edge, `memory`'s masks
/// (`ContactMemory::internal_edges`; none: both sides, as Box2D's); B's from `memory.masks_b`.
/// Box2D's `b2CollideEdgeAndPolygon` for `Backend::Box2D`, `Config::triangles_only` and
/// `Config::edges_and_chains` off. Counted in `stats`.
void collide_edge_and_polygon(b2Manifold* manifold, Backend backend, const b2EdgeShape& edge,
                              const b2Transform& xf_a, const b2PolygonShape& polygon,
                              const b2Transform& xf_b, ContactMemory* memory = nullptr,
                              const Config& config = Config::all());

/// The same for an edge and a circle (`b2CollideEdgeAndCircle`).
void collide_edge_and_circle(b2Manifold* manifold, Backend backend, const b2EdgeShape& edge,
                             const b2Transform& xf_a, const b2CircleShape& circle,
                             const b2Transform& xf_b, ContactMemory* memory = nullptr,
                             const Config& config = Config::all());

/// Counters since the last `install` or `reset_stats`, summed over every thread that evaluated
/// pairs (with one world, or worlds stepped one after another, the counts of those worlds).
struct Stats {
  /// Triangle pairs evaluated, per backend (index: `static_cast<int>(Backend)`).
  std::array<std::uint64_t, backend_count> triangle_pairs{};
  /// Other polygon pairs (a side with more than 3 vertices), evaluated by any path.
  std::uint64_t polygon_pairs = 0;
  /// Polygon–circle pairs evaluated by the plug-in's contact (none with `Config::triangles_only`).
  std::uint64_t circle_pairs = 0;
  /// Edge and chain pairs (against polygons and circles) evaluated by the plug-in's contact (none
  /// with `Config::triangles_only` or `Config::edges_and_chains` off).
  std::uint64_t edge_pairs = 0;
  /// Of `polygon_pairs`, `circle_pairs` and `edge_pairs`, those answered exactly by the solver
  /// (`dyop::collide`, for every backend but `Box2D`); the others by Box2D's own functions
  /// (`Backend::Box2D`, `Config::triangles_only`, or a shape the solver refuses, also counted in
  /// `fallbacks`).
  std::uint64_t exact_pairs = 0;
  /// Evaluations of the plug-in's pairs (every family) that produced a non-empty manifold.
  std::uint64_t manifolds = 0;
  /// Pairs of any family the backend or the solver could not answer (`Status::Invalid`, or a shape
  /// it refuses: `Triangle<float>::make`, `Polygon<float>`, `Segment<float>`), answered by Box2D's
  /// function instead so that the simulation goes on. Nonzero means the figures include Box2D's
  /// answers.
  std::uint64_t fallbacks = 0;
  /// Evaluations of every family answered without running the backend or the solver, per reason
  /// (index: `static_cast<int>(Skip)`); included in their family's count (`triangle_pairs`,
  /// `polygon_pairs`, `circle_pairs`, `edge_pairs`).
  std::array<std::uint64_t, skip_count> skipped{};
  /// Evaluations of any family run by an exact solver with internal edges or closed vertices in
  /// force (`Config::internal_edges`): the pairs whose contact the rule may change.
  std::uint64_t internal_edge_pairs = 0;
  /// Evaluations of any family that kept the contact's manifold (`Config::recycle_distance`);
  /// included in their family's count.
  std::uint64_t recycled = 0;
  /// Contacts the plug-in made (Box2D asks for one when two fixtures' boxes start to overlap).
  std::uint64_t contacts = 0;
  /// Evaluations of every family: the pairs the plug-in's contacts and entry points evaluated.
  std::uint64_t evaluations() const {
    std::uint64_t n = polygon_pairs + circle_pairs + edge_pairs;
    for (const std::uint64_t t : triangle_pairs) n += t;
    return n;
  }
  /// Evaluations answered afresh: neither kept (`recycled`) nor skipped.
  std::uint64_t answered() const {
    std::uint64_t n = evaluations() - recycled;
    for (const std::uint64_t k : skipped) n -= k;
    return n;
  }
  /// Triangle pairs evaluated by `b`.
  std::uint64_t triangles(Backend b) const { return triangle_pairs[static_cast<int>(b)]; }
  /// Triangle-pair evaluations skipped for reason `s`.
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
  /// Valid only when `ok()`: 3 CCW vertices in Box2D 2.4.1's order (under 2.4.2 too), skin radius.
  b2PolygonShape shape;
  bool ok() const { return error == ShapeError::None; }  ///< true when `error == None`
};

/// A `b2PolygonShape` triangle from three body-frame points (any winding), or the reason it cannot
/// be one, checked before Box2D 2.4 can assert (thin triangles abort in its centroid) or silently
/// turn a bad hull into a 2×2 box. The vertices are stored as Box2D 2.4.1's `Set` stores them: the
/// rightmost first (of two, the lower), then CCW. Under Box2D 2.4.2, whose `Set` welds vertices
/// within 2 cm and drops those within 1 cm of their neighbours' line (and then leaves the shape
/// empty), the shape is built through `Set(const b2Hull&)` in that order: both releases give the
/// same bits (`dyop/box2d_release.hpp`).
TriangleShape make_triangle(const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2);

}  // namespace dyop::box2d
