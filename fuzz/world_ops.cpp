#include "world_ops.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cstdarg>
#include <cfloat>
#include <cmath>
#include <optional>
#include <type_traits>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_mesh.hpp"
#include "byte_reader.hpp"
#include "worlds/world.hpp"

namespace dyop::fuzz {

std::vector<WorldOp> decode_world_ops(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  std::vector<WorldOp> ops;
  while (in.left() > 0 && ops.size() < static_cast<std::size_t>(max_ops)) {
    WorldOp op;
    op.kind = static_cast<OpKind>(in.get<std::uint8_t>() % static_cast<int>(OpKind::Count));
    for (std::uint8_t& a : op.arg) a = in.get<std::uint8_t>();
    ops.push_back(op);
  }
  return ops;
}

const char* WorldVerdict::failure() const {
  if (!finite) return "a body's position or angle went NaN or infinite";
  if (!repeatable) return "the same sequence played twice ends differently";
  if (!box2d_is_own) return "backend box2d differs from Box2D's own contact";
  if (!dyop_is_sat) return "backend dyop differs from backend sat";
  return nullptr;
}

WorldVerdict judge_world_ops(const std::vector<WorldOp>& ops) {
  WorldVerdict v;
  v.as_written = play_world_ops(ops, Installs::AsWritten);
  v.finite = v.as_written.finite;
  v.repeatable = play_world_ops(ops, Installs::AsWritten).hash == v.as_written.hash;
  v.box2d_is_own =
      play_world_ops(ops, Installs::Box2D).hash == play_world_ops(ops, Installs::Never).hash;
  v.dyop_is_sat =
      play_world_ops(ops, Installs::Dyop).hash == play_world_ops(ops, Installs::Sat).hash;
  return v;
}

namespace {

using box2d::Backend;

constexpr int kWorlds = 3;
// Shape sizes (m): tiny (a few weld distances) to huge.
constexpr float kScales[8] = {0.01f, 0.05f, 0.25f, 1.0f, 1.0f, 4.0f, 50.0f, 1000.0f};
// Body positions' offsets from the origin (m).
constexpr float kFar[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1e3f, -1e4f, 3e4f, 1e5f};
constexpr float kTimeSteps[8] = {1.0f / 60,  1.0f / 240, 1.0f / 30, 1.0f / 60,
                                 1.0f / 120, 1e-4f,      0.1f,      1e-6f};
constexpr float kSpeeds[4] = {0.1f, 1.0f, 10.0f, 300.0f};  // m/s per unit of a signed byte / 16
// A sliver's height, or a needle's width, per unit of its length.
constexpr float kThin[4] = {1e-2f, 1e-3f, 1e-4f, 2e-5f};
constexpr float kDensities[4] = {1.0f, 0.1f, 10.0f, 0.0f};
constexpr float kRecycle[4] = {box2d::default_recycle_distance, 0.0f, 0.01f, 1e-5f};
constexpr float kGravities[4][2] = {{0.0f, -10.0f}, {0.0f, 0.0f}, {3.0f, -30.0f}, {0.0f, -10.0f}};
constexpr float kPi = 3.14159265358979f;

// Why the player keeps a shape's vertices within this many of its longest edge of its body's
// origin: Box2D 2.4.1's `b2Body::ResetMassData` moves the inertia to the centre of mass in float
// (`I -= m·|c|²`) and asserts it stays positive; a shape far from the origin of its size loses the
// difference to rounding (an inertia about the centroid of at least m·size²/18 against an error of
// a few FLT_EPSILON of m·|c|²).
constexpr float kBodyReach = 30.0f;
// Margins on Box2D's own thresholds, so that its float rounding cannot cross them.
constexpr float kWeldMargin = 1.1f;  // `b2PolygonShape::Set` welds points closer than 0.5 slop
constexpr float kAreaMargin = 4.0f;  // its centroid asserts area > b2_epsilon
constexpr float kTurnMargin = 64 * FLT_EPSILON;  // a hull corner's sine, robust in float

float s8(std::uint8_t b) { return static_cast<float>(static_cast<std::int8_t>(b)); }
float lo(std::uint8_t b) { return static_cast<float>(b & 15) - 8.0f; }
float hi(std::uint8_t b) { return static_cast<float>(b >> 4) - 8.0f; }

const char* kind_name(OpKind k) {
  constexpr const char* names[static_cast<int>(OpKind::Count)] = {
      "new world",   "end world",   "create body",   "destroy body",    "add triangle",
      "add mesh",    "add polygon", "add circle",    "destroy fixture", "teleport",
      "set type",    "set enabled", "set velocity",  "apply impulse",   "install",
      "uninstall",   "fix edges",   "refresh edges", "forget edges",    "step",
      "world flags", "add edge",    "add chain"};
  return names[static_cast<int>(k)];
}

b2BodyType body_type(int k) {
  constexpr b2BodyType types[4] = {b2_staticBody, b2_kinematicBody, b2_dynamicBody, b2_dynamicBody};
  return types[k & 3];
}
const char* type_name(int k) {
  constexpr const char* names[4] = {"static", "kinematic", "dynamic", "bullet"};
  return names[k & 3];
}

// Box2D's Set of `n` points, and whether it left a polygon: 2.4.1's returns nothing (what
// polygon_refusal lets through it makes); 2.4.2's returns false and leaves the shape empty where
// its hull welds points within 4·b2_linearSlop or drops one within 2·b2_linearSlop of its
// neighbours' line, both wider than 2.4.1's, down to fewer than three points.
template <class Shape>
bool set_polygon(Shape& shape, const b2Vec2* v, int n) {
  if constexpr (std::is_same_v<decltype(shape.Set(v, n)), bool>) {
    return shape.Set(v, n);
  } else {
    shape.Set(v, n);
    return true;
  }
}

// Why Box2D 2.4.1 would assert on polygon `v` (CCW for more than 3 vertices) on a body, or nullptr.
const char* polygon_refusal(const b2Vec2* v, int n) {
  double longest = 0, reach = 0, area2 = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double dx = double(v[i].x) - v[j].x, dy = double(v[i].y) - v[j].y;
      const double d = std::sqrt(dx * dx + dy * dy);
      if (d < kWeldMargin * 0.5 * b2_linearSlop) return "two vertices Box2D would weld";
      longest = std::max(longest, d);
    }
    reach = std::max(reach, std::hypot(double(v[i].x), double(v[i].y)));
  }
  for (int i = 0; i < n; ++i) {  // every corner turns the same way, clear of rounding
    const b2Vec2 a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    const double fx = double(c.x) - b.x, fy = double(c.y) - b.y;
    const double turn = ex * fy - ey * fx;
    const double lengths = std::hypot(ex, ey) * std::hypot(fx, fy);
    if ((n == 3 ? std::abs(turn) : turn) <= kTurnMargin * lengths) {
      return "a corner Box2D's hull may drop";
    }
    area2 += double(a.x - v[0].x) * (b.y - v[0].y) - double(a.y - v[0].y) * (b.x - v[0].x);
  }
  if (std::abs(area2) / 2 <= kAreaMargin * b2_epsilon) return "an area Box2D's centroid asserts on";
  if (reach > kBodyReach * longest) return "too far from its body's origin for Box2D's inertia";
  return nullptr;
}

class Player {
 public:
  // World 0 exists from the start (gravity -10 m/s²), so that short inputs reach the worlds.
  Player(Installs installs, std::FILE* log) : installs_(installs), log_(log) {
    box2d::uninstall();
    slots_[0].world = new b2World(b2Vec2(kGravities[0][0], kGravities[0][1]));
  }
  ~Player() {
    for (int w = 0; w < kWorlds; ++w) end_world(w, w % 2 == 0);
    box2d::uninstall();
  }
  Player(const Player&) = delete;
  Player& operator=(const Player&) = delete;

  void run(const WorldOp& op);

  PlayResult result() {
    for (int w = 0; w < kWorlds; ++w) {
      if (slots_[w].world) fold(w);
    }
    return result_;
  }

 private:
  struct Slot {
    b2World* world = nullptr;
    std::vector<b2Body*> bodies;  // in creation order, for the hash
  };

  [[gnu::format(printf, 2, 3)]] void note(const char* format, ...) {
    if (!log_) return;
    va_list args;
    va_start(args, format);
    std::vfprintf(log_, format, args);
    va_end(args);
    std::fputc('\n', log_);
  }
  void skip(const char* why) {
    ++result_.skipped;
    if (log_) std::fprintf(log_, "  skipped: %s\n", why);
  }

  // Target byte: world `b % 3`, the (b / 3)-th of its bodies (modulo their count).
  std::optional<int> world_of(std::uint8_t b) {
    if (!slots_[b % kWorlds].world) return std::nullopt;
    return b % kWorlds;
  }
  b2Body* body_of(std::uint8_t b) {
    Slot& s = slots_[b % kWorlds];
    if (!s.world || s.bodies.empty()) return nullptr;
    return s.bodies[(b / kWorlds) % s.bodies.size()];
  }
  int where(const b2Body* body) const {
    for (int w = 0; w < kWorlds; ++w) {
      if (slots_[w].world == body->GetWorld()) return w;
    }
    return -1;
  }
  int index_of(const b2Body* body) const {
    const std::vector<b2Body*>& v = slots_[where(body)].bodies;
    return static_cast<int>(std::find(v.begin(), v.end(), body) - v.begin());
  }
  static b2Vec2 position(std::uint8_t x, std::uint8_t y, std::uint8_t far) {
    return {0.25f * s8(x) + kFar[far & 7], 0.25f * s8(y) + kFar[(far >> 3) & 7]};
  }
  static int fixture_count(const b2Body& body) {
    int n = 0;
    for (const b2Fixture* f = body.GetFixtureList(); f; f = f->GetNext()) ++n;
    return n;
  }

  void fold(int w) {
    result_.hash = (result_.hash ^ worlds::state_hash(slots_[w].bodies)) * 0x100000001b3ull;
  }
  void end_world(int w, bool destroy_bodies) {
    Slot& s = slots_[w];
    if (!s.world) return;
    if (destroy_bodies) {
      while (b2Body* body = s.world->GetBodyList()) s.world->DestroyBody(body);
    }
    delete s.world;
    s = Slot{};
  }

  b2FixtureDef fixture_def(std::uint8_t b) const {
    b2FixtureDef def;
    def.density = kDensities[b & 3];
    def.friction = (b & 4) ? 0.0f : 0.6f;
    def.restitution = (b & 8) ? 0.5f : 0.0f;
    def.isSensor = (b & 0x30) == 0x30;
    return def;
  }
  void add_fixture(b2Body& body, const b2Shape& shape, std::uint8_t b) {
    b2FixtureDef def = fixture_def(b);
    def.shape = &shape;
    body.CreateFixture(&def);
    ++fixtures_;
  }
  bool room_for_fixtures(int n) {
    if (fixtures_ + n <= max_fixtures) return true;
    skip("fixture bound");
    return false;
  }

  void new_world(const WorldOp& op);
  void create_body(const WorldOp& op);
  void add_triangle(b2Body& body, const WorldOp& op);
  void add_mesh(b2Body& body, const WorldOp& op);
  void add_polygon(b2Body& body, const WorldOp& op);
  void add_circle(b2Body& body, const WorldOp& op);
  void add_edge(b2Body& body, const WorldOp& op);
  void add_chain(b2Body& body, const WorldOp& op);
  void body_op(b2Body& body, const WorldOp& op);
  void install(const WorldOp& op);
  void step(const WorldOp& op);
  void world_op(int w, const WorldOp& op);

  Installs installs_;
  std::FILE* log_;
  std::array<Slot, kWorlds> slots_;
  int bodies_ = 0;
  int fixtures_ = 0;
  PlayResult result_;
};

void Player::run(const WorldOp& op) {
  switch (op.kind) {
    case OpKind::NewWorld:
      new_world(op);
      break;
    case OpKind::CreateBody:
      create_body(op);
      break;
    case OpKind::Install:
      install(op);
      break;
    case OpKind::Uninstall:
      note("uninstall");
      if (installs_ != Installs::Never) box2d::uninstall();
      ++result_.played;
      break;
    case OpKind::Step:
      step(op);
      break;
    case OpKind::EndWorld:
    case OpKind::FixEdges:
    case OpKind::RefreshEdges:
    case OpKind::ForgetEdges:
    case OpKind::WorldFlags:
      if (const std::optional<int> w = world_of(op.arg[0])) {
        if (op.kind != OpKind::FixEdges || (op.arg[1] & 1)) {
          world_op(*w, op);
          break;
        }
      }
      [[fallthrough]];
    default:
      if (b2Body* body = body_of(op.arg[0])) {
        body_op(*body, op);
      } else {
        note("%s on world %d", kind_name(op.kind), op.arg[0] % kWorlds);
        skip("no such world or body");
      }
  }
}

void Player::new_world(const WorldOp& op) {
  const int w = op.arg[0] % kWorlds;
  const b2Vec2 g(kGravities[op.arg[1] & 3][0], kGravities[op.arg[1] & 3][1]);
  note("world %d: new, gravity (%g, %g)", w, g.x, g.y);
  if (slots_[w].world) return skip("the slot holds a world");
  slots_[w].world = new b2World(g);
  ++result_.played;
}

void Player::create_body(const WorldOp& op) {
  const std::optional<int> w = world_of(op.arg[0]);
  const int k = op.arg[1] & 3;
  b2BodyDef def;
  def.type = body_type(k);
  def.bullet = k == 3;
  def.position = position(op.arg[2], op.arg[3], op.arg[4]);
  def.angle = s8(op.arg[5]) * kPi / 64;
  note("world %d: create %s body %d at (%.9g, %.9g) angle %.9g", op.arg[0] % kWorlds, type_name(k),
       w ? static_cast<int>(slots_[*w].bodies.size()) : -1, def.position.x, def.position.y,
       def.angle);
  if (!w) return skip("no such world");
  if (bodies_ >= max_bodies) return skip("body bound");
  slots_[*w].bodies.push_back(slots_[*w].world->CreateBody(&def));
  ++bodies_;
  ++result_.played;
}

// arg[1]: bits 0-2 scale, 3-4 form (any, any, sliver, needle), 5-7 the fixture (`fixture_def`'s
// bits 0-2); arg[2..4]: the vertices' grid coordinates (nibbles, in scale units); arg[5]: an offset
// from the body's origin (nibbles, 4 scale units each); arg[6]: thinness, density, sensor bits.
void Player::add_triangle(b2Body& body, const WorldOp& op) {
  const float s = kScales[op.arg[1] & 7];
  const int form = (op.arg[1] >> 3) & 3;
  const b2Vec2 offset(4 * s * lo(op.arg[5]), 4 * s * hi(op.arg[5]));
  b2Vec2 v[3];
  for (int i = 0; i < 3; ++i) {
    v[i] = offset + s * b2Vec2(lo(op.arg[2 + i]), hi(op.arg[2 + i]));
  }
  if (form >= 2) {
    const b2Vec2 d = v[1] - v[0];
    const b2Vec2 normal(-d.y, d.x);
    const float thin = kThin[op.arg[6] & 3];
    v[2] = form == 2 ? 0.5f * (v[0] + v[1]) + thin * normal  // sliver: a flat top
                     : v[1] + 0.5f * d + thin * normal;      // needle: a long thin spike
  }
  const char* forms[4] = {"triangle", "triangle", "sliver", "needle"};
  note("body %d of world %d: add %s (%.9g, %.9g) (%.9g, %.9g) (%.9g, %.9g)", index_of(&body),
       where(&body), forms[form], v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
  if (const char* why = polygon_refusal(v, 3)) return skip(why);
  if (!room_for_fixtures(1)) return;
  b2PolygonShape shape;
  if (!set_polygon(shape, v, 3)) return skip("Box2D 2.4.2's hull refuses these points");
  add_fixture(body, shape, static_cast<std::uint8_t>((op.arg[1] >> 5) | (op.arg[6] & 0x38)));
  ++result_.played;
}

// arg[1]: bits 0-2 cell size, bit 3 a T-junction (cell 0 split at its right edge's midpoint), bit 4
// the other diagonal; arg[2]: cells across (1-4, low nibble) and up (1-3, high nibble); arg[3]: an
// offset (nibbles, a cell each); arg[4]: the slope of the top row; arg[5]: the fixture's bits.
void Player::add_mesh(b2Body& body, const WorldOp& op) {
  const float s = kScales[op.arg[1] & 7];
  const bool t_junction = (op.arg[1] & 8) != 0;
  const bool other_diagonal = (op.arg[1] & 16) != 0;
  const int nx = 1 + (op.arg[2] & 15) % 4;
  const int ny = 1 + (op.arg[2] >> 4) % 3;
  const b2Vec2 offset(s * lo(op.arg[3]), s * hi(op.arg[3]));
  const int slope = op.arg[4] % 4;
  std::vector<b2Vec2> vertices;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const float lift = j == ny ? 0.25f * static_cast<float>((i * slope) % 3) : 0.0f;
      vertices.push_back(offset + s * b2Vec2(static_cast<float>(i), static_cast<float>(j) + lift));
    }
  }
  auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  std::vector<int> indices;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (t_junction && i == 0 && j == 0 && nx > 1) {
        vertices.push_back(0.5f * (vertices[b] + vertices[c]));
        const int m = static_cast<int>(vertices.size()) - 1;
        indices.insert(indices.end(), {a, b, m, a, m, d, d, m, c});
      } else if (other_diagonal) {
        indices.insert(indices.end(), {a, b, d, b, c, d});
      } else {
        indices.insert(indices.end(), {a, b, c, a, c, d});
      }
    }
  }
  const int triangles = static_cast<int>(indices.size()) / 3;
  note("body %d of world %d: add_triangles %dx%d cells of %.9g at (%.9g, %.9g)%s%s, %d triangles",
       index_of(&body), where(&body), nx, ny, s, offset.x, offset.y,
       t_junction ? ", T-junction" : "", other_diagonal ? ", other diagonal" : "", triangles);
  for (int t = 0; t < triangles; ++t) {
    const b2Vec2 v[3] = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
                         vertices[indices[3 * t + 2]]};
    if (const char* why = polygon_refusal(v, 3)) return skip(why);
  }
  if (!room_for_fixtures(triangles)) return;
  const box2d::MeshResult r =
      box2d::add_triangles(body, vertices.data(), static_cast<int>(vertices.size()), indices.data(),
                           static_cast<int>(indices.size()), fixture_def(op.arg[5]));
  if (!r.ok()) return skip(r.message);
  fixtures_ += triangles;
  ++result_.played;
}

// arg[1]: bits 0-2 radius, bits 3-5 vertices (4-8); arg[2]: a turn; arg[3]: a stretch along x;
// arg[4]: centre (nibbles, a radius each); arg[5]: the fixture's bits.
void Player::add_polygon(b2Body& body, const WorldOp& op) {
  const float r = kScales[op.arg[1] & 7];
  const int n = 4 + ((op.arg[1] >> 3) & 7) % 5;
  const float turn = s8(op.arg[2]) * kPi / 128;
  const float stretch = 1.0f + 0.25f * static_cast<float>(op.arg[3] % 8);
  const b2Vec2 centre(r * lo(op.arg[4]), r * hi(op.arg[4]));
  b2Vec2 v[b2_maxPolygonVertices];
  for (int i = 0; i < n; ++i) {
    const float a = turn + 2 * kPi * static_cast<float>(i) / static_cast<float>(n);
    v[i] = centre + b2Vec2(stretch * r * std::cos(a), r * std::sin(a));
  }
  note("body %d of world %d: add %d-gon radius %.9g stretch %.9g at (%.9g, %.9g)", index_of(&body),
       where(&body), n, r, stretch, centre.x, centre.y);
  if (const char* why = polygon_refusal(v, n)) return skip(why);
  if (!room_for_fixtures(1)) return;
  b2PolygonShape shape;
  if (!set_polygon(shape, v, n)) return skip("Box2D 2.4.2's hull refuses these points");
  add_fixture(body, shape, op.arg[5]);
  ++result_.played;
}

// arg[1]: bits 0-2 radius; arg[2]: centre (nibbles, a radius each); arg[3]: the fixture's bits.
void Player::add_circle(b2Body& body, const WorldOp& op) {
  b2CircleShape shape;
  shape.m_radius = kScales[op.arg[1] & 7];
  shape.m_p.Set(shape.m_radius * lo(op.arg[2]), shape.m_radius * hi(op.arg[2]));
  note("body %d of world %d: add circle radius %.9g at (%.9g, %.9g)", index_of(&body), where(&body),
       shape.m_radius, shape.m_p.x, shape.m_p.y);
  if (!room_for_fixtures(1)) return;
  add_fixture(body, shape, op.arg[3]);
  ++result_.played;
}

// arg[1]: bits 0-2 scale, bit 3 one-sided, bits 4-5 where its ghost vertices turn (straight on,
// up, down, back); arg[2], arg[3]: its ends (nibbles, in scale units); arg[4]: the fixture's bits.
void Player::add_edge(b2Body& body, const WorldOp& op) {
  const float s = kScales[op.arg[1] & 7];
  const bool one_sided = (op.arg[1] & 8) != 0;
  const b2Vec2 v1 = s * b2Vec2(lo(op.arg[2]), hi(op.arg[2]));
  const b2Vec2 v2 = s * b2Vec2(lo(op.arg[3]), hi(op.arg[3]));
  const b2Vec2 d = v2 - v1;
  const b2Vec2 turns[4] = {d, d + b2Vec2(-d.y, d.x), d + b2Vec2(d.y, -d.x), -0.5f * d};
  const b2Vec2 ghost = turns[(op.arg[1] >> 4) & 3];
  note("body %d of world %d: add %s edge (%.9g, %.9g) (%.9g, %.9g)", index_of(&body), where(&body),
       one_sided ? "one-sided" : "two-sided", v1.x, v1.y, v2.x, v2.y);
  if (!room_for_fixtures(1)) return;
  b2EdgeShape shape;
  if (one_sided) {
    shape.SetOneSided(v1 - ghost, v1, v2, v2 + ghost);
  } else {
    shape.SetTwoSided(v1, v2);
  }
  add_fixture(body, shape, op.arg[4]);
  ++result_.played;
}

// arg[1]: bits 0-2 scale, bit 3 a loop, bits 4-6 vertices (2-9; a loop 3-9); arg[2..5]: the
// steps from one vertex to the next (nibbles, in scale units, the last repeated); arg[6]: the
// fixture's bits.
void Player::add_chain(b2Body& body, const WorldOp& op) {
  const float s = kScales[op.arg[1] & 7];
  const bool loop = (op.arg[1] & 8) != 0;
  const int n = (loop ? 3 : 2) + ((op.arg[1] >> 4) & 7);
  std::vector<b2Vec2> v(1, b2Vec2(0, 0));
  for (int i = 1; i < n; ++i) {
    const std::uint8_t step = op.arg[2 + std::min(i - 1, 3)];
    v.push_back(v.back() + s * b2Vec2(lo(step), hi(step)));
  }
  note("body %d of world %d: add %s chain of %d vertices from (0, 0) to (%.9g, %.9g)",
       index_of(&body), where(&body), loop ? "loop" : "open", n, v.back().x, v.back().y);
  // b2ChainShape asserts on vertices closer than b2_linearSlop, the loop's closing one too.
  for (int i = 0; i + 1 < n + (loop ? 1 : 0); ++i) {
    if (b2DistanceSquared(v[static_cast<std::size_t>(i)],
                          v[static_cast<std::size_t>((i + 1) % n)]) <=
        b2_linearSlop * b2_linearSlop) {
      return skip("chain vertices too close (Box2D asserts)");
    }
  }
  if (!room_for_fixtures(1)) return;
  b2ChainShape shape;
  if (loop) {
    shape.CreateLoop(v.data(), n);
  } else {
    shape.CreateChain(v.data(), n, v.front() - (v[1] - v[0]), v.back() + (v.back() - v[n - 2]));
  }
  add_fixture(body, shape, op.arg[6]);
  ++result_.played;
}

void Player::body_op(b2Body& body, const WorldOp& op) {
  const int w = where(&body);
  const int i = index_of(&body);
  switch (op.kind) {
    case OpKind::DestroyBody:
      note("body %d of world %d: destroy", i, w);
      fixtures_ -= fixture_count(body);
      slots_[w].bodies.erase(slots_[w].bodies.begin() + i);
      slots_[w].world->DestroyBody(&body);
      --bodies_;
      break;
    case OpKind::AddTriangle:
      return add_triangle(body, op);
    case OpKind::AddMesh:
      return add_mesh(body, op);
    case OpKind::AddPolygon:
      return add_polygon(body, op);
    case OpKind::AddCircle:
      return add_circle(body, op);
    case OpKind::AddEdge:
      return add_edge(body, op);
    case OpKind::AddChain:
      return add_chain(body, op);
    case OpKind::DestroyFixture: {
      const int n = fixture_count(body);
      note("body %d of world %d: destroy fixture %d of %d", i, w, n ? op.arg[1] % n : 0, n);
      if (n == 0) return skip("no fixture");
      b2Fixture* f = body.GetFixtureList();
      for (int k = op.arg[1] % n; k > 0; --k) f = f->GetNext();
      body.DestroyFixture(f);
      --fixtures_;
      break;
    }
    case OpKind::Teleport: {
      const b2Vec2 p = position(op.arg[1], op.arg[2], op.arg[3]);
      const float angle = s8(op.arg[4]) * kPi / 64;
      note("body %d of world %d: teleport to (%.9g, %.9g) angle %.9g", i, w, p.x, p.y, angle);
      body.SetTransform(p, angle);
      break;
    }
    case OpKind::SetType: {
      const int k = op.arg[1] & 3;
      note("body %d of world %d: make %s", i, w, type_name(k));
      body.SetType(body_type(k));
      body.SetBullet(k == 3);
      break;
    }
    case OpKind::SetEnabled:
      note("body %d of world %d: %s", i, w, (op.arg[1] & 1) ? "disable" : "enable");
      body.SetEnabled((op.arg[1] & 1) == 0);
      break;
    case OpKind::SetVelocity: {
      const float speed = kSpeeds[op.arg[1] & 3] / 16;
      const b2Vec2 v(speed * s8(op.arg[2]), speed * s8(op.arg[3]));
      const float spin = speed * s8(op.arg[4]);
      note("body %d of world %d: velocity (%.9g, %.9g) spin %.9g", i, w, v.x, v.y, spin);
      body.SetLinearVelocity(v);
      body.SetAngularVelocity(spin);
      break;
    }
    case OpKind::ApplyImpulse: {
      // Impulses of a velocity change: a body's mass can be anything from 1e-6 kg to 1e9 kg.
      const float speed = kSpeeds[op.arg[1] & 3] / 16;
      const b2Vec2 dv(speed * s8(op.arg[2]), speed * s8(op.arg[3]));
      const b2Vec2 arm(0.25f * lo(op.arg[4]), 0.25f * hi(op.arg[4]));
      const float spin = speed * s8(op.arg[5]);
      note("body %d of world %d: impulse of %.9g·(%.9g, %.9g) at centre + (%.9g, %.9g), spin %.9g",
           i, w, body.GetMass(), dv.x, dv.y, arm.x, arm.y, spin);
      body.ApplyLinearImpulse(body.GetMass() * dv, body.GetWorldCenter() + arm, true);
      body.ApplyAngularImpulse(body.GetInertia() * spin, true);
      break;
    }
    case OpKind::FixEdges:
      note("body %d of world %d: fix_internal_edges", i, w);
      box2d::fix_internal_edges(body);
      break;
    default:
      return skip("not a body operation");
  }
  ++result_.played;
}

// arg[0]: backend (modulo 6); arg[1]: bits 0-3 clear bounds_early_out, warm_axis,
// lin_canny_cache, internal_edges; arg[2]: recycle distance.
void Player::install(const WorldOp& op) {
  const Backend written = box2d::all_backends[op.arg[0] % box2d::backend_count];
  box2d::Config c;
  c.bounds_early_out = (op.arg[1] & 1) == 0;
  c.warm_axis = (op.arg[1] & 2) == 0;
  c.lin_canny_cache = (op.arg[1] & 4) == 0;
  c.internal_edges = (op.arg[1] & 8) == 0;
  c.recycle_distance = kRecycle[op.arg[2] & 3];
  c.edges_and_chains = (op.arg[1] & 16) == 0;
  c.triangles_only = (op.arg[1] & 32) != 0;
  note(
      "install %s (bounds %d, warm axis %d, lin-canny cache %d, internal edges %d, recycle %g, "
      "edges and chains %d, triangles only %d)",
      box2d::name(written), c.bounds_early_out, c.warm_axis, c.lin_canny_cache, c.internal_edges,
      c.recycle_distance, c.edges_and_chains, c.triangles_only);
  ++result_.played;
  const Backend backend = installs_ == Installs::Box2D  ? Backend::Box2D
                          : installs_ == Installs::Dyop ? Backend::Dyop
                          : installs_ == Installs::Sat  ? Backend::Sat
                                                        : written;
  if (installs_ != Installs::Never) box2d::install(backend, c);
}

// arg[0]: world (3: every world, in slot order); arg[1]: time step; arg[2]: velocity iterations
// (0-12); arg[3]: position iterations (0-8); arg[4]: repeats (1-4).
void Player::step(const WorldOp& op) {
  const int which = op.arg[0] % (kWorlds + 1);
  const float dt = kTimeSteps[op.arg[1] & 7];
  const int velocity_iterations = op.arg[2] % 13;
  const int position_iterations = op.arg[3] % 9;
  const int repeats = 1 + op.arg[4] % 4;
  char target[16] = "every world";
  if (which < kWorlds) std::snprintf(target, sizeof target, "world %d", which);
  note("step %s x%d: dt %.9g, iterations %d/%d", target, repeats, dt, velocity_iterations,
       position_iterations);
  for (int r = 0; r < repeats; ++r) {
    if (result_.steps >= max_steps) return skip("step bound");
    ++result_.steps;
    ++result_.played;
    for (int w = 0; w < kWorlds; ++w) {
      Slot& s = slots_[w];
      if (!s.world || (which != kWorlds && which != w)) continue;
      s.world->Step(dt, velocity_iterations, position_iterations);
      for (std::size_t b = 0; b < s.bodies.size(); ++b) {
        const b2Transform& xf = s.bodies[b]->GetTransform();
        if (std::isfinite(xf.p.x) && std::isfinite(xf.p.y) && std::isfinite(xf.q.s) &&
            std::isfinite(xf.q.c) && std::isfinite(s.bodies[b]->GetAngle())) {
          continue;
        }
        if (result_.finite) note("  world %d body %zu is not finite", w, b);
        result_.finite = false;
      }
    }
  }
}

void Player::world_op(int w, const WorldOp& op) {
  b2World& world = *slots_[w].world;
  switch (op.kind) {
    case OpKind::EndWorld: {
      const bool destroy = (op.arg[1] & 1) == 0;
      note("world %d: %s", w, destroy ? "destroy its bodies, delete" : "delete");
      fold(w);
      bodies_ -= static_cast<int>(slots_[w].bodies.size());
      for (const b2Body* b : slots_[w].bodies) fixtures_ -= fixture_count(*b);
      end_world(w, destroy);
      break;
    }
    case OpKind::FixEdges:
      note("world %d: fix_internal_edges", w);
      box2d::fix_internal_edges(world);
      break;
    case OpKind::RefreshEdges: {
      const b2Vec2 c = position(op.arg[1], op.arg[2], op.arg[3]);
      const float h = 4 * kScales[op.arg[4] & 7];
      const b2AABB box{c - b2Vec2(h, h), c + b2Vec2(h, h)};
      const int n = box2d::refresh_internal_edges(world, box);
      note("world %d: refresh_internal_edges around (%.9g, %.9g) +-%.9g: %d", w, c.x, c.y, h, n);
      break;
    }
    case OpKind::ForgetEdges:
      note("world %d: forget_internal_edges", w);
      box2d::forget_internal_edges(world);
      break;
    case OpKind::WorldFlags: {
      const std::uint8_t f = op.arg[1];
      note("world %d: sleeping %d, warm starting %d, continuous %d, sub-stepping %d", w,
           (f & 1) == 0, (f & 2) == 0, (f & 4) == 0, (f & 8) != 0);
      world.SetAllowSleeping((f & 1) == 0);
      world.SetWarmStarting((f & 2) == 0);
      world.SetContinuousPhysics((f & 4) == 0);
      world.SetSubStepping((f & 8) != 0);
      break;
    }
    default:
      return skip("not a world operation");
  }
  ++result_.played;
}

}  // namespace

PlayResult play_world_ops(const std::vector<WorldOp>& ops, Installs installs, std::FILE* log) {
  Player player(installs, log);
  for (const WorldOp& op : ops) player.run(op);
  WorldOp last;  // every world one more step, so that whatever the operations built is simulated
  last.kind = OpKind::Step;
  last.arg = {kWorlds, 0, 8, 3};
  player.run(last);
  return player.result();
}

}  // namespace dyop::fuzz
