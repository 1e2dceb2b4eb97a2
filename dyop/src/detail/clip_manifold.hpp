#pragma once
// Internal: Box2D-style contact manifold on a chosen reference face, shared by every method
// (after E. Catto's b2CollidePolygons, Box2D 2.4).
//
// The incident edge is the other triangle's edge most anti-parallel to the reference normal; it
// is clipped against the two side lines of the reference face (moved outwards by the margin, as
// Box2D moves them by the skins), and a clipped point is kept while its separation from the
// reference line is at most the margin. Keys name the feature pair so that they stay equal from
// frame to frame while the same features touch. Invariants: at most two points, each on the
// incident edge and within the reference face's side lines widened by the margin.

#include <algorithm>
#include <cstdint>

#include "detail/axis_overlap.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

// Which side line of the reference face clipped a manifold point (None: the point is an incident
// vertex itself); part of the point's key.
enum class ClipSide : std::uint8_t { None, Start, End };

// Key layout: the physical feature pair that made the point, in the caller's (A, B) order,
// whichever triangle holds the reference face: byte 0 A's feature index, byte 1 B's, byte 2 A's
// feature type, byte 3 B's (0 vertex, 1 edge; caller's indices). A point not clipped is the
// reference edge against an incident vertex; a clipped point is the reference face's end vertex
// whose side line cut it against the incident edge. So a point keeps its key when the reference
// face passes from one triangle to the other, or when it passes from an incident vertex to a
// side-line cut at the same features (b2ContactFeature's layout and meaning, as in
// b2CollidePolygons): warm starting carries its impulse through both. Measured in a tall rain
// (1,500 triangles into a triangulated bin, 10 seeds): keys naming the reference side and edge
// lost about 2 % of the warm starts Box2D keeps, and the world had 16 % more time-of-impact
// events than under Box2D's own contact; with these keys, as many. A manifold's points can have
// only four keys, found once per manifold; each point's key is then looked up.
class PointKeys {
 public:
  // `reference_edge`, `face_start` and `face_end`: the reference edge and its start and end
  // vertices; `incident_edge` and `incident_start`: the incident edge and its first vertex
  // (`incident_end` its second); every index the caller's. `reference_is_a`: whose face it is.
  PointKeys(int reference_edge, int face_start, int face_end, int incident_edge, int incident_start,
            int incident_end, bool reference_is_a) {
    const int ref_shift = reference_is_a ? 0 : 8;
    const int inc_shift = reference_is_a ? 8 : 0;
    const auto pair = [&](std::uint32_t ref, std::uint32_t inc) {
      return ref << ref_shift | inc << inc_shift;
    };
    const auto u = [](int index) { return static_cast<std::uint32_t>(index); };
    key_[0] = pair(u(reference_edge) | kEdge, u(incident_start));
    key_[1] = pair(u(face_start), u(incident_edge) | kEdge);
    key_[2] = pair(u(face_end), u(incident_edge) | kEdge);
    key_[3] = pair(u(reference_edge) | kEdge, u(incident_end));
  }

  // The key of the incident edge's end `end` (0 its first vertex, 1 its second), clipped at
  // `side` or not clipped (None). Looked up, not branched on: whether a side line cut the point
  // does not predict.
  std::uint32_t key(int end, ClipSide side) const {
    const int s = static_cast<int>(side);
    return key_[s + 3 * (end & static_cast<int>(s == 0))];
  }

 private:
  static constexpr std::uint32_t kEdge = 1u << 16;  // feature type Edge, at the type byte
  // The first end not clipped, a cut at the start side line, a cut at the end side line, the
  // second end not clipped: `key`'s order.
  std::uint32_t key_[4];
};

// One end of the incident edge after clipping: the end itself (side None) or the point where a
// side line cut it, as a position along the edge.
template <class T>
struct ClippedEnd {
  T along;        // 0 at the edge's first vertex, 1 at its second
  ClipSide side;  // which side line cut this end, None when the end is the vertex itself
};

// Box2D clips the incident edge against the start side line, then the end side line; along the
// edge the tangential coordinate s is linear, so both clips amount to clamping each end's s into
// [lo, hi] and moving the end by the same fraction. No branch on which ends are cut: an end not
// cut has clamped == s, so its fraction is `from` exactly; the divisor is made safe for an edge
// whose ends share s (then neither end is cut, or the caller returned before).
template <class T>
inline ClippedEnd<T> clip_end(T s, T s_other, T lo, T hi, T from) {
  const T clamped = std::min(std::max(s, lo), hi);
  const T ds = s_other - s;
  const T divisor = ds != T(0) ? ds : T(1);
  ClippedEnd<T> out;
  // Start (1) below the range, End (2) above it, None (0) inside: arithmetic, not branches.
  static_assert(static_cast<int>(ClipSide::Start) == 1 && static_cast<int>(ClipSide::End) == 2);
  out.side = static_cast<ClipSide>(static_cast<int>(s < lo) | static_cast<int>(s > hi) << 1);
  out.along = from + (clamped - s) / divisor * (T(1) - 2 * from);
  return out;
}

// The clip once the faces are chosen (every vertex count): incident edge p0→p1 against the
// reference face v1→v2 of outward unit normal `n`, in a frame whose origin is `origin`; each point
// keyed by `keys`, appended to `m` when within the margin.
template <class T>
inline void clip_incident_edge(const Vec2<T>& v1, const Vec2<T>& v2, const Vec2<T>& n,
                               const Vec2<T>& p0, const Vec2<T>& p1, T margin,
                               const PointKeys& keys, const Vec2<T>& origin, Manifold<T>& m) {
  const Vec2<T> tangent(-n.y(), n.x());  // unit, from v1 to v2 (CCW edge, outward normal n)
  const T s0 = tangent.dot(p0);
  const T s1 = tangent.dot(p1);
  const T lo = tangent.dot(v1) - margin;
  const T hi = tangent.dot(v2) + margin;
  // The whole edge beyond one side line: Box2D's clip leaves fewer than two points, no manifold.
  if (std::max(s0, s1) < lo || std::min(s0, s1) > hi) return;

  const ClippedEnd<T> ends[2] = {clip_end(s0, s1, lo, hi, T(0)), clip_end(s1, s0, lo, hi, T(1))};
  const Vec2<T>* vertex_point[2] = {&p0, &p1};
  const T front = n.dot(v1);
  for (int k = 0; k < 2; ++k) {
    // An end the side lines did not cut is the incident vertex itself, bit for bit.
    const bool cut = ends[k].side != ClipSide::None;
    // Looked up by index, not branched on: whether a side line cuts an end does not predict.
    const Vec2<T> choice[2] = {*vertex_point[k], p0 + ends[k].along * (p1 - p0)};
    const Vec2<T>& p = choice[static_cast<int>(cut)];
    const T separation = n.dot(p) - front;
    // Written into the next slot whether kept or not, and counted only when within the margin:
    // whether an end lies beyond the margin is not predictable (slots past `point_count` are
    // not part of the answer).
    ManifoldPoint<T>& out = m.points[static_cast<std::size_t>(m.point_count)];
    out.point = p + origin;
    out.separation = separation;
    out.key = keys.key(k, ends[k].side);
    m.point_count += static_cast<int>(separation <= margin);
  }
}

// Sets `m`'s face fields for the face of `reference_axis` (its points are left as they are).
template <class T>
void set_reference_face(const PairFrame<T>& f, int reference_axis, Manifold<T>& m) {
  const bool ref_is_a = reference_axis < 3;
  const int e = ref_is_a ? reference_axis : reference_axis - 3;
  const Vec2<T>& n = ref_is_a ? f.ta.normal(e) : f.tb.normal(e);
  m.reference_is_a = ref_is_a;
  m.reference_edge = static_cast<std::uint8_t>((ref_is_a ? f.ta : f.tb).input_edge(e));
  m.normal = ref_is_a ? n : Vec2<T>(-n);
}

// Fills `m`, which has no point yet, with the manifold on the face of `reference_axis`: written
// in place, since a Result is large and a query's time is short.
template <class T>
void clip_manifold(const PairFrame<T>& f, int reference_axis, T margin, Manifold<T>& m) {
  const bool ref_is_a = reference_axis < 3;
  const int e = ref_is_a ? reference_axis : reference_axis - 3;
  const Triangle<T>& rt = ref_is_a ? f.ta : f.tb;
  const Triangle<T>& it = ref_is_a ? f.tb : f.ta;
  const std::array<Vec2<T>, 3>& rv = ref_is_a ? f.a : f.b;
  const std::array<Vec2<T>, 3>& iv = ref_is_a ? f.b : f.a;
  const Vec2<T>& n = rt.normal(e);

  set_reference_face(f, reference_axis, m);

  T least;
  int inc;
  min3(n.dot(it.normal(0)), n.dot(it.normal(1)), n.dot(it.normal(2)), least, inc);
  m.incident_edge = static_cast<std::uint8_t>(it.input_edge(inc));

  const PointKeys keys(m.reference_edge, rt.input_vertex(e), rt.input_vertex(next3(e)),
                       m.incident_edge, it.input_vertex(inc), it.input_vertex(next3(inc)),
                       ref_is_a);
  clip_incident_edge(rv[e], rv[next3(e)], n, iv[inc], iv[next3(inc)], margin, keys, f.origin, m);
}

}  // namespace dyop::detail
