// A static polygon's edge data is memoised between findings (the plug-in keeps the last one in
// the fixture's shape with a fingerprint of what it was found from): after every change near it,
// even one no contact sees, its masks are those a world built afresh with the same fixtures gives.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing::memoised {
namespace {

// m: the side of a tile.
constexpr float kTile = 0.5f;

// A static body of the level: where it is, and what it holds.
struct Piece {
  b2Vec2 position{0, 0};
  float angle = 0;
  b2BodyType type = b2_staticBody;
  bool enabled = true;
  bool sensor = false;
  // Its triangles (body frame), or, when `edge` is set, one two-sided edge from the first two
  // points of the first.
  std::vector<std::array<b2Vec2, 3>> triangles;
  bool edge = false;
};

// A tile of `kTile` at column i, row j, as a body of its own at its corner, split along its
// diagonal.
Piece tile(int i, int j) {
  Piece p;
  p.position = b2Vec2(i * kTile, j * kTile);
  p.triangles = {{b2Vec2(0, 0), b2Vec2(kTile, 0), b2Vec2(kTile, kTile)},
                 {b2Vec2(0, 0), b2Vec2(kTile, kTile), b2Vec2(0, kTile)}};
  return p;
}

// `body` placed and flagged as `p` says.
void apply(const Piece& p, b2Body& body) {
  if (body.GetPosition() != p.position || body.GetAngle() != p.angle) {
    body.SetTransform(p.position, p.angle);
  }
  for (b2Fixture* f = body.GetFixtureList(); f; f = f->GetNext()) f->SetSensor(p.sensor);
  body.SetType(p.type);
  body.SetEnabled(p.enabled);
}

// The level's pieces made in `world`, each body's fixtures in the pieces' order.
std::vector<b2Body*> build(World& world, const std::vector<Piece>& pieces) {
  std::vector<b2Body*> bodies;
  for (const Piece& p : pieces) {
    b2Body* body = add_body(world, b2_staticBody, p.position, p.angle);
    if (p.edge) {
      b2EdgeShape e;
      e.SetTwoSided(p.triangles[0][0], p.triangles[0][1]);
      body->CreateFixture(&e, 0);
    } else {
      for (const auto& t : p.triangles) add_triangle(body, t[0], t[1], t[2]);
    }
    apply(p, *body);
    bodies.push_back(body);
  }
  return bodies;
}

// Every polygon fixture's masks, body by body in the pieces' order.
std::vector<ShapeMasks> masks_of(const std::vector<b2Body*>& bodies) {
  std::vector<ShapeMasks> out;
  for (const b2Body* body : bodies) {
    for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) {
      if (f->GetType() == b2Shape::e_polygon) out.push_back(polygon_internal_edges(*f));
    }
  }
  return out;
}

// The masks the level's fixtures have in a world built afresh from `pieces`.
std::vector<ShapeMasks> afresh(const std::vector<Piece>& pieces) {
  World fresh;
  return masks_of(build(fresh, pieces));
}

// A change, made both to the live world's bodies and to the level's description.
struct Change {
  std::string name;
  std::function<void(std::vector<b2Body*>&, std::vector<Piece>&, World&)> make;
};

TEST(MemoisedEdgeData, EveryChangeNearAStaticTileGivesTheMasksOfAWorldBuiltAfresh) {
  std::vector<Piece> level;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) level.push_back(tile(i, j));
  }
  World world;
  std::vector<b2Body*> bodies = build(world, level);
  const int left = 1;   // the tile left of the centre (column 0, row 1)
  const int right = 7;  // the tile right of it (column 2, row 1)
  // A change of piece k's place or flags, made to its description and then to its body.
  const auto restyled = [](int k, std::function<void(Piece&)> edit) {
    return [k, edit](std::vector<b2Body*>& b, std::vector<Piece>& l, World&) {
      edit(l[k]);
      apply(l[k], *b[k]);
    };
  };
  const std::vector<Change> changes = {
      {"a neighbour moved away (no contact sees it)",
       restyled(left, [](Piece& p) { p.position.x += 0.3f; })},
      {"moved back", restyled(left, [](Piece& p) { p.position.x = 0; })},
      {"turned in place", restyled(right, [](Piece& p) { p.angle = 1e-3f; })},
      {"turned back", restyled(right, [](Piece& p) { p.angle = 0; })},
      {"a neighbour made a sensor", restyled(left, [](Piece& p) { p.sensor = true; })},
      {"and no sensor again", restyled(left, [](Piece& p) { p.sensor = false; })},
      {"a neighbour made dynamic", restyled(right, [](Piece& p) { p.type = b2_dynamicBody; })},
      {"and static again", restyled(right, [](Piece& p) { p.type = b2_staticBody; })},
      {"a neighbour disabled", restyled(left, [](Piece& p) { p.enabled = false; })},
      {"and enabled", restyled(left, [](Piece& p) { p.enabled = true; })},
      {"a neighbour destroyed and made again in its place",
       [&](auto& b, auto& l, World& w) {
         w->DestroyBody(b[right]);
         std::vector<b2Body*> made = build(w, {l[right]});
         b[right] = made[0];
       }},
      {"a neighbour destroyed",
       [&](auto& b, auto& l, World& w) {
         w->DestroyBody(b[right]);
         b.erase(b.begin() + right);
         l.erase(l.begin() + right);
       }},
      {"a refined tile in its place (T-junctions)",
       [&](auto& b, auto& l, World& w) {
         Piece refined;
         refined.position = b2Vec2(2 * kTile, kTile);
         const float h = kTile / 2;
         refined.triangles = {{b2Vec2(0, 0), b2Vec2(kTile, 0), b2Vec2(0, h)},
                              {b2Vec2(kTile, 0), b2Vec2(kTile, h), b2Vec2(0, h)},
                              {b2Vec2(0, h), b2Vec2(kTile, h), b2Vec2(0, kTile)},
                              {b2Vec2(kTile, h), b2Vec2(kTile, kTile), b2Vec2(0, kTile)}};
         l.push_back(refined);
         b.push_back(build(w, {refined})[0]);
       }},
      {"a two-sided edge from the top right corner (a junction)",
       [&](auto& b, auto& l, World& w) {
         Piece edge;
         edge.edge = true;
         edge.triangles = {{b2Vec2(3 * kTile, 3 * kTile), b2Vec2(4 * kTile, 4 * kTile), b2Vec2()}};
         l.push_back(edge);
         b.push_back(build(w, {edge})[0]);
       }},
  };
  ASSERT_EQ(masks_of(bodies), afresh(level)) << "as built";
  for (const Change& c : changes) {
    c.make(bodies, level, world);
    EXPECT_EQ(masks_of(bodies), afresh(level)) << "after: " << c.name;
  }
}

// A shape copied out of a fixture carries the memo along; made into a fixture of another world,
// among other neighbours, it still gets that world's masks.
TEST(MemoisedEdgeData, AShapeCopiedIntoAnotherWorldGetsThatWorldsMasks) {
  World first;
  const std::vector<b2Body*> row = build(first, {tile(0, 0), tile(1, 0), tile(2, 0)});
  masks_of(row);  // memoised
  const auto& shape = *static_cast<const b2PolygonShape*>(row[1]->GetFixtureList()->GetShape());
  World second;
  const std::vector<b2Body*> alone = build(second, {tile(0, 0), tile(1, 0)});
  b2Body* copy = add_body(second, b2_staticBody, b2Vec2(kTile, 0));
  copy->CreateFixture(&shape, 0);
  alone[1]->GetWorld()->DestroyBody(alone[1]);
  const ShapeMasks masks = polygon_internal_edges(*copy->GetFixtureList());
  World fresh;
  const std::vector<b2Body*> expected = build(fresh, {tile(0, 0)});
  b2Body* same = add_body(fresh, b2_staticBody, b2Vec2(kTile, 0));
  b2PolygonShape clean;
  clean.Set(shape.m_vertices, shape.m_count);
  same->CreateFixture(&clean, 0);
  EXPECT_EQ(masks, polygon_internal_edges(*same->GetFixtureList()));
}

}  // namespace
}  // namespace dyop::box2d::testing::memoised
