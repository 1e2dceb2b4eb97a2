// Fixed edge data (`fix_internal_edges`, `refresh_internal_edges`, `add_triangles`): a triangle's
// masks computed once and kept in its fixture. They equal the masks the world's contacts find,
// leave the world bit-identical to those, follow a fixed ground changed by hand once it is
// refreshed where it changed, belong to their fixture alone, and die with it in any order. A mesh
// the builder refuses names the triangle and creates nothing.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_mesh.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

constexpr float kTile = 0.5f;

// The corners of a row of `columns` square tiles of side kTile whose tops are y = 0, from x = 0,
// and the indices of their triangles (each tile split along its diagonal).
struct TileRow {
  std::vector<b2Vec2> vertices;
  std::vector<int> indices;
};

TileRow tile_row(int columns) {
  TileRow row;
  for (int i = 0; i <= columns; ++i) {
    row.vertices.emplace_back(i * kTile, 0.0f);    // top: 2i
    row.vertices.emplace_back(i * kTile, -kTile);  // bottom: 2i + 1
  }
  for (int i = 0; i < columns; ++i) {
    const int tl = 2 * i, bl = 2 * i + 1, tr = 2 * i + 2, br = 2 * i + 3;
    row.indices.insert(row.indices.end(), {tl, bl, tr, tr, bl, br});
  }
  return row;
}

// A static body per tile (as tile maps lay them), each tile's two triangles added by the builder.
std::vector<b2Body*> add_tiles(World& world, int columns) {
  std::vector<b2Body*> tiles;
  const TileRow one = tile_row(1);
  for (int i = 0; i < columns; ++i) {
    b2Body* tile = add_body(world, b2_staticBody, b2Vec2(i * kTile, 0.0f));
    b2FixtureDef def;
    def.friction = 0;
    const MeshResult r = add_triangles(*tile, one.vertices.data(), 4, one.indices.data(), 6, def);
    EXPECT_TRUE(r.ok()) << r.message;
    tiles.push_back(tile);
  }
  return tiles;
}

// Every triangle fixture of `world` holds fixed edge data equal to the masks found now.
void expect_fixed_equals_found(b2World& world) {
  int triangles = 0;
  for (b2Body* b = world.GetBodyList(); b; b = b->GetNext()) {
    for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext()) {
      const std::optional<InternalEdges> fixed = fixed_internal_edges(*f);
      ASSERT_TRUE(fixed.has_value());
      EXPECT_EQ(*fixed, triangle_internal_edges(*f));
      ++triangles;
    }
  }
  EXPECT_GT(triangles, 0);
}

TEST(FixedEdgeData, EqualsTheMasksFoundForTilesAsBodiesAndForOneBody) {
  World world;
  add_tiles(world, 6);
  b2Body* one = add_body(world, b2_staticBody, b2Vec2(0.0f, -5.0f));
  const TileRow row = tile_row(6);
  const MeshResult r =
      add_triangles(*one, row.vertices.data(), static_cast<int>(row.vertices.size()),
                    row.indices.data(), static_cast<int>(row.indices.size()));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.fixtures.size(), 12u);
  expect_fixed_equals_found(world.get());
  // A tile in the middle has internal edges: the shared sides and its diagonal.
  EXPECT_NE(fixed_internal_edges(*r.fixtures[4])->edges, 0);
}

TEST(FixedEdgeData, FixingAWorldBuiltByHandGivesTheMasksFound) {
  World world;
  b2Body* ground = add_triangle_ground(world, 3.0f);
  b2Body* box = add_split_box(world, b2Vec2(0.0f, 2.0f), 0.5f);
  fix_internal_edges(world.get());
  expect_fixed_equals_found(world.get());
  EXPECT_TRUE(fixed_internal_edges(*ground->GetFixtureList()).has_value());
  EXPECT_TRUE(fixed_internal_edges(*box->GetFixtureList()).has_value());
}

// One frictionless box launched along a ground of tiles as bodies, with the masks found by the
// contacts or fixed beforehand: the final state hash.
std::uint64_t slide_over_tiles(bool fixed) {
  World world;
  std::vector<b2Body*> tiles;
  const TileRow one = tile_row(1);
  for (int i = 0; i < 40; ++i) {
    b2Body* tile = add_body(world, b2_staticBody, b2Vec2(i * kTile, 0.0f));
    for (int t = 0; t < 2; ++t) {
      const int* k = one.indices.data() + 3 * t;
      add_triangle(tile, one.vertices[k[0]], one.vertices[k[1]], one.vertices[k[2]], kIce);
    }
  }
  b2Body* box = add_split_box(world, b2Vec2(0.6f, 0.25f), 0.25f, kIce);
  box->SetLinearVelocity(b2Vec2(6.0f, 0.0f));
  if (fixed) fix_internal_edges(world.get());
  for (int i = 0; i < 180; ++i) world.step();
  EXPECT_LT(std::abs(box->GetLinearVelocity().y), 0.05f) << (fixed ? "fixed" : "found");
  return worlds::state_hash(world);
}

TEST(FixedEdgeData, LeavesTheWorldBitIdenticalToMasksFoundByContacts) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  EXPECT_EQ(slide_over_tiles(true), slide_over_tiles(false));
  ASSERT_TRUE(uninstall().ok());
}

TEST(FixedEdgeData, ARefreshWhereATileWentMakesItsNeighboursEdgeAnOutlineEdge) {
  World world;
  const std::vector<b2Body*> tiles = add_tiles(world, 3);
  b2Fixture* left_of_gap =
      tiles[0]->GetFixtureList();  // the tile's second triangle: its right side
  const InternalEdges before = *fixed_internal_edges(*left_of_gap);
  b2AABB where;
  where.lowerBound = tiles[1]->GetPosition() + b2Vec2(0.0f, -kTile);
  where.upperBound = tiles[1]->GetPosition() + b2Vec2(kTile, 0.0f);
  world->DestroyBody(tiles[1]);
  // Fixed edge data changes only when refreshed: until then it is the ground as built.
  EXPECT_EQ(*fixed_internal_edges(*left_of_gap), before);
  EXPECT_FALSE(triangle_internal_edges(*left_of_gap) == before);
  EXPECT_GT(refresh_internal_edges(world.get(), where), 0);
  expect_fixed_equals_found(world.get());
}

// A box resting in the middle of a fixed row of tiles as bodies; the tile under it is destroyed
// and the ground refreshed where it was: the box falls and rests on nothing it should not.
TEST(FixedEdgeData, BoxFallsThroughATileDestroyedUnderItOnceRefreshed) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  World world;
  const std::vector<b2Body*> tiles = add_tiles(world, 5);
  b2Body* floor = add_body(world, b2_staticBody, b2Vec2(0.0f, -3.0f));
  const TileRow row = tile_row(5);
  ASSERT_TRUE(add_triangles(*floor, row.vertices.data(), static_cast<int>(row.vertices.size()),
                            row.indices.data(), static_cast<int>(row.indices.size()))
                  .ok());
  b2Body* box = add_split_box(world, b2Vec2(2 * kTile + 0.25f, 0.2f), 0.2f, kIce);
  fix_internal_edges(*box);
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_NEAR(box->GetPosition().y, 0.2f, 0.02f);
  b2AABB where;
  where.lowerBound = tiles[2]->GetPosition() + b2Vec2(0.0f, -kTile);
  where.upperBound = tiles[2]->GetPosition() + b2Vec2(kTile, 0.0f);
  world->DestroyBody(tiles[2]);
  refresh_internal_edges(world.get(), where);
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_NEAR(box->GetPosition().y, -3.0f + 0.2f, 0.02f);  // on the floor below
  EXPECT_LT(std::abs(box->GetLinearVelocity().y), 0.01f);
  ASSERT_TRUE(uninstall().ok());
}

TEST(FixedEdgeData, ACopiedShapeCarriesNoEdgeDataIntoAnotherFixture) {
  World world;
  const std::vector<b2Body*> tiles = add_tiles(world, 2);
  b2Fixture* fixed = tiles[0]->GetFixtureList();
  ASSERT_TRUE(fixed_internal_edges(*fixed).has_value());
  b2Body* other = add_body(world, b2_staticBody, b2Vec2(10.0f, 0.0f));
  b2Fixture* copy = other->CreateFixture(fixed->GetShape(), 1.0f);
  EXPECT_FALSE(fixed_internal_edges(*copy).has_value());
  b2PolygonShape box;
  box.SetAsBox(0.5f, 0.5f);
  EXPECT_FALSE(fixed_internal_edges(*other->CreateFixture(&box, 1.0f)).has_value());
}

// Box2D's allocators hand a destroyed fixture's memory to the next fixture made: a shape copied out
// of a fixed fixture and given other vertices (`Set`) carries the record into a fixture at the
// same address on the same body, and it must not read as that fixture's edge data.
TEST(FixedEdgeData, ACopyRecreatedInTheFixturesPlaceWithOtherVerticesHasNoEdgeData) {
  World world;
  const std::vector<b2Body*> tiles = add_tiles(world, 2);
  b2Fixture* fixed = tiles[0]->GetFixtureList();
  ASSERT_TRUE(fixed_internal_edges(*fixed).has_value());
  b2PolygonShape copy = *static_cast<const b2PolygonShape*>(fixed->GetShape());
  const b2Fixture* const address = fixed;
  tiles[0]->DestroyFixture(fixed);
  const b2Vec2 elsewhere[3] = {{0.0f, 2.0f}, {1.0f, 2.0f}, {0.0f, 3.0f}};
  copy.Set(elsewhere, 3);
  b2Fixture* recreated = tiles[0]->CreateFixture(&copy, 0.0f);
  ASSERT_EQ(recreated, address) << "the allocator did not reuse the address: nothing was tested";
  EXPECT_FALSE(fixed_internal_edges(*recreated).has_value());
}

// Fixed grounds and bodies destroyed in every order, with steps between, and the world deleted
// with bodies still in it: nothing is read after it is freed (this test's value is under ASan).
TEST(FixedEdgeData, DestroyingFixedTrianglesInAnyOrderLeavesNothingDangling) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (int order = 0; order < 3; ++order) {
    auto world = std::make_unique<World>();
    std::vector<b2Body*> tiles = add_tiles(*world, 6);
    b2Body* box = add_split_box(*world, b2Vec2(1.5f, 0.3f), 0.25f, kIce);
    box->SetLinearVelocity(b2Vec2(2.0f, 0.0f));
    fix_internal_edges(*box);
    for (int i = 0; i < 20; ++i) world->step();
    if (order == 0) {
      (*world)->DestroyBody(tiles[3]);
      for (int i = 0; i < 10; ++i) world->step();
      (*world)->DestroyBody(box);
    } else if (order == 1) {
      (*world)->DestroyBody(box);
      tiles[2]->DestroyFixture(tiles[2]->GetFixtureList());
      b2AABB all;
      all.lowerBound.Set(-1.0f, -1.0f);
      all.upperBound.Set(4.0f, 1.0f);
      refresh_internal_edges(world->get(), all);
    }
    for (int i = 0; i < 10; ++i) world->step();
    world.reset();
  }
  ASSERT_TRUE(uninstall().ok());
}

TEST(MeshBuilder, ARefusedMeshNamesTheTriangleAndCreatesNothing) {
  World world;
  b2Body* body = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const b2Vec2 vertices[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {nan, 0}, {2, 0}};
  struct Bad {
    std::vector<int> indices;
    MeshError error;
    int triangle;
  };
  const Bad cases[] = {
      {{0, 1, 2, 0, 2, 0}, MeshError::Triangle, 1},         // a repeated vertex
      {{0, 1, 2, 0, 1, 5}, MeshError::Triangle, 1},         // three collinear points
      {{0, 1, 2, 0, 2, 4}, MeshError::Triangle, 1},         // a non-finite vertex
      {{0, 1, 2, 2, 3, 6}, MeshError::IndexOutOfRange, 1},  // past the vertices
      {{0, 1, -1}, MeshError::IndexOutOfRange, 0},
      {{0, 1, 2, 3}, MeshError::IndexCount, -1},
      {{}, MeshError::IndexCount, -1},
  };
  for (const Bad& c : cases) {
    const MeshResult r =
        add_triangles(*body, vertices, 6, c.indices.data(), static_cast<int>(c.indices.size()));
    EXPECT_EQ(r.error, c.error) << r.message;
    EXPECT_EQ(r.triangle, c.triangle) << r.message;
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.fixtures.empty());
    EXPECT_STRNE(r.message, "");
    EXPECT_EQ(body->GetFixtureList(), nullptr) << "a refused mesh created a fixture";
  }
  const MeshResult sliver = add_triangles(*body, vertices, 6, std::vector<int>{0, 1, 5}.data(), 3);
  EXPECT_EQ(sliver.shape_error, ShapeError::Triangle);
}

// Adding a mesh from a contact callback (the world is locked in a step) is refused.
TEST(MeshBuilder, AMeshAddedDuringAStepIsRefused) {
  struct AddOnContact : b2ContactListener {
    b2Body* target = nullptr;
    std::optional<MeshError> error;
    void BeginContact(b2Contact*) override {
      const b2Vec2 v[] = {{5, 5}, {6, 5}, {6, 6}};
      const int i[] = {0, 1, 2};
      if (!error) error = add_triangles(*target, v, 3, i, 3).error;
    }
  } listener;
  World world;
  b2Body* ground = add_triangle_ground(world, 2.0f);
  add_split_box(world, b2Vec2(0.0f, 0.3f), 0.25f);
  listener.target = ground;
  world->SetContactListener(&listener);
  for (int i = 0; i < 10 && !listener.error; ++i) world.step();
  world->SetContactListener(nullptr);
  ASSERT_TRUE(listener.error.has_value());
  EXPECT_EQ(*listener.error, MeshError::WorldLocked);
}

}  // namespace
}  // namespace dyop::box2d::testing
