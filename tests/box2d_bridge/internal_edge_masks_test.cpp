// The internal-edge masks of triangle fixtures (`dyop::box2d::triangle_internal_edges`) in worlds
// built by hand: edges shared by static bodies are internal, in any frames, within the placement
// tolerance and not beyond; dynamic and kinematic bodies keep their edges to themselves, sensors
// share none; an edge covered wholly by the edges of a refined neighbour (T-junctions) is internal
// and the junction's vertex flat; an edge covered in part stays an outline edge; tiles in bodies
// of their own get the masks of the same tiles in one body.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// m: world points of a fixture are matched to the test's points within this (well above the
// rounding of placing turned frames, well below any feature here).
constexpr float kSamePoint = 1e-4f;

const b2PolygonShape& polygon(const b2Fixture& f) {
  return *static_cast<const b2PolygonShape*>(f.GetShape());
}

b2Vec2 world_vertex(const b2Fixture& f, int i) {
  return b2Mul(f.GetBody()->GetTransform(), polygon(f).m_vertices[i]);
}

bool same(const b2Vec2& a, const b2Vec2& b) { return (a - b).Length() <= kSamePoint; }

// True when `f` has the edge p–q (world, either way) and it is internal; fails if it has no such
// edge.
bool internal(const b2Fixture& f, const b2Vec2& p, const b2Vec2& q) {
  const InternalEdges m = triangle_internal_edges(f);
  for (int i = 0; i < 3; ++i) {
    const b2Vec2 a = world_vertex(f, i);
    const b2Vec2 b = world_vertex(f, (i + 1) % 3);
    if ((same(a, p) && same(b, q)) || (same(a, q) && same(b, p))) return (m.edges >> i) & 1;
  }
  ADD_FAILURE() << "no edge (" << p.x << ", " << p.y << ")-(" << q.x << ", " << q.y << ")";
  return false;
}

// True when `f` has the vertex p (world) and it is closed; fails if it has no such vertex.
bool closed(const b2Fixture& f, const b2Vec2& p) {
  const InternalEdges m = triangle_internal_edges(f);
  for (int i = 0; i < 3; ++i) {
    if (same(world_vertex(f, i), p)) return (m.closed_vertices >> i) & 1;
  }
  ADD_FAILURE() << "no vertex (" << p.x << ", " << p.y << ")";
  return false;
}

// A body of `type` at `position` turned by `angle` holding the triangle with world vertices
// p0, p1, p2 (placed in its frame by its transform).
b2Fixture* placed_triangle(World& world, b2BodyType type, const b2Vec2& p0, const b2Vec2& p1,
                           const b2Vec2& p2, const b2Vec2& position = b2Vec2(0, 0),
                           float angle = 0) {
  b2Body* body = add_body(world, type, position, angle);
  const b2Transform& xf = body->GetTransform();
  return add_triangle(body, b2MulT(xf, p0), b2MulT(xf, p1), b2MulT(xf, p2));
}

TEST(EdgeGroupMasks, EdgeSharedByTwoStaticBodiesIsInternal) {
  World world;
  b2Fixture* a = placed_triangle(world, b2_staticBody, {0, 0}, {1, 0}, {0, 1});
  b2Fixture* b = placed_triangle(world, b2_staticBody, {1, 0}, {1, 1}, {0, 1});
  EXPECT_TRUE(internal(*a, {1, 0}, {0, 1}));
  EXPECT_TRUE(internal(*b, {1, 0}, {0, 1}));
  EXPECT_FALSE(internal(*a, {0, 0}, {1, 0}));
  EXPECT_FALSE(internal(*b, {1, 0}, {1, 1}));
}

// Static bodies with other origins and angles, near the origin and 1 km from it: their shared
// edge meets only within the rounding of the two placements, and is internal.
TEST(EdgeGroupMasks, EdgeSharedByStaticBodiesInTheirOwnFramesIsInternal) {
  for (const float far : {0.0f, 1000.0f}) {
    SCOPED_TRACE(far);
    World world;
    const b2Vec2 o(far, -far);
    b2Fixture* a = placed_triangle(world, b2_staticBody, o + b2Vec2(0, 0), o + b2Vec2(1, 0),
                                   o + b2Vec2(0, 1), o + b2Vec2(3.7f, -2.1f), 1.1f);
    b2Fixture* b = placed_triangle(world, b2_staticBody, o + b2Vec2(1, 0), o + b2Vec2(1, 1),
                                   o + b2Vec2(0, 1), o + b2Vec2(-5.0f, 8.0f), -2.3f);
    EXPECT_TRUE(internal(*a, o + b2Vec2(1, 0), o + b2Vec2(0, 1)));
    EXPECT_TRUE(internal(*b, o + b2Vec2(1, 0), o + b2Vec2(0, 1)));
  }
}

// A neighbour whose edge is off by 0.1 mm (50 times the tolerance at this magnitude): a step, not
// a shared edge. Off by 0.1 µm (rounding): shared.
TEST(EdgeGroupMasks, EdgesApartBeyondThePlacementToleranceStayOutlineEdges) {
  for (const float offset : {1e-4f, 1e-7f}) {
    SCOPED_TRACE(offset);
    World world;
    b2Fixture* a = placed_triangle(world, b2_staticBody, {0, 0}, {1, 0}, {1, 1});
    placed_triangle(world, b2_staticBody, {1 + offset, 0}, {2, 0}, {1 + offset, 1});
    EXPECT_EQ(internal(*a, {1, 0}, {1, 1}), offset < 1e-6f);
  }
}

// The same two triangles in two dynamic, two kinematic, or a static and a dynamic body: they move
// apart, so the edge stays an outline edge of each.
TEST(EdgeGroupMasks, EdgeSharedByMovingBodiesStaysAnOutlineEdge) {
  const b2BodyType pairs[][2] = {{b2_dynamicBody, b2_dynamicBody},
                                 {b2_kinematicBody, b2_kinematicBody},
                                 {b2_staticBody, b2_dynamicBody},
                                 {b2_staticBody, b2_kinematicBody}};
  for (const auto& types : pairs) {
    SCOPED_TRACE(std::to_string(types[0]) + " " + std::to_string(types[1]));
    World world;
    world->SetGravity(b2Vec2(0, 0));
    b2Fixture* a = placed_triangle(world, types[0], {0, 0}, {1, 0}, {0, 1});
    b2Fixture* b = placed_triangle(world, types[1], {1, 0}, {1, 1}, {0, 1});
    EXPECT_EQ(triangle_internal_edges(*a), InternalEdges{});
    EXPECT_EQ(triangle_internal_edges(*b), InternalEdges{});
  }
}

// A sensor triangle on the other side of an edge: nothing collides with it, so the edge stays the
// outline.
TEST(EdgeGroupMasks, SensorsShareNoEdges) {
  World world;
  b2Fixture* a = placed_triangle(world, b2_staticBody, {0, 0}, {1, 0}, {0, 1});
  b2Fixture* b = placed_triangle(world, b2_staticBody, {1, 0}, {1, 1}, {0, 1});
  b->SetSensor(true);
  EXPECT_FALSE(internal(*a, {1, 0}, {0, 1}));
}

// Cell A = [0, 1]² split along a diagonal, cell B = [1, 2] × [0, 1] split in five around its
// centre with its left side split at (1, 0.5): A's right side is covered by B's two left edges,
// each of which A's right side covers. Both sides are internal, in one static body or two; the top
// junction (1, 1) is flat and closed on both sides, and (1, 0.5), inside A's side, is inside the
// ground: closed.
TEST(EdgeGroupMasks, EdgesMeetingAtATJunctionAreInternal) {
  for (const bool one_body : {true, false}) {
    SCOPED_TRACE(one_body ? "one body" : "a body per cell");
    World world;
    b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
    b2Fixture* a_upper = add_triangle(ground, {0, 1}, {0, 0}, {1, 1});
    b2Fixture* a_lower = add_triangle(ground, {1, 1}, {0, 0}, {1, 0});
    b2Body* cell_b = one_body ? ground : add_body(world, b2_staticBody, b2Vec2(1, 0), 0.3f);
    const b2Transform& xf = cell_b->GetTransform();
    const auto add_b = [&](b2Vec2 p, b2Vec2 q, b2Vec2 r) {
      return add_triangle(cell_b, b2MulT(xf, p), b2MulT(xf, q), b2MulT(xf, r));
    };
    const b2Vec2 mid(1, 0.5f), centre(1.5f, 0.5f);
    b2Fixture* b_upper_left = add_b({1, 1}, mid, centre);
    b2Fixture* b_lower_left = add_b(mid, {1, 0}, centre);
    add_b({1, 0}, {2, 0}, centre);
    add_b({2, 0}, {2, 1}, centre);
    b2Fixture* b_top = add_b({2, 1}, {1, 1}, centre);

    EXPECT_TRUE(internal(*a_lower, {1, 0}, {1, 1}));
    EXPECT_TRUE(internal(*b_upper_left, {1, 1}, mid));
    EXPECT_TRUE(internal(*b_lower_left, mid, {1, 0}));
    EXPECT_TRUE(closed(*b_upper_left, mid));
    EXPECT_TRUE(closed(*b_lower_left, mid));
    EXPECT_TRUE(closed(*a_upper, {1, 1}));  // the top's junction: flat
    EXPECT_TRUE(closed(*b_top, {1, 1}));
    EXPECT_FALSE(internal(*a_upper, {0, 1}, {1, 1}));  // the top stays the outline
    EXPECT_FALSE(internal(*b_top, {2, 1}, {1, 1}));
  }
}

// A's right side (x = 1, y in [0, 1]) has a neighbour along its lower 0.6 m only: it stays an
// outline edge (the step above the neighbour is real); the neighbour's side, covered wholly by A's,
// is internal.
TEST(EdgeGroupMasks, EdgeCoveredInPartStaysAnOutlineEdge) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  add_triangle(ground, {0, 1}, {0, 0}, {1, 1});
  b2Fixture* a = add_triangle(ground, {1, 1}, {0, 0}, {1, 0});
  b2Fixture* b = add_triangle(ground, {1, 0}, {2, 0}, {1, 0.6f});
  EXPECT_FALSE(internal(*a, {1, 0}, {1, 1}));
  EXPECT_TRUE(internal(*b, {1, 0}, {1, 0.6f}));
}

// A U body (a bar with two posts, one body): each post's bottom lies inside the bar's top edge
// (T-junctions): internal; the bar's top, covered in part, stays the outline between the posts.
TEST(EdgeGroupMasks, PostsOfAUBodyStandOnItsBarWithInternalEdges) {
  World world;
  b2Body* u = add_body(world, b2_dynamicBody, b2Vec2(0, 0));
  b2Fixture* bar = add_triangle(u, {0, 0}, {3, 1}, {0, 1});
  add_triangle(u, {0, 0}, {3, 0}, {3, 1});
  b2Fixture* left_post = add_triangle(u, {0, 1}, {1, 1}, {1, 2});
  add_triangle(u, {0, 1}, {1, 2}, {0, 2});
  b2Fixture* right_post = add_triangle(u, {2, 1}, {3, 1}, {3, 2});
  add_triangle(u, {2, 1}, {3, 2}, {2, 2});
  EXPECT_TRUE(internal(*left_post, {0, 1}, {1, 1}));
  EXPECT_TRUE(internal(*right_post, {2, 1}, {3, 1}));
  EXPECT_FALSE(internal(*bar, {3, 1}, {0, 1}));
}

// A ground of 0.5 m tiles, 8 columns and 2 rows, each tile split along its diagonal: in one
// static body, and one static body per tile turned by quarter turns about its centre. Every edge
// and vertex of every triangle has the same mask either way.
TEST(EdgeGroupMasks, TilesInBodiesOfTheirOwnHaveTheMasksOfOneBody) {
  constexpr float tile = 0.5f;
  World one_world;
  World tiles_world;
  b2Body* one = add_body(one_world, b2_staticBody, b2Vec2(0, 0));
  std::vector<std::pair<b2Fixture*, b2Fixture*>> pairs;
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < 8; ++i) {
      const b2Vec2 bl(i * tile, -(row + 1) * tile), br(bl.x + tile, bl.y),
          tr(bl.x + tile, bl.y + tile), tl(bl.x, bl.y + tile);
      const b2Vec2 centre = 0.5f * (bl + tr);
      const float angle = 1.5707963f * ((i + row) % 4);
      for (const auto& t : {std::array<b2Vec2, 3>{tl, bl, tr}, std::array<b2Vec2, 3>{tr, bl, br}}) {
        b2Fixture* in_one = add_triangle(one, t[0], t[1], t[2]);
        b2Body* body = add_body(tiles_world, b2_staticBody, centre, angle);
        const b2Transform& xf = body->GetTransform();
        pairs.emplace_back(
            in_one, add_triangle(body, b2MulT(xf, t[0]), b2MulT(xf, t[1]), b2MulT(xf, t[2])));
      }
    }
  }
  int internal_edges = 0;
  for (const auto& [in_one, alone] : pairs) {
    for (int i = 0; i < 3; ++i) {
      const b2Vec2 p = world_vertex(*in_one, i);
      const b2Vec2 q = world_vertex(*in_one, (i + 1) % 3);
      const bool expected = internal(*in_one, p, q);
      internal_edges += expected;
      EXPECT_EQ(internal(*alone, p, q), expected) << p.x << ", " << p.y;
      EXPECT_EQ(closed(*alone, p), closed(*in_one, p)) << p.x << ", " << p.y;
    }
  }
  EXPECT_GT(internal_edges, 40);
}

}  // namespace
}  // namespace dyop::box2d::testing
