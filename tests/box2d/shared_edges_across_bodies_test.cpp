// Edges shared across static bodies in running worlds (`Config::internal_edges`): a slider glides
// over a ground of one static body per triangle as over one body; a ground of kinematic bodies
// keeps every edge an outline edge (the world is bit-identical to one without the rule); and the
// masks of live contacts follow a neighbouring static body moved away (`SetTransform`, far or by a
// centimetre), made kinematic and static again (`SetType`), and disabled and enabled again; a body
// beyond the broad phase's margin sees a move after `forget_internal_edges`.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <utility>

#include "dyop/box2d_internal_edges.hpp"
#include "scene.hpp"

namespace dyop::box2d::testing {
namespace {

// The rule as installed by default, every evaluation run in full (recycling off): these tests
// count the evaluations the rule is in force in (`Stats::internal_edge_pairs`).
Config counted() {
  Config c;
  c.recycle_distance = 0;
  return c;
}

const scenes::Material kIce{1.0f, 0.0f};
constexpr float kGlideVerticalSpeed = 0.05f;  // m/s: the bound for a glide
constexpr float kGlideTravel = 0.98f;         // of speed × time

// A ground whose top is y = 0 from x = -2 to 14, 0.25 m cells split along a diagonal, one body of
// `type` per triangle.
void add_ground_of_bodies(World& world, b2BodyType type) {
  constexpr float cell = 0.25f;
  for (float x = -2.0f; x < 14.0f; x += cell) {
    b2Body* piece = add_body(world, type, b2Vec2(0, 0));
    add_triangle(piece, b2Vec2(x, 0), b2Vec2(x, -cell), b2Vec2(x + cell, 0), kIce);
    piece = add_body(world, type, b2Vec2(0, 0));
    add_triangle(piece, b2Vec2(x + cell, 0), b2Vec2(x, -cell), b2Vec2(x + cell, -cell), kIce);
  }
}

struct SlideRun {
  b2Transform slider;
  float max_vertical = 0;
  float travel = 0;
  std::uint64_t rule_pairs = 0;
};

// A frictionless one-triangle slider launched at 2 m/s along the ground for 3 s.
SlideRun slide(const Config& config, b2BodyType ground) {
  EXPECT_TRUE(install(Backend::Dyop, config).ok());
  World world;
  add_ground_of_bodies(world, ground);
  b2Body* box = add_body(world, b2_dynamicBody, b2Vec2(0.1f, 0));
  add_triangle(box, b2Vec2(-0.25f, 0), b2Vec2(0.25f, 0), b2Vec2(0, 0.3f), kIce);
  constexpr float speed = 2.0f;
  box->SetLinearVelocity(b2Vec2(speed, 0));
  SlideRun r;
  for (int i = 0; i < 3 * kStepsPerSecond; ++i) {
    world.step();
    r.max_vertical = std::max(r.max_vertical, std::abs(box->GetLinearVelocity().y));
  }
  r.slider = box->GetTransform();
  r.travel = (box->GetPosition().x - 0.1f) / (speed * 3);
  r.rule_pairs = stats().internal_edge_pairs;
  EXPECT_TRUE(uninstall().ok());
  return r;
}

Config rule(bool on) {
  Config c;
  c.internal_edges = on;
  return c;
}

TEST(SharedEdgesAcrossBodies, SliderGlidesOverAGroundOfOneStaticBodyPerTriangle) {
  const SlideRun on = slide(rule(true), b2_staticBody);
  const SlideRun off = slide(rule(false), b2_staticBody);
  std::printf(
      "one static body per triangle: rule on vy %.4f travel %.1f %% | off vy %.4f travel "
      "%.1f %%\n",
      on.max_vertical, 100 * on.travel, off.max_vertical, 100 * off.travel);
  EXPECT_GT(on.rule_pairs, 0u);
  EXPECT_LE(on.max_vertical, kGlideVerticalSpeed);
  EXPECT_GE(on.travel, kGlideTravel);
}

// Kinematic bodies move (here at zero speed): their shared edges are not internal, the rule never
// applies, and the world is bit-identical to one without it.
TEST(SharedEdgesAcrossBodies, EdgesSharedByKinematicBodiesStayOutlineEdges) {
  const SlideRun on = slide(rule(true), b2_kinematicBody);
  const SlideRun off = slide(rule(false), b2_kinematicBody);
  EXPECT_EQ(on.rule_pairs, 0u);
  EXPECT_EQ(std::memcmp(&on.slider, &off.slider, sizeof on.slider), 0);
}

// Two static bodies sharing an edge (x = 0, y in [-1, 0]): G = (0, 0) (0, -1) (4, 0) and F, flat
// on top, to its left. A one-triangle body rests on G across the junction's neighbourhood, with
// contacts with G and F. The rule applies while the edge is shared; `change` breaks the sharing
// between two steps and `restore` makes it again: within one step the live contacts find their
// masks again (no more rule pairs: G and F alone have no internal edge), and again after.
void expect_masks_follow(const std::function<void(b2Body*)>& change,
                         const std::function<void(b2Body*)>& restore, float body_x) {
  ASSERT_TRUE(install(Backend::Dyop, counted()).ok());
  World world;
  b2Body* g = add_body(world, b2_staticBody, b2Vec2(0, 0));
  add_triangle(g, {0, 0}, {0, -1}, {4, 0});
  b2Body* f = add_body(world, b2_staticBody, b2Vec2(-1.0f, 0.0f), 0.5f);  // a frame of its own
  const b2Transform& xf = f->GetTransform();
  add_triangle(f, b2MulT(xf, {0, 0}), b2MulT(xf, {-4, 0}), b2MulT(xf, {0, -1}));
  b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(body_x, 0.0f));
  add_triangle(body, {-0.3f, 0}, {0.3f, 0}, {0, 0.3f}, kIce);
  const auto rule_pairs_over = [&](int steps) {
    reset_stats();
    for (int i = 0; i < steps; ++i) world.step();
    EXPECT_GT(stats().triangles(Backend::Dyop), 0u);
    return stats().internal_edge_pairs;
  };
  EXPECT_GT(rule_pairs_over(30), 0u);
  change(f);
  world.step();  // the step that sees the change
  EXPECT_EQ(rule_pairs_over(10), 0u);
  restore(f);
  world.step();
  EXPECT_GT(rule_pairs_over(10), 0u);
  EXPECT_NEAR(body->GetPosition().y, 0.0f, 0.02f);
  ASSERT_TRUE(uninstall().ok());
}

TEST(SharedEdgesAcrossBodies, NeighbourMovedFarAwayBySetTransformLeavesAnOutlineEdge) {
  const b2Vec2 home(-1.0f, 0.0f);
  expect_masks_follow([&](b2Body* f) { f->SetTransform(b2Vec2(-30.0f, 0.0f), 0.5f); },
                      [&](b2Body* f) { f->SetTransform(home, 0.5f); }, 0.4f);
}

// Moved by 1 cm, within the broad phase's margin: no contact is made or ended, the live contacts
// of the body resting across the junction see it in their stamps.
TEST(SharedEdgesAcrossBodies, NeighbourMovedByACentimetreLeavesAnOutlineEdge) {
  const b2Vec2 home(-1.0f, 0.0f);
  expect_masks_follow([&](b2Body* f) { f->SetTransform(home - b2Vec2(0.01f, 0), 0.5f); },
                      [&](b2Body* f) { f->SetTransform(home, 0.5f); }, 0.1f);
}

TEST(SharedEdgesAcrossBodies, NeighbourMadeKinematicLeavesAnOutlineEdge) {
  expect_masks_follow([](b2Body* f) { f->SetType(b2_kinematicBody); },
                      [](b2Body* f) { f->SetType(b2_staticBody); }, 0.4f);
}

TEST(SharedEdgesAcrossBodies, NeighbourDisabledLeavesAnOutlineEdge) {
  expect_masks_follow([](b2Body* f) { f->SetEnabled(false); },
                      [](b2Body* f) { f->SetEnabled(true); }, 0.4f);
}

// A body resting 2.7 m from the neighbour, beyond the broad phase's margin: it has no contact with
// the neighbour, so nothing tells it that the neighbour moved away (the world's fixtures are the
// same), and its contact with G keeps G's edge internal; `forget_internal_edges` makes it look.
TEST(SharedEdgesAcrossBodies, NeighbourMovedFarFromABodyIsSeenAfterForgetInternalEdges) {
  ASSERT_TRUE(install(Backend::Dyop, counted()).ok());
  World world;
  b2Body* g = add_body(world, b2_staticBody, b2Vec2(0, 0));
  add_triangle(g, {0, 0}, {0, -1}, {4, 0});
  b2Body* f = add_body(world, b2_staticBody, b2Vec2(0, 0));
  add_triangle(f, {0, 0}, {-4, 0}, {0, -1});
  b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(3.0f, 0.0f));
  add_triangle(body, {-0.3f, 0}, {0.3f, 0}, {0, 0.3f}, kIce);
  const auto rule_pairs_over = [&](int steps) {
    reset_stats();
    for (int i = 0; i < steps; ++i) world.step();
    return stats().internal_edge_pairs;
  };
  EXPECT_GT(rule_pairs_over(30), 0u);
  f->SetTransform(b2Vec2(-30.0f, 0.0f), 0);
  EXPECT_GT(rule_pairs_over(10), 0u) << "not seen: the limit forget_internal_edges is for";
  forget_internal_edges(world.get());
  EXPECT_EQ(rule_pairs_over(10), 0u);
  ASSERT_TRUE(uninstall().ok());
}

}  // namespace
}  // namespace dyop::box2d::testing
