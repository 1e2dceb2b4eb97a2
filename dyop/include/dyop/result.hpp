#pragma once
/// \file
/// What a penetration query asks for (`Query`) and what it returns (`Result`), shared by every
/// method.
///
/// Conventions:
/// - `normal` is a unit vector pointing from A to B: translating B by `depth * normal` brings a
///   penetrating pair to touching.
/// - `separation` is signed: `-depth` when penetrating, the Euclidean distance when apart.
/// - Points are in world coordinates; feature indices are in the caller's vertex order (edge `i`
///   runs from vertex `i` to vertex `(i + 1) % 3`).
/// - Which fields are valid depends on the `status` and on the `Level` asked for; it is written
///   on each field. Fields that are not valid keep their default values.

#include <array>
#include <cstdint>
#include <limits>

#include "dyop/vec2.hpp"

namespace dyop {

/// How two triangles relate. `Touching` means |separation| is within rounding of zero
/// (`touching_tolerance`), so the closed triangles meet but neither overlaps the other.
enum class Status : std::uint8_t { Separated, Touching, Penetrating, Invalid };

/// Why a method answered `Status::Invalid`, for a caller to branch on (`describe` spells it out).
enum class InvalidReason : std::uint8_t {
  None,                 ///< the result is not Invalid (or no method ran: a default `Result`)
  NotPairMethod,        ///< `penetrate` was given a method with no per-pair entry (`Batch`)
  PaperVerticalEdge,    ///< `dyop_paper`: a vertical pivot edge has no slope (paper eq. 3)
  PaperVertexAtOrigin,  ///< `dyop_paper`: the pivot edge's P at the origin (eq. 8 divides by |P|)
  PaperSlopeOverflow,   ///< `dyop_paper`: the pivot edge too steep, its slope or depth not finite
};

/// A static, human-readable description of `r` ("unknown method", ...).
const char* describe(InvalidReason r);

/// How much a caller wants; a method computes nothing beyond the level asked for.
enum class Level : std::uint8_t {
  Overlap,   ///< `status` only; a method may exit at the first separating axis
  Depth,     ///< + `depth`, `separation`, `normal`
  Contact,   ///< + witness points and the feature pair
  Manifold,  ///< + up to two clipped contact points (as Box2D's solver needs)
};

/// Every level, shallowest first.
inline constexpr Level all_levels[] = {Level::Overlap, Level::Depth, Level::Contact,
                                       Level::Manifold};

/// "overlap", "depth", "contact", "manifold": the spelling in tables, CSV and benchmark names.
const char* name(Level level);

/// What a query at `Level::Depth` or above reports for a pair found apart.
enum class Apart : std::uint8_t {
  /// The Euclidean distance, its direction and (`Level::Contact` and above) the closest points
  /// and features: the exact answer, which costs a search over vertex–edge pairs.
  Distance,
  /// Only the proof of separation: `separation` is the largest gap along a candidate axis (an
  /// edge normal of either triangle, at least 0), a lower bound on the distance, and `normal` that
  /// axis; the witnesses and features are left at their defaults. Also for a pair whose gap lies
  /// in the touching band and whose distance proved it apart. So, with internal-edge masks,
  /// `separation > margin` is exactly the case the masks are not read (`Query::internal_edges`).
  /// For callers that want penetration depth and nothing for pairs apart (the paper's setting; a
  /// Box2D manifold beyond the skins). The exact methods (`dyop`, `sat`) honour it; the others
  /// find the distance on their way and report it (`lin_canny`, `epa`) or never compute one
  /// (`dyop_fast`, `dyop_paper`).
  Gap,
};

/// The masks of the internal-edge rule for one pair: where the triangles belong to triangulated
/// bodies, the edges and vertices along which no push may leave the body (caller's order: bit i
/// is A's edge or vertex i, bit 3 + i B's; edge i runs from vertex i to vertex i + 1).
struct InternalEdges {
  /// Edges internal to their body (covered by the other triangles of the body, or of a ground
  /// made of several bodies: see the Box2D plug-in's `Config::internal_edges`): their normals are
  /// not directions the body's outline allows.
  std::uint8_t edges = 0;
  /// Closed vertices: no edge axis of the other triangle whose deepest vertex is one of these is
  /// allowed, unless an edge of this triangle at that vertex that is not internal lies flat on
  /// the axis's face (turned from it by at most 1e-3 rad): the outline face then realises the
  /// axis as well. A vertex is closed where the body's outline is flat or reflex and one of its own
  /// triangle's edges there is internal (that triangle's other edge normal, an axis of its own, is
  /// the only direction the outline allows there), or where both of its edges in its triangle are
  /// internal (inside the body, or on the outline between other triangles' edges, whose own pairs
  /// carry its contact). A box sliding over a junction of flat ground triangles is then pushed up,
  /// never back.
  std::uint8_t closed_vertices = 0;

  /// True when any edge or vertex is marked: only then can the rule change an answer.
  constexpr bool any() const { return (edges | closed_vertices) != 0; }
  /// The pair's masks from each triangle's own (bits 0..2 each): A's as they are, B's moved up.
  static constexpr InternalEdges pair(InternalEdges a, InternalEdges b) {
    return {static_cast<std::uint8_t>(a.edges | b.edges << 3),
            static_cast<std::uint8_t>(a.closed_vertices | b.closed_vertices << 3)};
  }
};

/// True when `x` and `y` mark the same edges and vertices.
constexpr bool operator==(InternalEdges x, InternalEdges y) {
  return x.edges == y.edges && x.closed_vertices == y.closed_vertices;
}

/// A query: the level, what to report for pairs apart, and for `Level::Manifold` how contact
/// points are kept.
template <class T>
struct Query {
  Level level = Level::Depth;  ///< what to compute
  /// Manifold only: contact points (and whole manifolds of separated pairs) are kept while their
  /// separation is at most `margin` (length units; Box2D passes the sum of the two skins, so
  /// contacts are speculative). 0 keeps only touching and penetrating points.
  T margin = 0;
  /// Manifold only, exact methods: a face of B is the reference face only when its separation
  /// exceeds A's best by more than this (length units; Box2D uses 0.1·linearSlop) — hysteresis
  /// against the reference face flipping between frames. 0 takes the minimum-depth face.
  T face_hysteresis = 0;
  /// Level ≥ Depth: the distance of a pair found apart, or only a gap that proves it (`Apart`).
  /// The status is the same either way: a gap inside the touching band is decided by the distance.
  Apart apart = Apart::Distance;
  /// The internal-edge rule's masks (see `InternalEdges`). Honoured by the exact methods
  /// (`dyop`, `sat`; the others ignore them: `MethodInfo::internal_edges()`). The status (and, for
  /// pairs apart, `separation` and `normal`) is still decided over all six axes, so a pair
  /// separated only along an internal edge stays apart, and a pair apart beyond `margin` is
  /// answered as without masks. Otherwise, when the masks allow the pair's least axis and its
  /// reference face, the answer is the plain one; when not, `depth`, `normal` and the reference
  /// face come from the least *usable* axis: allowed (its edge not internal, its deepest vertex
  /// not closed but for an outline edge lying flat there: see `InternalEdges`) and reached (the
  /// other triangle touches that edge, within `margin` and the touching band): the exact depth of
  /// the pair along the directions the outline allows there. No usable axis: the status, `depth`
  /// and `normal` are the unrestricted answer and the manifold is empty (another pair of the two
  /// bodies carries the contact). One triangle reaching no edge of the other (held whole by it):
  /// allowed axes suffice. Empty (the default): every axis allowed, the plain answer, bit for bit.
  InternalEdges internal_edges{};
  /// Level::Manifold only: false leaves the Contact level's fields (`witness_a`, `witness_b`,
  /// `feature_a`, `feature_b`) at their defaults, for a caller that wants the manifold as Box2D's
  /// `b2CollidePolygons` gives it and nothing else (the Box2D plug-in). The status, the Depth
  /// level's fields and the manifold are the same either way, bit for bit. Honoured by the exact
  /// methods (`dyop`, `sat`); the others fill the fields anyway.
  bool witnesses = true;
  /// Manifold only: `Manifold::lead` is looked for up to this (length units); a lead at least
  /// this comes back +infinity. Default +infinity: always the lead.
  T lead_reach = std::numeric_limits<T>::infinity();
};

/// A vertex or an edge of one triangle, by caller's index.
struct Feature {
  /// What the feature is: none computed, a vertex or an edge.
  enum class Type : std::uint8_t { None, Vertex, Edge };
  Type type = Type::None;  ///< None when no feature was computed
  std::uint8_t index = 0;  ///< caller's vertex index, or caller's edge index (edge i: vertex i→i+1)
};

/// One contact point of a manifold.
template <class T>
struct ManifoldPoint {
  Vec2<T> point = Vec2<T>::Zero();  ///< world; on the incident triangle's edge (after clipping)
  T separation = 0;  ///< signed distance from the reference face line, negative when penetrating
  /// Feature pair that made the point, stable from frame to frame while the same features touch
  /// (warm starting matches on it): A's feature and B's (caller's indices), whichever triangle
  /// holds the reference face. A point not clipped is the reference edge against the incident
  /// vertex; a clipped point is the end vertex of the reference face whose side line cut it
  /// against the incident edge. So the key survives a change of reference face between the two
  /// triangles, as Box2D's contact ids do. Compare keys for equality only; the layout is not part
  /// of the API.
  std::uint32_t key = 0;
};

/// Up to two contact points on a reference face, in the manner of Box2D's `b2CollidePolygons`.
/// The face fields are set whenever a manifold was asked for, also when no point is within the
/// margin: they name the face the method judged the pair on (a caller can try it first next time).
template <class T>
struct Manifold {
  int point_count = 0;               ///< 0, 1 or 2
  bool reference_is_a = true;        ///< the reference face belongs to A (false: to B)
  std::uint8_t reference_edge = 0;   ///< caller's edge index of the reference face
  std::uint8_t incident_edge = 0;    ///< caller's edge index of the incident edge (other triangle)
  Vec2<T> normal = Vec2<T>::Zero();  ///< unit, A to B (reference face normal, negated for B)
  std::array<ManifoldPoint<T>, 2> points{};  ///< first `point_count` are valid
  /// With points, exact methods: the least overlap of the other axes, but the other shape's lying
  /// flush with the reference face, minus the face's (length units, ≥ −`face_hysteresis`);
  /// +infinity otherwise or from `lead_reach` on. While the pair moves less than
  /// `(face_hysteresis + lead) / 2`, no such axis beats the face by more than `face_hysteresis`.
  T lead = std::numeric_limits<T>::infinity();
};

/// The answer of every method, returned by value.
template <class T>
struct Result {
  Status status = Status::Invalid;             ///< always valid
  InvalidReason reason = InvalidReason::None;  ///< Invalid only: why (`describe`); None otherwise
  /// Level ≥ Depth, not Invalid: signed; `-depth` when penetrating, the distance when apart
  /// (with `Apart::Gap`, the exact methods give a lower bound on it: the largest axis gap).
  T separation = 0;
  /// Level ≥ Depth, not Invalid: `max(0, -separation)`, length units, ≥ 0.
  T depth = 0;
  /// Level ≥ Depth, not Invalid: unit, A to B. Penetrating or touching: the minimum-translation
  /// axis (B moved by `depth * normal` separates). Separated: from `witness_a` to `witness_b`
  /// (with `Apart::Gap`: the separating axis whose gap is `separation`).
  Vec2<T> normal = Vec2<T>::Zero();
  /// Level ≥ Contact, not Invalid: world. Penetrating: the deepest point of A inside B or its
  /// projection, so that `witness_a - witness_b == depth * normal`. Separated: closest points
  /// (`Apart::Distance` only; with `Apart::Gap` the witnesses and features keep their defaults).
  /// A manifold asked for with `Query::witnesses` false leaves them and the features at their
  /// defaults too.
  Vec2<T> witness_a = Vec2<T>::Zero();
  Vec2<T> witness_b = Vec2<T>::Zero();  ///< Level ≥ Contact: see `witness_a`
  Feature feature_a;     ///< Level ≥ Contact: the feature of A that realises the answer
  Feature feature_b;     ///< Level ≥ Contact: the feature of B that realises the answer
  int iterations = 0;    ///< iterative methods (Lin–Canny, EPA): steps taken; 0 for the others
  Manifold<T> manifold;  ///< Level == Manifold, not Invalid (points: those within `margin`)
};

/// Tolerance around zero separation inside which a pair is `Touching`, relative to the larger
/// triangle's size. Why: the exact methods compute a separation with a rounding error of a few
/// eps times the size (one subtraction into the local frame, one dot product); 32·eps keeps a
/// margin above that. double: 7.1e-15, float: 3.8e-6 (relative).
template <class T>
constexpr T touching_tolerance() {
  return T(32) * Eigen::NumTraits<T>::epsilon();
}

}  // namespace dyop
