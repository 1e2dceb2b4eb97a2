#pragma once
/// \file
/// Box2D 2.4 worlds built from triangle fixtures: the building blocks of the testbed's scenes, of
/// the bridge's tests and of the world fuzzer.
///
/// Units are Box2D's: metres, kilograms, seconds, radians; y points up. Every triangle goes
/// through `dyop::box2d::make_triangle`, so a shape Box2D would assert on (or silently turn into
/// a box) is refused with the plug-in's message instead.

#include <box2d/box2d.h>

#include <cstdint>
#include <vector>

namespace dyop::worlds {

/// Box2D's testbed settings: 60 Hz, 8 velocity and 3 position iterations.
inline constexpr float time_step = 1.0f / 60.0f;
inline constexpr int velocity_iterations = 8;
inline constexpr int position_iterations = 3;
inline constexpr int steps_per_second = 60;

/// A `b2World` that destroys its bodies before itself and remembers them in creation order.
/// Why the destruction: `b2World`'s destructor frees contacts without destroying them, which
/// would leave the plug-in's contacts counted and block `dyop::box2d::uninstall`. Sleeping is off:
/// a sleeping body cannot drift or jitter, and every resting contact stays in the narrow phase,
/// which is what the scenes measure and the tests check.
class World {
 public:
  explicit World(const b2Vec2& gravity = b2Vec2(0.0f, -10.0f));
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World();

  b2World* operator->() { return &world_; }
  const b2World* operator->() const { return &world_; }
  b2World& get() { return world_; }
  const b2World& get() const { return world_; }

  /// One step of `time_step` with the testbed's iterations.
  void step();

  /// Creates a body and records it (`bodies()` lists them in creation order).
  b2Body* create_body(const b2BodyDef& def);
  /// Every body created through `create_body`, in creation order.
  const std::vector<b2Body*>& bodies() const { return bodies_; }

 private:
  b2World world_;
  std::vector<b2Body*> bodies_;
};

/// What a fixture is made of.
struct Material {
  float density = 1.0f;  ///< kg/m²
  float friction =
      0.6f;  ///< Coulomb coefficient (Box2D mixes two as the square root of the product)
};

/// A body of `type` at `position` (its origin) turned by `angle`.
b2Body* add_body(World& world, b2BodyType type, const b2Vec2& position, float angle = 0);

/// A triangle fixture from body-frame points (any winding). Throws `std::invalid_argument` with
/// the plug-in's description when the points cannot make a Box2D triangle.
b2Fixture* add_triangle(b2Body* body, const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2,
                        const Material& material = {});

/// The axis-aligned rectangle [x0, x1] × [y0, y1] (body frame) as triangle fixtures: cells of at
/// most `cell` metres on a side, each split along its diagonal into two triangles.
void add_triangle_block(b2Body* body, float x0, float y0, float x1, float y1, float cell = 1.0f,
                        const Material& material = {});

/// A static ground whose top is y = 0 over [-half_width, half_width], 1 m thick, made of unit
/// squares split into two triangle fixtures each: every contact with it is triangle–triangle.
b2Body* add_triangle_ground(World& world, float half_width);

/// A static bin of triangle fixtures: a floor whose top is y = 0 over [-half_width, half_width]
/// and two 1 m thick walls of `height` just outside it.
b2Body* add_triangle_bin(World& world, float half_width, float height);

/// A dynamic square of side 2·half made of two triangle fixtures split along its diagonal.
b2Body* add_split_box(World& world, const b2Vec2& center, float half,
                      const Material& material = {});

/// A dynamic L (two 2 × 1 arms meeting at the body origin), four triangle fixtures.
b2Body* add_l_shape(World& world, const b2Vec2& position, float angle);

/// A dynamic U (3 wide, 2 high, a 1 × 1 notch on top), six triangle fixtures.
b2Body* add_u_shape(World& world, const b2Vec2& position, float angle);

/// A dynamic five-pointed star (tips at `outer`, notches at `inner` from the body origin): ten
/// triangle fixtures fanned from the centre.
b2Body* add_star(World& world, const b2Vec2& position, float angle, float outer = 1.0f,
                 float inner = 0.45f);

/// The FNV-1a hash of the bodies' state: each body's position, angle and velocities, as float
/// bits, in the order given. Equal hashes: bit-identical worlds.
std::uint64_t state_hash(const std::vector<b2Body*>& bodies);

/// `state_hash` of `world`'s bodies in creation order (the scenes' `SceneMetrics::hash`).
inline std::uint64_t state_hash(const World& world) { return state_hash(world.bodies()); }

/// True when the fixture is a triangle (a 3-vertex polygon): the pairs the plug-in answers.
bool is_triangle(const b2Fixture* fixture);

}  // namespace dyop::worlds
