// `collide` for a segment (a Box2D edge) against a polygon and against a circle: validation with
// named reasons, the two sides and their normals, answers worked by hand on either side, beyond
// an end and apart, the one-sided and closed-end masks, and the same answer whichever side of
// the segment the polygon is given from.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dyop/convex_pair.hpp"
#include "support/result_checks.hpp"
#include "support/scalars.hpp"

namespace dyop {
namespace {

template <class T>
class SegmentPair : public ::testing::Test {};
using test_support::ScalarNames;
using test_support::Scalars;
using test_support::tol;
TYPED_TEST_SUITE(SegmentPair, Scalars, ScalarNames);

template <class T>
Segment<T> segment(T x0, T y0, T x1, T y1) {
  const SegmentOrError<T> s = Segment<T>::make({x0, y0}, {x1, y1});
  EXPECT_TRUE(s.ok()) << describe(s.error);
  return s.segment;
}

// The axis-aligned box [x0, x1] × [y0, y1], counter-clockwise from the lower left.
template <class T>
Polygon<T> box(T x0, T y0, T x1, T y1) {
  const Vec2<T> v[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  const PolygonOrError<T> p = Polygon<T>::make(v, 4);
  EXPECT_TRUE(p.ok()) << describe(p.error);
  return p.polygon;
}

template <class T>
ConvexQuery<T> manifold_query(T margin = 0) {
  ConvexQuery<T> q;
  q.level = Level::Manifold;
  q.margin = margin;
  return q;
}

TYPED_TEST(SegmentPair, ValidationNamesWhatIsWrong) {
  using T = TypeParam;
  EXPECT_EQ(Segment<T>::check({1, 2}, {1, 2}), ConvexError::RepeatedVertex);
  EXPECT_EQ(Segment<T>::check({0, 0}, {T(NAN), 1}), ConvexError::NonFinite);
  EXPECT_EQ(Segment<T>::check({0, 0}, {T(INFINITY), 1}), ConvexError::NonFinite);
  EXPECT_EQ(Segment<T>::check({0, 0}, {2 * max_coordinate<T>(), 0}), ConvexError::TooLarge);
  EXPECT_EQ(Segment<T>::check({0, 0}, {min_size<T>() / 4, 0}), ConvexError::TooSmall);
  EXPECT_EQ(Segment<T>::check({0, 0}, {0, 1}), ConvexError::None);
  EXPECT_FALSE(Segment<T>::make({0, 0}, {0, 0}).ok());
}

// Box2D's edge normal: to the right of vertex 1 → vertex 2, the front of a one-sided edge.
TYPED_TEST(SegmentPair, FrontIsToTheRightOfItsDirection) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(-1, 0, 1, 0);
  EXPECT_EQ(s.count(), 2);
  EXPECT_NEAR(s.normal(0).x(), 0, tol<T>());
  EXPECT_NEAR(s.normal(0).y(), -1, tol<T>());
  EXPECT_EQ(s.normal(1), Vec2<T>(-s.normal(0)));
  EXPECT_NEAR(s.size(), 2, tol<T>());
}

// A box sunk 0.1 into a segment from its front: pushed out along the front normal, two points on
// the box's bottom, the segment's front the reference face.
TYPED_TEST(SegmentPair, BoxOnTheFrontIsPushedOutAlongTheFrontNormal) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(1, 0, -1, 0);  // front up
  const Result<T> r = collide(s, box<T>(T(-0.5), T(-0.1), T(0.5), T(0.9)), manifold_query<T>());
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.separation, -0.1, tol<T>());
  EXPECT_NEAR(r.normal.x(), 0, tol<T>());
  EXPECT_NEAR(r.normal.y(), 1, tol<T>());
  ASSERT_EQ(r.manifold.point_count, 2);
  EXPECT_TRUE(r.manifold.reference_is_a);
  EXPECT_EQ(r.manifold.reference_edge, 0);
  for (const ManifoldPoint<T>& p : r.manifold.points) {
    EXPECT_NEAR(p.point.y(), -0.1, tol<T>());
    EXPECT_NEAR(std::abs(p.point.x()), 0.5, tol<T>());
    EXPECT_NEAR(p.separation, -0.1, tol<T>());
  }
  EXPECT_NE(r.manifold.points[0].key, r.manifold.points[1].key);
}

// The same box given the segment the other way round lies at its back: the same push, along the
// back normal (edge 1), as a two-sided Box2D edge answers either side.
TYPED_TEST(SegmentPair, BoxOnTheBackIsPushedOutAlongTheBackNormal) {
  using T = TypeParam;
  const Polygon<T> b = box<T>(T(-0.5), T(-0.1), T(0.5), T(0.9));
  const Result<T> front = collide(segment<T>(1, 0, -1, 0), b, manifold_query<T>());
  const Result<T> back = collide(segment<T>(-1, 0, 1, 0), b, manifold_query<T>());
  EXPECT_EQ(back.status, Status::Penetrating);
  EXPECT_NEAR(back.separation, front.separation, tol<T>());
  EXPECT_NEAR(back.normal.y(), 1, tol<T>());
  EXPECT_EQ(back.manifold.reference_edge, 1);
  EXPECT_EQ(back.manifold.point_count, 2);
}

// A box beyond the segment's end, apart: the exact distance from the end vertex, and nothing
// within the margin.
TYPED_TEST(SegmentPair, BoxBeyondAnEndIsApartByItsDistanceFromTheEnd) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(-2, 0, 0, 0);
  const Polygon<T> b = box<T>(T(0.3), T(-0.4), T(1.3), T(-0.2));
  ConvexQuery<T> q;
  q.level = Level::Contact;
  const Result<T> r = collide(s, b, q);
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, std::sqrt(0.3 * 0.3 + 0.2 * 0.2), tol<T>());
  EXPECT_NEAR(r.witness_a.x(), 0, tol<T>());
  EXPECT_NEAR(r.witness_b.x(), 0.3, tol<T>());
  EXPECT_NEAR(r.witness_b.y(), -0.2, tol<T>());
  EXPECT_EQ(r.feature_a.type, Feature::Type::Vertex);
  EXPECT_EQ(r.feature_a.index, 1);
  EXPECT_EQ(collide(s, b, manifold_query<T>(T(0.1))).manifold.point_count, 0);
}

// A one-sided segment (edge bit 1: its back internal) never pushes along its back normal: a
// triangle sunk from the front past its apex's reach is pushed out through the front (its own
// faces push no nearer down).
TYPED_TEST(SegmentPair, OneSidedMaskNeverPushesAlongTheBack) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(1, 0, -1, 0);  // front up
  const Vec2<T> v[3] = {{-1, T(-0.7)}, {1, T(-0.7)}, {0, T(0.3)}};
  const PolygonOrError<T> b = Polygon<T>::make(v, 3);
  ASSERT_TRUE(b.ok());
  ConvexQuery<T> q = manifold_query<T>();
  const Result<T> plain = collide(s, b.polygon, q);
  EXPECT_NEAR(plain.separation, -0.3, tol<T>());
  EXPECT_NEAR(plain.normal.y(), -1, tol<T>());
  EXPECT_EQ(plain.manifold.reference_edge, 1);
  q.masks_a.edges = 0b10;
  const Result<T> r = collide(s, b.polygon, q);
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.separation, -0.7, tol<T>());
  EXPECT_NEAR(r.normal.y(), 1, tol<T>());
  EXPECT_TRUE(r.manifold.reference_is_a);
  EXPECT_EQ(r.manifold.reference_edge, 0);
}

// A box tilted by 0.1 rad sliding over a closed end (the next segment continues flat): its face
// realised at the end vertex is refused, and it is pushed along the segment's front normal.
TYPED_TEST(SegmentPair, ClosedEndRefusesATiltedFaceAtIt) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(1, 0, 0, 0);  // front up; its end vertex 1 at the origin
  const T c = std::cos(T(0.1));
  const T sn = std::sin(T(0.1));
  // A unit box turned by 0.1 rad whose bottom face dips 0.01 below the segment's line at x = 0.
  std::vector<Vec2<T>> v = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (Vec2<T>& p : v) p = Vec2<T>(c * p.x() - sn * p.y(), sn * p.x() + c * p.y());
  const Vec2<T> lift(0, T(0.5) / c - T(0.01));
  for (Vec2<T>& p : v) p += lift;
  const PolygonOrError<T> b = Polygon<T>::make(v.data(), 4);
  ASSERT_TRUE(b.ok());
  ConvexQuery<T> q = manifold_query<T>();
  const Result<T> plain = collide(s, b.polygon, q);
  ASSERT_EQ(plain.status, Status::Penetrating);
  EXPECT_FALSE(plain.manifold.reference_is_a);  // the box's tilted bottom face, at the end vertex
  q.masks_a.edges = 0b10;
  q.masks_a.closed_vertices = 0b10;
  const Result<T> r = collide(s, b.polygon, q);
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_TRUE(r.manifold.reference_is_a);
  EXPECT_EQ(r.manifold.reference_edge, 0);
  EXPECT_NEAR(r.normal.x(), 0, tol<T>());
  EXPECT_NEAR(r.normal.y(), 1, tol<T>());
}

// A circle over the segment's middle is pushed along the side's normal; over an end, from the end
// vertex; on the segment's line beyond its end, apart by its distance from the end.
TYPED_TEST(SegmentPair, CircleTakesTheSideOrTheEndNearestIt) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(1, 0, -1, 0);  // front up
  ConvexQuery<T> q = manifold_query<T>();
  const Result<T> middle = collide(s, Circle<T>{{T(0.2), T(0.25)}, T(0.3)}, q);
  EXPECT_EQ(middle.status, Status::Penetrating);
  EXPECT_NEAR(middle.separation, -0.05, tol<T>());
  EXPECT_NEAR(middle.normal.y(), 1, tol<T>());
  EXPECT_EQ(middle.manifold.reference_edge, 0);
  ASSERT_EQ(middle.manifold.point_count, 1);
  const Result<T> below = collide(s, Circle<T>{{T(0.2), T(-0.25)}, T(0.3)}, q);
  EXPECT_NEAR(below.separation, -0.05, tol<T>());
  EXPECT_NEAR(below.normal.y(), -1, tol<T>());
  EXPECT_EQ(below.manifold.reference_edge, 1);
  const Result<T> end = collide(s, Circle<T>{{T(1.3), T(0.4)}, T(0.6)}, q);
  EXPECT_NEAR(end.separation, -0.1, tol<T>());
  EXPECT_NEAR(end.normal.x(), 0.6, tol<T>());
  EXPECT_NEAR(end.normal.y(), 0.8, tol<T>());
  ConvexQuery<T> depth;
  const Result<T> on_line = collide(s, Circle<T>{{T(1.5), T(0)}, T(0.25)}, depth);
  EXPECT_EQ(on_line.status, Status::Separated);
  EXPECT_NEAR(on_line.separation, 0.25, tol<T>());
  EXPECT_NEAR(on_line.normal.x(), 1, tol<T>());
  const Result<T> on_segment = collide(s, Circle<T>{{T(0.5), T(0)}, T(0.25)}, depth);
  EXPECT_EQ(on_segment.status, Status::Penetrating);
  EXPECT_NEAR(on_segment.separation, -0.25, tol<T>());
}

// A circle past a closed end is pushed along the segment's front normal, as by the segment the
// end continues flat into: no bump from the end vertex.
TYPED_TEST(SegmentPair, CirclePastAClosedEndTakesTheFrontNormal) {
  using T = TypeParam;
  const Segment<T> s = segment<T>(1, 0, 0, 0);  // front up, end vertex 1 at the origin
  ConvexQuery<T> q = manifold_query<T>();
  q.masks_a.edges = 0b10;
  q.masks_a.closed_vertices = 0b10;
  const Result<T> r = collide(s, Circle<T>{{T(-0.1), T(0.28)}, T(0.3)}, q);
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.separation, -0.02, tol<T>());
  EXPECT_NEAR(r.normal.x(), 0, tol<T>());
  EXPECT_NEAR(r.normal.y(), 1, tol<T>());
  ASSERT_EQ(r.manifold.point_count, 1);
}

}  // namespace
}  // namespace dyop
