// The paper's equations 3–8, literally, for reproduction only (docs/paper.md lists what is wrong
// with them): each edge's line in slope–intercept form y = Mx + C (eq. 3, 4), the vertex's own
// intercept C_i (eq. 5), and the depth |C_i − C| / sqrt(X_P² + Y_P²) of eq. 8, which divides by
// the distance of P from the origin instead of sqrt(1 + M²). Vertical edges and P at the origin
// give `Invalid` (the equations have no value there); the true line distance is kept beside it so
// that a test can pin the paper's own Figure 6 (0.0580101 against the printed 0.0292043).

#include "dyop/dyop_paper.hpp"

#include <cmath>

#include "detail/fill_result.hpp"
#include "detail/pivot.hpp"

namespace dyop {

template <class T>
PaperLinesOrError<T> paper_lines(const Vec2<T>& p, const Vec2<T>& q, const Vec2<T>& x) {
  PaperLinesOrError<T> out;
  if (p.x() == q.x()) {
    out.reason = InvalidReason::PaperVerticalEdge;
    return out;
  }
  const T p_norm = std::sqrt(p.x() * p.x() + p.y() * p.y());
  if (!(p_norm > 0)) {
    out.reason = InvalidReason::PaperVertexAtOrigin;
    return out;
  }
  PaperLines<T>& l = out.lines;
  l.m = (p.y() - q.y()) / (p.x() - q.x());  // eq. 3
  l.c = p.y() - l.m * p.x();                // eq. 4
  l.c_vertex = x.y() - l.m * x.x();         // eq. 5
  const T dc = std::abs(l.c_vertex - l.c);
  l.depth_eq8 = l.m == 0 ? l.c - l.c_vertex : dc / p_norm;  // eq. 7, eq. 8
  l.true_distance = dc / std::sqrt(1 + l.m * l.m);
  if (!std::isfinite(l.m) || !std::isfinite(l.depth_eq8)) {
    out.reason = InvalidReason::PaperSlopeOverflow;
    out.lines = {};
  }
  return out;
}

namespace {

// Paper step 2: p is inside when the three sub-triangle areas add up to the triangle's area.
// Why a tolerance: float sums are never exactly equal; 8 eps of the area is rounding.
template <class T>
bool inside_by_areas(const Triangle<T>& t, const Vec2<T>& p) {
  auto area = [](const Vec2<T>& u, const Vec2<T>& v, const Vec2<T>& w) {
    return std::abs(cross(Vec2<T>(v - u), Vec2<T>(w - u))) / 2;
  };
  const Vec2<T>& v0 = t.vertex(0);
  const Vec2<T>& v1 = t.vertex(1);
  const Vec2<T>& v2 = t.vertex(2);
  const T whole = area(v0, v1, v2);
  const T parts = area(p, v0, v1) + area(p, v1, v2) + area(p, v2, v0);
  return std::abs(parts - whole) <= T(8) * Eigen::NumTraits<T>::epsilon() * whole;
}

// One direction: the pivot vertex of `from` against the pivot edge of `into`, world coordinates.
template <class T>
struct PaperDirection {
  InvalidReason reason = InvalidReason::None;  // None when this direction could be computed
  bool inside = false;
  T signed_depth = 0;  // eq. 7/8 magnitude, negative when the vertex is outside the edge line
  int edge = 0;        // CCW edge of `into`
  int vertex = 0;      // CCW vertex of `from`
};

template <class T>
PaperDirection<T> paper_direction(const Triangle<T>& from, const std::array<Vec2<T>, 3>& from_local,
                                  const Triangle<T>& into, const std::array<Vec2<T>, 3>& into_local,
                                  const Vec2<T>& pivot) {
  PaperDirection<T> d;
  d.vertex = detail::nearest_vertex(from_local, pivot);
  d.edge = detail::nearest_edge(into, into_local, pivot);
  const Vec2<T>& p = into.vertex(d.edge);
  const Vec2<T>& q = into.vertex(detail::next3(d.edge));
  const Vec2<T>& x = from.vertex(d.vertex);
  const PaperLinesOrError<T> lines = paper_lines(p, q, x);
  if (!lines.ok()) {
    d.reason = lines.reason;
    return d;
  }
  // The vertex is on the inner side of the edge line when its intercept lies on the same side as
  // the intercept of the triangle's third vertex.
  const Vec2<T>& third = into.vertex(detail::next3(detail::next3(d.edge)));
  const T c_third = third.y() - lines.lines.m * third.x();
  const bool inner = (lines.lines.c_vertex - lines.lines.c) * (c_third - lines.lines.c) > 0;
  const T magnitude = std::abs(lines.lines.depth_eq8);
  d.signed_depth = inner ? magnitude : -magnitude;
  d.inside = inside_by_areas(into, x);
  return d;
}

}  // namespace

template <class T>
Result<T> dyop_paper(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query) {
  const detail::PairFrame<T> f(a, b);
  const Vec2<T> pivot = detail::pivot_point(f);
  const PaperDirection<T> ab = paper_direction(a, f.a, b, f.b, pivot);
  const PaperDirection<T> ba = paper_direction(b, f.b, a, f.a, pivot);
  const InvalidReason reason = ab.reason != InvalidReason::None ? ab.reason : ba.reason;
  if (reason != InvalidReason::None) {
    Result<T> invalid;
    invalid.reason = reason;
    return invalid;
  }
  const detail::AxisOverlap<T> a_into_b{3 + ab.edge, ab.signed_depth, ab.vertex};
  const detail::AxisOverlap<T> b_into_a{ba.edge, ba.signed_depth, ba.vertex};
  return detail::answer_from_axis(
      f, query, detail::choose_direction(a_into_b, ab.inside, b_into_a, ba.inside));
}

template PaperLinesOrError<float> paper_lines(const Vec2<float>&, const Vec2<float>&,
                                              const Vec2<float>&);
template PaperLinesOrError<double> paper_lines(const Vec2<double>&, const Vec2<double>&,
                                               const Vec2<double>&);
template Result<float> dyop_paper(const Triangle<float>&, const Triangle<float>&,
                                  const Query<float>&);
template Result<double> dyop_paper(const Triangle<double>&, const Triangle<double>&,
                                   const Query<double>&);

}  // namespace dyop
