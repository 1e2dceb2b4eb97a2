// Stacks, a pyramid and a pile of concave bodies, all made of triangle fixtures, under every
// backend and under Box2D's own contact.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "support/per_contact.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

struct Motion {
  float top_displacement = 0;  // largest distance of the top body from where it was placed
  float max_tilt = 0;          // largest |angle| of any body
  bool finite = true;          // every body's state finite after every step (`finite_state`)
};

// Steps `seconds` and measures `top` against its position at the start, and every body.
Motion run(World& world, b2Body* top, const std::vector<b2Body*>& bodies, int seconds) {
  Motion m;
  const b2Vec2 start = top->GetPosition();
  for (int i = 0; i < seconds * kStepsPerSecond; ++i) {
    world.step();
    // std::max keeps its first argument against a NaN: the maxima alone cannot tell a world that
    // went NaN, so finiteness is followed step by step.
    m.finite = m.finite && finite_state(world);
    m.top_displacement = std::max(m.top_displacement, (top->GetPosition() - start).Length());
    for (b2Body* b : bodies) {
      m.max_tilt = std::max(m.max_tilt, std::abs(b->GetAngle()));
    }
  }
  return m;
}

void report(const std::string& what, const std::string& contact, const Motion& m) {
  std::cout << what << " " << contact << ": top displacement " << m.top_displacement
            << " m, max tilt " << m.max_tilt << " rad\n";
  ::testing::Test::RecordProperty("top_displacement", std::to_string(m.top_displacement));
}

// The stack and the piles: claimed for every contact but dyop-fast (`StacksAndPiles`); the
// pyramid for every contact (`Stacking`); what dyop-fast holds of the stack and the piles under
// names of its own (`StacksAndPilesUnderDyopFast`).
using StacksAndPiles = PerContact;
using Stacking = PerContact;
using StacksAndPilesUnderDyopFast = PerContact;

// Standing: the top box neither fell nor slid. Boxes are placed with their cores 1 cm apart
// (Box2D rests them 1.5 cm apart: the skins' sum less the slop), so settling moves the top by a
// few centimetres; a toppled stack moves metres.
constexpr float kStandingDisplacement = 0.1f;
constexpr float kStandingTilt = 0.05f;
// DyopFast is approximate by design: its pivot sometimes takes a face that is not the
// minimum-depth axis, so the boxes get sideways pushes. The 10-box stack is at the edge of what it
// can hold: it has been measured swaying ±0.25 m and, after a change of rounding in the clipping
// (same manifolds within 1e-6 m), toppling. It is held only to a finite, NaN-free simulation
// (`StacksAndPilesUnderDyopFast`); its displacement is reported. The pyramid meets the others'
// bounds.

// Ten split boxes stacked on a triangle ground, stepped for 10 s: how the top moved, every tilt.
Motion run_ten_box_stack() {
  World world;
  add_triangle_ground(world, 5.0f);
  std::vector<b2Body*> boxes;
  const float pitch = 2 * kBoxHalf + b2_polygonRadius;
  for (int i = 0; i < 10; ++i) {
    boxes.push_back(
        add_split_box(world, b2Vec2(0.0f, kBoxHalf + b2_polygonRadius + i * pitch), kBoxHalf));
  }
  return run(world, boxes.back(), boxes, 10);
}

TEST_P(StacksAndPiles, TenSplitBoxesStackedStayStandingFor10s) {
  const Motion m = run_ten_box_stack();
  report("stack", contact(), m);
  EXPECT_LE(m.top_displacement, kStandingDisplacement);
  EXPECT_LE(m.max_tilt, kStandingTilt);
}

TEST_P(StacksAndPilesUnderDyopFast, TenSplitBoxesStackedStayFiniteFor10s) {
  const Motion m = run_ten_box_stack();
  report("stack", contact(), m);
  EXPECT_TRUE(m.finite);
}

TEST_P(Stacking, PyramidOf55SplitBoxesStaysStandingFor10s) {
  World world;
  add_triangle_ground(world, 10.0f);
  std::vector<b2Body*> boxes;
  const float pitch = 2 * kBoxHalf + b2_polygonRadius;
  constexpr int kBase = 10;  // 10 + 9 + ... + 1 = 55 bodies, 110 triangles
  for (int row = 0; row < kBase; ++row) {
    for (int i = 0; i < kBase - row; ++i) {
      const float x = (i - 0.5f * (kBase - row - 1)) * pitch;
      boxes.push_back(
          add_split_box(world, b2Vec2(x, kBoxHalf + b2_polygonRadius + row * pitch), kBoxHalf));
    }
  }
  ASSERT_EQ(boxes.size(), 55u);
  const Motion m = run(world, boxes.back(), boxes, 10);
  report("pyramid", contact(), m);
  EXPECT_LE(m.top_displacement, kStandingDisplacement);
  EXPECT_LE(m.max_tilt, kStandingTilt);
}

// The bodies are dropped one by one into a bin 12 m wide, from 12 m up, every 1.2 s: a body
// falls 7.2 m in that time, farther than any of these shapes reaches from its origin (3.6 m),
// so no body starts overlapping another. Settled: 6 s after the last drop, over the next 4 s
// nothing moves faster than 1 cm/s nor farther than 1 cm. Jitter shows as speeds of m/s.
constexpr int kConcaveBodies = 12;
constexpr float kDropHeight = 12.0f;
constexpr int kDropSteps = 72;  // 1.2 s
constexpr int kSettleSeconds = 6;
constexpr int kWatchSeconds = 4;
constexpr float kSettledSpeed = 0.01f;
constexpr float kSettledDisplacement = 0.01f;
// A pile of concave bodies is chaotic: turning every drop by 1e-4 rad changes where each body
// comes to rest, and now and then a pile shifts late. Measured over `kPiles` piles, each turned by
// `kTwist` more than the last: Box2D's own contact settles 11 of them (in the twelfth a body still
// moved at 0.29 m/s 6 s after the last drop), `dyop` and `sat` 11, `epa` and `lin-canny` 12. A
// single pile would pass or fail on luck (a change of the last bit of one clipped point flips it);
// jitter unsettles them all.
constexpr int kPiles = 12;
constexpr float kTwist = 1e-4f;  // radians
constexpr int kPilesSettled = 10;
// DyopFast does not settle the pile: bodies keep creeping over one another (measured over the
// twelve piles: 0.11 to 7.7 m/s over the last 4 s). Held to what it achieves: every body stays in
// the bin (none passes through the ground or the walls), and none is faster than a body falling
// from the drop height (under `World`'s gravity, 10 m/s²), which would be energy from nowhere.
const float kFreeFallSpeed = std::sqrt(2 * 10.0f * kDropHeight);

// A static wall of 1 × `height` m at x in [x0, x0 + 1]: one cell, two triangle fixtures.
void add_triangle_wall(b2Body* ground, float x0, float height) {
  worlds::add_triangle_block(ground, x0, 0.0f, x0 + 1, height, height);
}

// How a pile ended: the fastest body and the farthest move over the last `kWatchSeconds`, and
// whether every body is still in the bin.
struct PileEnd {
  float speed = 0;
  float displacement = 0;
  bool in_bin = true;
  bool settled() const { return speed <= kSettledSpeed && displacement <= kSettledDisplacement; }
};

// Drops the concave bodies into the bin, each turned by `twist` radians more than its own angle,
// under whatever contact is installed.
PileEnd drop_concave_pile(float twist) {
  World world;
  b2Body* ground = add_triangle_ground(world, 8.0f);
  add_triangle_wall(ground, -7.0f, 16.0f);
  add_triangle_wall(ground, 6.0f, 16.0f);
  std::vector<b2Body*> bodies;
  for (int i = 0; i < kConcaveBodies; ++i) {
    const b2Vec2 p(i % 2 ? 1.0f : -2.0f, kDropHeight);
    const float angle = 0.7f * i + twist;
    bodies.push_back(i % 2 ? worlds::add_u_shape(world, p, angle)
                           : worlds::add_l_shape(world, p, angle));
    for (int k = 0; k < kDropSteps; ++k) world.step();
  }
  for (int i = 0; i < kSettleSeconds * kStepsPerSecond; ++i) world.step();
  std::vector<b2Vec2> settled;
  for (b2Body* b : bodies) settled.push_back(b->GetPosition());
  PileEnd end;
  for (int i = 0; i < kWatchSeconds * kStepsPerSecond; ++i) {
    world.step();
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      end.speed = std::max(end.speed, bodies[k]->GetLinearVelocity().Length());
      end.displacement =
          std::max(end.displacement, (bodies[k]->GetPosition() - settled[k]).Length());
    }
  }
  for (b2Body* b : bodies) {
    const b2Vec2 c = b->GetWorldCenter();
    end.in_bin = end.in_bin && std::abs(c.x) < 6.0f && c.y > 0.0f;
  }
  return end;
}

// The twelve piles (`kPiles`): how many settled, the fastest body over their last seconds,
// whether every body of every pile stayed in the bin.
struct Piles {
  int settled = 0;
  float fastest = 0;
  bool in_bin = true;
};

Piles drop_piles(const std::string& contact) {
  Piles all;
  for (int pile = 0; pile < kPiles; ++pile) {
    const PileEnd end = drop_concave_pile(kTwist * static_cast<float>(pile));
    std::cout << "concave pile " << pile << " " << contact << ": max speed " << end.speed
              << " m/s, max displacement " << end.displacement << " m over the last "
              << kWatchSeconds << " s\n";
    EXPECT_TRUE(end.in_bin) << "a body of pile " << pile << " left the bin";
    all.in_bin = all.in_bin && end.in_bin;
    all.settled += static_cast<int>(end.settled());
    all.fastest = std::max(all.fastest, end.speed);
  }
  ::testing::Test::RecordProperty("piles_settled", std::to_string(all.settled));
  ::testing::Test::RecordProperty("max_speed", std::to_string(all.fastest));
  return all;
}

TEST_P(StacksAndPiles, PilesOfConcaveBodiesSettleWithoutJitter) {
  const Piles piles = drop_piles(contact());
  EXPECT_GE(piles.settled, kPilesSettled) << "of " << kPiles << " piles";
}

TEST_P(StacksAndPilesUnderDyopFast, PilesOfConcaveBodiesStayInTheBinAndNeverOutrunAFreeFall) {
  const Piles piles = drop_piles(contact());
  EXPECT_TRUE(piles.in_bin);
  EXPECT_LT(piles.fastest, kFreeFallSpeed);
}

INSTANTIATE_TEST_SUITE_P(ContactsButDyopFast, StacksAndPiles,
                         ::testing::ValuesIn(kContactsButDyopFast), contact_param_name);
INSTANTIATE_TEST_SUITE_P(EveryContact, Stacking, ::testing::ValuesIn(kAllContacts),
                         contact_param_name);
INSTANTIATE_TEST_SUITE_P(DyopFast, StacksAndPilesUnderDyopFast, ::testing::ValuesIn(kDyopFastOnly),
                         contact_param_name);

}  // namespace
}  // namespace dyop::box2d::testing
