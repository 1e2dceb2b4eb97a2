#pragma once
// Internal: Box2D-style contact manifold on a chosen reference face, shared by every method.
//
// The incident edge is the other triangle's edge most anti-parallel to the reference normal; it
// is clipped against the two side lines of the reference face (moved outwards by the margin, as
// Box2D moves them by the skins), and a clipped point is kept while its separation from the
// reference line is at most the margin. Keys name the feature pair so that they stay equal from
// frame to frame while the same features touch.

#include <cstdint>

#include "detail/axis_overlap.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

// Key layout: byte 0 reference side (0: A, 1: B), byte 1 caller's reference edge, byte 2 caller's
// incident vertex (unclipped) or incident edge (clipped), byte 3 the ClipSide.
inline std::uint32_t contact_key(bool reference_is_b, int ref_edge, int incident, ClipSide side) {
  return static_cast<std::uint32_t>(reference_is_b) | static_cast<std::uint32_t>(ref_edge) << 8 |
         static_cast<std::uint32_t>(incident) << 16 | static_cast<std::uint32_t>(side) << 24;
}

template <class T>
struct ClipVertex {
  Vec2<T> p;
  int incident;    // CCW index: the incident vertex, or the incident edge when clipped
  ClipSide side;   // None: an original incident vertex
};

// Keeps the part of segment `in` with `dot(dir, p) <= offset`; returns the number of points out.
template <class T>
inline int clip_segment(const ClipVertex<T> in[2], ClipVertex<T> out[2], const Vec2<T>& dir,
                        T offset, int incident_edge, ClipSide side) {
  int count = 0;
  const T d0 = dir.dot(in[0].p) - offset;
  const T d1 = dir.dot(in[1].p) - offset;
  if (d0 <= 0) out[count++] = in[0];
  if (d1 <= 0) out[count++] = in[1];
  if (d0 * d1 < 0) {
    const T t = d0 / (d0 - d1);
    out[count++] = {in[0].p + t * (in[1].p - in[0].p), incident_edge, side};
  }
  return count;
}

template <class T>
Manifold<T> clip_manifold(const PairFrame<T>& f, int reference_axis, T margin) {
  const bool ref_is_a = reference_axis < 3;
  const int e = ref_is_a ? reference_axis : reference_axis - 3;
  const Triangle<T>& rt = ref_is_a ? f.ta : f.tb;
  const Triangle<T>& it = ref_is_a ? f.tb : f.ta;
  const std::array<Vec2<T>, 3>& rv = ref_is_a ? f.a : f.b;
  const std::array<Vec2<T>, 3>& iv = ref_is_a ? f.b : f.a;
  const Vec2<T>& n = rt.normal(e);

  Manifold<T> m;
  m.reference_is_a = ref_is_a;
  m.reference_edge = static_cast<std::uint8_t>(rt.input_edge(e));
  m.normal = ref_is_a ? n : Vec2<T>(-n);

  int inc = 0;
  T least = n.dot(it.normal(0));
  for (int k = 1; k < 3; ++k) {
    const T d = n.dot(it.normal(k));
    if (d < least) { least = d; inc = k; }
  }
  m.incident_edge = static_cast<std::uint8_t>(it.input_edge(inc));

  const Vec2<T>& v1 = rv[e];
  const Vec2<T>& v2 = rv[next3(e)];
  const Vec2<T> tangent(-n.y(), n.x());  // unit, from v1 to v2 (CCW edge, outward normal n)
  const ClipVertex<T> segment[2] = {{iv[inc], inc, ClipSide::None},
                                    {iv[next3(inc)], next3(inc), ClipSide::None}};
  ClipVertex<T> once[2];
  ClipVertex<T> twice[2];
  if (clip_segment(segment, once, Vec2<T>(-tangent), margin - tangent.dot(v1), inc,
                   ClipSide::Start) < 2 ||
      clip_segment(once, twice, tangent, tangent.dot(v2) + margin, inc, ClipSide::End) < 2) {
    return m;
  }
  const T front = n.dot(v1);
  for (const ClipVertex<T>& c : twice) {
    const T s = n.dot(c.p) - front;
    if (s > margin) continue;
    const int incident = c.side == ClipSide::None ? it.input_vertex(c.incident)
                                                  : it.input_edge(c.incident);
    ManifoldPoint<T>& out = m.points[m.point_count++];
    out.point = c.p + f.origin;
    out.separation = s;
    out.key = contact_key(!ref_is_a, m.reference_edge, incident, c.side);
  }
  return m;
}

}  // namespace dyop::detail
