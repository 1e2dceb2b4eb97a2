// Lin–Canny closest-feature tracking (M. C. Lin, J. F. Canny, 1991; V-Clip, B. Mirtich, 1998),
// the paper's baseline (dyop/lin_canny.hpp has the whole description).
//   1. Feature walk from the cached feature pair (or vertex 0 of each, cold): each state tests
//      each feature's closest point against the other feature's Voronoi region and steps to the
//      neighbouring feature a violated region names; it ends proving the pair apart (exact
//      distance), or finding it meeting (a vertex inside, two edges crossing, a distance inside
//      the touching band).
//   2. Meeting pairs: a depth walk over the six axes sorted by angle (the cycle of A − B's edge
//      normals), from the least overlap among the meeting features' axes and the cached axis,
//      moving while the overlap strictly decreases: a local minimum, never below the true depth.
//   Invariants: a visited set (36 feature pairs) stops a rounding cycle; the depth walk visits
//   each axis at most once; `iterations` ≤ lin_canny_max_steps.

#include "dyop/lin_canny.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "detail/fill_result.hpp"

namespace dyop {
namespace {

using detail::AxisOverlap;
using detail::Closest;
using detail::next3;
using detail::PairFrame;

inline int prev3(int i) { return i == 0 ? 2 : i - 1; }

inline Feature vertex(int i) { return {Feature::Type::Vertex, static_cast<std::uint8_t>(i)}; }
inline Feature edge(int i) { return {Feature::Type::Edge, static_cast<std::uint8_t>(i)}; }

// The walk's state: one feature of each triangle, CCW indices.
struct FeaturePair {
  Feature a;
  Feature b;
};

// 0..35: one bit per feature pair in the visited set.
inline int state_index(const FeaturePair& p) {
  auto code = [](Feature x) { return (x.type == Feature::Type::Edge ? 3 : 0) + x.index; };
  return code(p.a) * 6 + code(p.b);
}

// Up to four axes of one feature pair, and room for the cached axis.
using AxisList = std::array<int, 5>;

// Axes of the edges that bound the pair's features (a vertex: both its edges): the axes of the
// Minkowski difference that belong to this pair of features. Returns how many.
inline int incident_axes(const FeaturePair& p, AxisList& out) {
  int n = 0;
  auto add = [&](Feature x, int base) {
    if (x.type == Feature::Type::Vertex) out[n++] = base + prev3(x.index);
    out[n++] = base + x.index;
  };
  add(p.a, 0);
  add(p.b, 3);
  return n;
}

// One triangle as the walk sees it.
template <class T>
struct Side {
  const std::array<Vec2<T>, 3>& v;  // CCW vertices, local
  const Triangle<T>& t;             // for the unit normals
  Vec2<T> edge(int i) const { return v[next3(i)] - v[i]; }
};

// The edge of `x` through whose side of vertex i's Voronoi region the point `q` leaves, or -1.
// The comparisons are closest_on_edge's, to the bit: the vertex–edge state that follows agrees that
// q is off the vertex, so rounding cannot bounce the walk straight back.
template <class T>
int leaves_vertex_region(const Side<T>& x, int i, const Vec2<T>& q) {
  if (x.edge(i).dot(q - x.v[i]) > 0) return i;
  const int p = prev3(i);
  const Vec2<T> e = x.edge(p);
  if (e.dot(q - x.v[p]) < e.squaredNorm()) return p;
  return -1;
}

// The edge of `x` leaving vertex i that gets closer along the unit direction `d`, or -1 when `d`
// lies in the vertex's normal cone (the vertex is then x's extreme point along d). When both edges
// do, the steeper one: with a nearly parallel edge the other test is a coin toss of rounding, and
// following it can close a cycle. cross(n, d) is d along the edge's unit direction (left of n).
template <class T>
int turns_from_vertex(const Side<T>& x, int i, const Vec2<T>& d) {
  const int p = prev3(i);
  const T out = cross(x.t.normal(i), d);    // > 0: moving along edge i gains on d
  const T back = -cross(x.t.normal(p), d);  // > 0: moving back along edge p gains on d
  if (out > 0 && out >= back) return i;
  return back > 0 ? p : -1;
}

enum class Outcome { Moved, Closest, Contact };

// Closest-feature walk (V-Clip reduced to 2D). Each state holds its closest-point candidate in
// `last` with the squared distance in `last.distance`; the square root is taken once, at the end.
template <class T>
struct FeatureWalk {
  FeatureWalk(const PairFrame<T>& frame, const FeaturePair& start)
      : f(frame), a{frame.a, frame.ta}, b{frame.b, frame.tb}, pair(start) {}

  const PairFrame<T>& f;
  Side<T> a;
  Side<T> b;
  FeaturePair pair;
  Closest<T> last;
  Closest<T> best;  // least-distance candidate seen: the answer if the cycling guard trips
  bool has_best = false;
  T inside = 0;  // > 0: a vertex is this deep inside the other triangle, a lower bound on depth

  void offer(const Closest<T>& c) {
    if (!has_best || c.distance < best.distance) best = c;
    has_best = true;
  }

  Outcome vertex_vertex() {
    const int i = pair.a.index;
    const int j = pair.b.index;
    last = Closest<T>{};
    last.distance = (f.b[j] - f.a[i]).squaredNorm();
    last.point_a = f.a[i];
    last.point_b = f.b[j];
    last.feature_a = pair.a;
    last.feature_b = pair.b;
    offer(last);
    int e = leaves_vertex_region(a, i, f.b[j]);
    if (e >= 0) {
      pair.a = edge(e);
      return Outcome::Moved;
    }
    e = leaves_vertex_region(b, j, f.a[i]);
    if (e >= 0) {
      pair.b = edge(e);
      return Outcome::Moved;
    }
    return Outcome::Closest;
  }

  // A vertex of one triangle (A when `vertex_of_a`) against an edge of the other.
  Outcome vertex_edge(bool vertex_of_a) {
    const Side<T>& x = vertex_of_a ? a : b;
    const Side<T>& y = vertex_of_a ? b : a;
    Feature& fx = vertex_of_a ? pair.a : pair.b;
    Feature& fy = vertex_of_a ? pair.b : pair.a;
    const int i = fx.index;
    const int j = fy.index;
    const Vec2<T>& p = x.v[i];
    const Vec2<T>& n = y.t.normal(j);
    Vec2<T> c;
    Feature fe;
    const T sq = detail::closest_on_edge(y.v, j, n, p, c, fe);
    if (fe.type == Feature::Type::Vertex) {  // p is past an end of the edge's region
      fy = fe;
      return Outcome::Moved;
    }
    const T h = n.dot(p - y.v[j]);
    if (h < 0) {
      // Behind the edge's line: p is inside y, or outside another edge, the one it is farthest
      // out of (Mirtich's escape from a local minimum). Inside, the walk has found the overlap.
      int k = j;
      T most = h;
      for (int e = 0; e < 3; ++e) {
        const T s = y.t.normal(e).dot(p - y.v[e]);
        if (s > most) {
          most = s;
          k = e;
        }
      }
      fy = edge(k);
      if (most > 0) return Outcome::Moved;
      inside = -most;
      return Outcome::Contact;
    }
    last = Closest<T>{};
    last.distance = sq;
    // The edge's own normal, not the difference of the points: exact direction, full accuracy.
    last.normal = vertex_of_a ? Vec2<T>(-n) : n;
    (vertex_of_a ? last.point_a : last.point_b) = p;
    (vertex_of_a ? last.point_b : last.point_a) = c;
    last.feature_a = pair.a;
    last.feature_b = pair.b;
    offer(last);
    const int e = turns_from_vertex(x, i, Vec2<T>(-n));
    if (e >= 0) {
      fx = edge(e);
      return Outcome::Moved;
    }
    return Outcome::Closest;
  }

  // Two edges either cross (the triangles overlap) or are closest at an end of one of them: in 2D
  // that end is the whole of V-Clip's edge clipping, so the walk moves to it.
  Outcome edge_edge() {
    const int i = pair.a.index;
    const int j = pair.b.index;
    const Vec2<T>& na = f.ta.normal(i);
    const Vec2<T>& nb = f.tb.normal(j);
    const Vec2<T>& a0 = f.a[i];
    const Vec2<T>& b0 = f.b[j];
    const bool b_straddles = (na.dot(b0 - a0) < 0) != (na.dot(f.b[next3(j)] - a0) < 0);
    const bool a_straddles = (nb.dot(a0 - b0) < 0) != (nb.dot(f.a[next3(i)] - b0) < 0);
    if (a_straddles && b_straddles) return Outcome::Contact;
    T least = std::numeric_limits<T>::infinity();
    for (int s = 0; s < 2; ++s) {
      Vec2<T> c;
      Feature fe;
      const int va = s == 0 ? i : next3(i);
      T d = detail::closest_on_edge(f.b, j, nb, f.a[va], c, fe);
      if (d < least) {
        least = d;
        pair = {vertex(va), fe};
      }
      const int vb = s == 0 ? j : next3(j);
      d = detail::closest_on_edge(f.a, i, na, f.b[vb], c, fe);
      if (d < least) {
        least = d;
        pair = {fe, vertex(vb)};
      }
    }
    return Outcome::Moved;
  }

  Outcome step() {
    const bool va = pair.a.type == Feature::Type::Vertex;
    const bool vb = pair.b.type == Feature::Type::Vertex;
    if (va && vb) return vertex_vertex();
    if (va) return vertex_edge(true);
    if (vb) return vertex_edge(false);
    return edge_edge();
  }
};

// How the feature walk ended.
template <class T>
struct WalkEnd {
  FeaturePair pair;    // last feature pair: the warm start of the next query
  bool apart = false;  // `closest` is the distance, above the touching band; else the pair meets
  Closest<T> closest;  // apart only; local coordinates
  T inside = 0;        // see FeatureWalk::inside
  int steps = 0;
};

// Gap between A and B along the unit direction `u` (A to B): positive when `u` separates them.
template <class T>
T gap_along(const PairFrame<T>& f, const Vec2<T>& u) {
  const T reach_a = std::max({u.dot(f.a[0]), u.dot(f.a[1]), u.dot(f.a[2])});
  const T reach_b = std::min({u.dot(f.b[0]), u.dot(f.b[1]), u.dot(f.b[2])});
  return reach_b - reach_a;
}

// Settles a candidate (squared distance) as the answer when it is above the touching band, and
// when `prove` also its direction separates the pair by more than the band. The direction comes
// from the points when no edge gave one (vertex–vertex), never as 0 / 0.
template <class T>
void settle_apart(const PairFrame<T>& f, Closest<T> c, bool prove, WalkEnd<T>& end) {
  const T band = detail::touching_band(f);
  c.distance = std::sqrt(c.distance);
  if (!(c.distance > band)) return;
  if (c.normal.isZero()) c.normal = (c.point_b - c.point_a) / c.distance;
  if (prove && !(gap_along(f, c.normal) > band)) return;
  end.apart = true;
  end.closest = c;
  end.pair = {c.feature_a, c.feature_b};
}

template <class T>
WalkEnd<T> feature_walk(const PairFrame<T>& f, const FeaturePair& start) {
  FeatureWalk<T> w(f, start);
  WalkEnd<T> end;
  std::uint64_t visited = 0;
  while (end.steps < lin_canny_max_steps) {
    const std::uint64_t bit = std::uint64_t{1} << state_index(w.pair);
    if (visited & bit) break;  // a cycle, closed by rounding at a near-tie
    visited |= bit;
    ++end.steps;
    const Outcome o = w.step();
    if (o == Outcome::Moved) continue;
    end.pair = w.pair;
    end.inside = w.inside;
    // A final state's regions are its proof: the direction separates the pair.
    if (o == Outcome::Closest) settle_apart(f, w.last, false, end);
    return end;
  }
  // Guard tripped. The least distance seen is a true distance between points of A and B (at the
  // near-tie that closed the cycle, the distance itself), but the cycle broke the chain of proof:
  // it is the answer only when its direction separates the pair; else the pair is taken as meeting
  // and the depth walk decides.
  end.pair = w.pair;
  if (w.has_best) settle_apart(f, w.best, true, end);
  return end;
}

// Position of `u` on the unit diamond, increasing with its angle over [0, 2π): orders axes by
// angle with one division and no trigonometry.
template <class T>
T pseudo_angle(const Vec2<T>& u) {
  const T p = u.y() / (std::abs(u.x()) + std::abs(u.y()));
  if (u.x() < 0) return 2 - p;
  return u.y() < 0 ? 4 + p : p;
}

template <class T>
struct DepthEnd {
  AxisOverlap<T> least;
  int steps = 0;
};

// Walks the cycle of the six axes sorted by angle (the edge normals of the Minkowski difference
// A − B, in the order of its edges) while a neighbour has a smaller overlap. It starts from the
// least overlap among the axes of the edges bounding the meeting pair and the cached axis (`cached`
// >= 0): the cached axis alone could strand a pair that merely touches in a positive local minimum,
// while the pair's own axes hold its contact. Overlap strictly decreases, so no axis is visited
// twice; the end is a local minimum, which can exceed the true (global) depth.
template <class T>
DepthEnd<T> depth_walk(const PairFrame<T>& f, const FeaturePair& pair, int cached) {
  std::array<int, 6> ring{0, 1, 2, 3, 4, 5};
  std::array<T, 6> angle;
  for (int k = 0; k < 6; ++k) angle[k] = pseudo_angle(f.axis(k));
  for (int s = 1; s < 6; ++s) {
    for (int t = s; t > 0 && angle[ring[t]] < angle[ring[t - 1]]; --t) {
      std::swap(ring[t], ring[t - 1]);
    }
  }
  std::array<int, 6> slot;
  for (int s = 0; s < 6; ++s) slot[ring[s]] = s;

  DepthEnd<T> end;
  std::array<AxisOverlap<T>, 6> seen;
  unsigned evaluated = 0;  // visited set of the depth walk
  auto overlap = [&](int k) {
    if (!(evaluated >> k & 1u)) {
      seen[k] = detail::overlap_on_axis(f, k);
      evaluated |= 1u << k;
      ++end.steps;
    }
    return seen[k].overlap;
  };
  AxisList starts;
  int n = incident_axes(pair, starts);
  if (cached >= 0) starts[n++] = cached;
  int at = starts[0];
  for (int c = 1; c < n; ++c) {
    if (overlap(starts[c]) < overlap(at)) at = starts[c];
  }
  for (;;) {
    const int before = ring[(slot[at] + 5) % 6];
    const int after = ring[(slot[at] + 1) % 6];
    const int next = overlap(after) < overlap(before) ? after : before;
    if (!(overlap(next) < overlap(at))) break;
    at = next;
  }
  end.least = seen[at];
  return end;
}

// Of the pair's incident axes, the one closest to the separating direction `u`: the reference face
// of a speculative manifold, and where a depth walk starts once the pair comes into contact.
template <class T>
int aligned_axis(const PairFrame<T>& f, const FeaturePair& pair, const Vec2<T>& u) {
  AxisList axes;
  const int n = incident_axes(pair, axes);
  int best = axes[0];
  for (int c = 1; c < n; ++c) {
    if (f.axis(axes[c]).dot(u) > f.axis(best).dot(u)) best = axes[c];
  }
  return best;
}

template <class T>
void fill_apart(const PairFrame<T>& f, const Query<T>& q, const Closest<T>& c, int axis,
                Result<T>& r) {
  detail::fill_closest(f, q.level, c, r);
  if (q.level == Level::Manifold) detail::fill_manifold(f, q, detail::overlap_on_axis(f, axis), r);
}

// A cache is opaque caller-owned memory: anything out of range starts cold instead of indexing
// out of bounds.
inline bool usable(const LinCannyCache& c) {
  auto feature_type = [](Feature::Type t) {
    return t == Feature::Type::Vertex || t == Feature::Type::Edge;
  };
  return c.valid && feature_type(c.type_a) && feature_type(c.type_b) && c.index_a < 3 &&
         c.index_b < 3 && c.depth_axis < 6;
}

}  // namespace

template <class T>
Result<T> lin_canny(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query,
                    LinCannyCache* cache) {
  const detail::PairFrame<T> f(a, b);
  const bool warm = cache != nullptr && usable(*cache);
  const FeaturePair start =
      warm ? FeaturePair{{cache->type_a, cache->index_a}, {cache->type_b, cache->index_b}}
           : FeaturePair{vertex(0), vertex(0)};
  const WalkEnd<T> w = feature_walk(f, start);

  Result<T> r;
  int axis;
  int steps = w.steps;
  if (w.apart) {
    axis = aligned_axis(f, w.pair, w.closest.normal);
    fill_apart(f, query, w.closest, axis, r);
  } else if (query.level == Level::Overlap && w.inside > detail::touching_band(f)) {
    // A vertex deeper than the band inside the other triangle: no translation shorter than that
    // frees it, so the pair penetrates whatever the depth walk would find.
    r.status = Status::Penetrating;
    axis = w.pair.a.type == Feature::Type::Edge ? w.pair.a.index : 3 + w.pair.b.index;
  } else {
    const DepthEnd<T> d = depth_walk(f, w.pair, warm ? int{cache->depth_axis} : -1);
    r = detail::answer_from_axis(f, query, d.least);
    axis = d.least.axis;
    steps += d.steps;
  }
  r.iterations = steps;
  if (cache != nullptr) {
    cache->valid = true;
    cache->type_a = w.pair.a.type;
    cache->index_a = w.pair.a.index;
    cache->type_b = w.pair.b.type;
    cache->index_b = w.pair.b.index;
    cache->depth_axis = static_cast<std::uint8_t>(axis);
  }
  return r;
}

template Result<float> lin_canny(const Triangle<float>&, const Triangle<float>&,
                                 const Query<float>&, LinCannyCache*);
template Result<double> lin_canny(const Triangle<double>&, const Triangle<double>&,
                                  const Query<double>&, LinCannyCache*);

}  // namespace dyop
