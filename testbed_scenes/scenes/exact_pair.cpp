#include "scenes/exact_pair.hpp"

#include <box2d/box2d.h>

namespace dyop::scenes {
namespace {

const b2PolygonShape* triangle(const b2Fixture* f) {
  if (f->GetType() != b2Shape::e_polygon) return nullptr;
  const auto* p = static_cast<const b2PolygonShape*>(f->GetShape());
  return p->m_count == 3 ? p : nullptr;
}

}  // namespace

Vec2<double> FrameBInA::direction(const b2Vec2& d) const {
  const double x = d.x, y = d.y;
  return {c * x - s * y, s * x + c * y};
}

std::optional<ExactPair> exact_pair(const b2Contact& contact) {
  const b2Fixture* fa = contact.GetFixtureA();
  const b2Fixture* fb = contact.GetFixtureB();
  const b2PolygonShape* a = triangle(fa);
  const b2PolygonShape* b = triangle(fb);
  if (!a || !b) return std::nullopt;
  const b2Transform& xa = fa->GetBody()->GetTransform();
  const b2Transform& xb = fb->GetBody()->GetTransform();
  const double ca = xa.q.c, sa = xa.q.s, cb = xb.q.c, sb = xb.q.s;
  const double dx = double(xb.p.x) - double(xa.p.x), dy = double(xb.p.y) - double(xa.p.y);
  const FrameBInA frame{ca * cb + sa * sb, ca * sb - sa * cb,
                        Vec2<double>(ca * dx + sa * dy, -sa * dx + ca * dy)};
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
