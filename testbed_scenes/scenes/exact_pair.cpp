#include "scenes/exact_pair.hpp"

#include <box2d/box2d.h>

namespace dyop::scenes {
namespace {

const b2PolygonShape* triangle(const b2Fixture* f) {
  if (f->GetType() != b2Shape::e_polygon) return nullptr;
  const auto* p = static_cast<const b2PolygonShape*>(f->GetShape());
  return p->m_count == 3 ? p : nullptr;
}

// B's body frame in A's, computed in double from the bodies' float transforms.
FrameBInA frame_of(const b2Contact& contact) {
  const b2Transform& xa = contact.GetFixtureA()->GetBody()->GetTransform();
  const b2Transform& xb = contact.GetFixtureB()->GetBody()->GetTransform();
  const double ca = xa.q.c, sa = xa.q.s, cb = xb.q.c, sb = xb.q.s;
  const double dx = double(xb.p.x) - double(xa.p.x), dy = double(xb.p.y) - double(xa.p.y);
  return {ca * cb + sa * sb, ca * sb - sa * cb,
          Vec2<double>(ca * dx + sa * dy, -sa * dx + ca * dy)};
}

// A polygon shape's vertices placed by `place` (a body frame into A's), as a `Polygon<double>`.
template <class Place>
std::optional<Polygon<double>> polygon_of(const b2PolygonShape& shape, const Place& place) {
  Vec2<double> v[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) v[i] = place(shape.m_vertices[i]);
  const PolygonOrError<double> p = Polygon<double>::make(v, shape.m_count);
  if (!p.ok()) return std::nullopt;
  return p.polygon;
}

}  // namespace

Result<double> ExactConvexPair::exact(Level level) const {
  ConvexQuery<double> q;
  q.level = level;
  if (segment) return b ? collide(*segment, *b, q) : collide(*segment, circle, q);
  return b ? collide(*a, *b, q) : collide(*a, circle, q);
}

double ExactConvexPair::overlap_along(const Vec2<double>& u) const {
  const auto vertex = [&](int i) { return segment ? segment->vertex(i) : a->vertex(i); };
  const int count = segment ? 2 : a->count();
  double a_max = vertex(0).dot(u);
  for (int i = 1; i < count; ++i) a_max = std::max(a_max, vertex(i).dot(u));
  if (!b) return a_max - (circle.center.dot(u) - circle.radius);
  double b_min = b->vertex(0).dot(u);
  for (int i = 1; i < b->count(); ++i) b_min = std::min(b_min, b->vertex(i).dot(u));
  return a_max - b_min;
}

std::optional<ExactConvexPair> exact_convex_pair(const b2Contact& contact) {
  const b2Fixture* fa = contact.GetFixtureA();
  const b2Fixture* fb = contact.GetFixtureB();
  ExactConvexPair out;
  out.b_in_a = frame_of(contact);
  const FrameBInA& frame = out.b_in_a;
  const b2Shape* shape_a = fa->GetShape();
  if (shape_a->m_type == b2Shape::e_edge || shape_a->m_type == b2Shape::e_chain) {
    b2EdgeShape edge;
    if (shape_a->m_type == b2Shape::e_chain) {
      static_cast<const b2ChainShape*>(shape_a)->GetChildEdge(&edge, contact.GetChildIndexA());
    } else {
      edge = *static_cast<const b2EdgeShape*>(shape_a);
    }
    const SegmentOrError<double> s = Segment<double>::make({edge.m_vertex1.x, edge.m_vertex1.y},
                                                           {edge.m_vertex2.x, edge.m_vertex2.y});
    if (!s.ok()) return std::nullopt;
    out.segment = s.segment;
  } else if (shape_a->m_type == b2Shape::e_polygon) {
    out.a = polygon_of(*static_cast<const b2PolygonShape*>(shape_a),
                       [](const b2Vec2& p) { return Vec2<double>(p.x, p.y); });
    if (!out.a) return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (fb->GetType() == b2Shape::e_circle) {
    const auto& c = *static_cast<const b2CircleShape*>(fb->GetShape());
    out.circle = {frame.point(c.m_p), c.m_radius};
    return out;
  }
  if (fb->GetType() != b2Shape::e_polygon) return std::nullopt;
  const auto& b = *static_cast<const b2PolygonShape*>(fb->GetShape());
  if (out.a && out.a->count() == 3 && b.m_count == 3) return std::nullopt;
  out.b = polygon_of(b, [&](const b2Vec2& p) { return frame.point(p); });
  if (!out.b) return std::nullopt;
  return out;
}

Vec2<double> FrameBInA::direction(const b2Vec2& d) const {
  const double x = d.x, y = d.y;
  return {c * x - s * y, s * x + c * y};
}

std::optional<ExactPair> exact_pair(const b2Contact& contact) {
  const b2PolygonShape* a = triangle(contact.GetFixtureA());
  const b2PolygonShape* b = triangle(contact.GetFixtureB());
  if (!a || !b) return std::nullopt;
  const FrameBInA frame = frame_of(contact);
  Vec2<double> va[3], vb[3];
  for (int i = 0; i < 3; ++i) {
    va[i] = Vec2<double>(a->m_vertices[i].x, a->m_vertices[i].y);
    vb[i] = frame.point(b->m_vertices[i]);
  }
  const TriangleOrError<double> ta = Triangle<double>::make(va[0], va[1], va[2]);
  const TriangleOrError<double> tb = Triangle<double>::make(vb[0], vb[1], vb[2]);
  if (!ta.ok() || !tb.ok()) return std::nullopt;
  return ExactPair{frame, ta.triangle, tb.triangle};
}

}  // namespace dyop::scenes
