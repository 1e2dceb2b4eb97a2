// Debug drawing of the internal-edge rule's masks and of the contacts (dyop/box2d_draw.hpp).
#include "dyop/box2d_draw.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>

#include <optional>

#include "dyop/box2d_internal_edges.hpp"

namespace dyop::box2d {
namespace {

bool has_bit(std::uint8_t mask, int i) { return ((mask >> i) & 1u) != 0; }

void draw_polygon(const b2Fixture& fixture, const b2PolygonShape& shape, const b2Transform& xf,
                  b2Draw& draw, const DrawStyle& style) {
  const std::optional<ShapeMasks> fixed = fixed_polygon_edges(fixture);
  const ShapeMasks masks = fixed ? *fixed : polygon_internal_edges(fixture);
  const int n = shape.m_count;
  for (int i = 0; i < n; ++i) {
    const b2Vec2 p = b2Mul(xf, shape.m_vertices[i]);
    const b2Vec2 q = b2Mul(xf, shape.m_vertices[i + 1 < n ? i + 1 : 0]);
    draw.DrawSegment(p, q, has_bit(masks.edges, i) ? style.internal : style.outline);
  }
  for (int i = 0; i < n; ++i) {
    if (has_bit(masks.closed_vertices, i)) {
      draw.DrawPoint(b2Mul(xf, shape.m_vertices[i]), style.point_size, style.closed);
    }
  }
}

// One edge, or a chain's child edge: its segment, and its ends closed (from the front for a
// one-sided edge, from either side for a two-sided one).
void draw_edge(const b2Vec2& v1, const b2Vec2& v2, std::uint8_t closed, const b2Transform& xf,
               b2Draw& draw, const DrawStyle& style) {
  const b2Vec2 p = b2Mul(xf, v1);
  const b2Vec2 q = b2Mul(xf, v2);
  draw.DrawSegment(p, q, style.outline);
  if (has_bit(closed, 0)) draw.DrawPoint(p, style.point_size, style.closed);
  if (has_bit(closed, 1)) draw.DrawPoint(q, style.point_size, style.closed);
}

void draw_fixture(const b2Fixture& fixture, const b2Transform& xf, b2Draw& draw,
                  const DrawStyle& style) {
  const b2Shape* shape = fixture.GetShape();
  switch (shape->m_type) {
    case b2Shape::e_polygon:
      draw_polygon(fixture, *static_cast<const b2PolygonShape*>(shape), xf, draw, style);
      break;
    case b2Shape::e_edge: {
      const auto& edge = *static_cast<const b2EdgeShape*>(shape);
      std::uint8_t closed = edge_internal_edges(fixture).closed_vertices;
      if (!edge.m_oneSided) closed |= edge_internal_edges(fixture, 0, true).closed_vertices;
      draw_edge(edge.m_vertex1, edge.m_vertex2, closed, xf, draw, style);
      break;
    }
    case b2Shape::e_chain: {
      const auto& chain = *static_cast<const b2ChainShape*>(shape);
      for (int child = 0; child < chain.GetChildCount(); ++child) {
        b2EdgeShape edge;
        chain.GetChildEdge(&edge, child);
        draw_edge(edge.m_vertex1, edge.m_vertex2,
                  edge_internal_edges(fixture, child).closed_vertices, xf, draw, style);
      }
      break;
    }
    default:  // circles make no edge
      break;
  }
}

}  // namespace

void draw_internal_edges(const b2World& world, b2Draw& draw, const DrawStyle& style) {
  for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext()) {
    const b2Transform& xf = body->GetTransform();
    for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      if (!f->IsSensor()) draw_fixture(*f, xf, draw, style);
    }
  }
}

void draw_contacts(const b2World& world, b2Draw& draw, const DrawStyle& style) {
  for (const b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
    if (!c->IsTouching()) continue;
    b2WorldManifold wm;
    c->GetWorldManifold(&wm);
    for (int i = 0; i < c->GetManifold()->pointCount; ++i) {
      draw.DrawPoint(wm.points[i], style.point_size, style.point);
      draw.DrawSegment(wm.points[i], wm.points[i] + style.normal_length * wm.normal, style.normal);
    }
  }
}

}  // namespace dyop::box2d
