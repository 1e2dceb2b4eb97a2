#include "experiments/lockstep_recording.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "experiments/reference_face.hpp"
#include "scenes/installation.hpp"
#include "scenes/paper.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_world.hpp"

namespace dyop::experiments {
namespace {

using scenes::DrawShape;

ViewManifold view_of(const b2Manifold& m, const b2Transform& xf_a, const b2Shape& a,
                     const b2Transform& xf_b, const b2Shape& b) {
  ViewManifold v;
  v.points = m.pointCount;
  if (v.points == 0) return v;
  b2WorldManifold w;
  w.Initialize(&m, xf_a, a.m_radius, xf_b, b.m_radius);
  v.reference = m.type == b2Manifold::e_circles ? ViewManifold::Reference::Circles
                : m.type == b2Manifold::e_faceA ? ViewManifold::Reference::FaceA
                                                : ViewManifold::Reference::FaceB;
  const b2Shape& ref = m.type == b2Manifold::e_faceA ? a : b;
  if (m.type != b2Manifold::e_circles && ref.GetType() == b2Shape::e_polygon) {
    v.reference_edge = reference_edge(m, static_cast<const b2PolygonShape&>(ref));
  }
  v.normal = w.normal;
  v.local_normal = m.localNormal;
  v.local_point = m.localPoint;
  for (int i = 0; i < v.points; ++i) {
    v.point[i] = {w.points[i], w.separations[i], m.points[i].id.key, m.points[i].localPoint};
  }
  return v;
}

double angle_between(const b2Vec2& u, const b2Vec2& v) {
  return std::atan2(std::abs(double(b2Cross(u, v))), double(b2Dot(u, v)));
}

// The plug-in's manifold against Box2D's on the same pose.
EdgeMark mark_of(const ViewManifold& plugin, const ViewManifold& box2d) {
  if (box2d.points > 0 && plugin.points == 0) return EdgeMark::Removed;
  if (box2d.points > 0 && angle_between(plugin.normal, box2d.normal) > redirect_angle) {
    return EdgeMark::Redirected;
  }
  return EdgeMark::None;
}

DrawShape::Role role_of(const b2Body& b) {
  return b.GetType() == b2_staticBody      ? DrawShape::Role::Static
         : b.GetType() == b2_kinematicBody ? DrawShape::Role::Kinematic
                                           : DrawShape::Role::Dynamic;
}

ViewFixture segment_of(int body, const b2EdgeShape& e) {
  ViewFixture f;
  f.body = body;
  f.radius = e.m_radius;
  f.kind = DrawShape::Kind::Segment;
  f.points = {e.m_vertex1, e.m_vertex2};
  return f;
}

ViewFixture fixture_of(int body, const b2Shape& shape) {
  if (shape.GetType() == b2Shape::e_edge) {
    return segment_of(body, static_cast<const b2EdgeShape&>(shape));
  }
  ViewFixture f;
  f.body = body;
  f.radius = shape.m_radius;
  switch (shape.GetType()) {
    case b2Shape::e_polygon: {
      const auto& p = static_cast<const b2PolygonShape&>(shape);
      f.points.assign(p.m_vertices, p.m_vertices + p.m_count);
      break;
    }
    case b2Shape::e_circle:
      f.kind = DrawShape::Kind::Circle;
      f.points.push_back(static_cast<const b2CircleShape&>(shape).m_p);
      break;
    default:
      break;  // edges: `segment_of`; chains: one segment per child (`index_of`)
  }
  return f;
}

BodyPose pose_of(const b2Body& b) { return {b.GetPosition().x, b.GetPosition().y, b.GetAngle()}; }

// A contact's frame entry: kept when touching or when the plug-in removed Box2D's points.
void add_contact(ViewFrame& frame, ViewContact&& c) {
  if (c.manifold.points == 0 && c.mark == EdgeMark::None) return;
  for (int i = 0; i < c.manifold.points; ++i) {
    frame.max_penetration =
        std::max(frame.max_penetration, -double(c.manifold.point[i].separation));
  }
  frame.contacts.push_back(std::move(c));
}

// Box2D's code on the poses the step's narrow phase saw (`collide_*`), placed at the poses after
// the step (`now_*`) as the plug-in's manifold is, and the mark it gives `v`.
void mark_against_box2d(ViewContact& v, const b2PolygonShape& a, const b2Transform& collide_a,
                        const b2Transform& now_a, const b2PolygonShape& b,
                        const b2Transform& collide_b, const b2Transform& now_b) {
  b2Manifold reference;
  b2CollidePolygons(&reference, &a, collide_a, &b, collide_b);
  const ViewManifold box2d = view_of(reference, now_a, a, now_b, b);
  v.mark = mark_of(v.manifold, box2d);
  if (v.mark != EdgeMark::None) v.box2d = box2d;
}

// The frame's contacts sorted by (fixture_a, fixture_b).
void sort_contacts(ViewFrame& frame) {
  std::sort(frame.contacts.begin(), frame.contacts.end(),
            [](const ViewContact& x, const ViewContact& y) {
              return std::pair(x.fixture_a, x.fixture_b) < std::pair(y.fixture_a, y.fixture_b);
            });
}

// The frame, its contacts sorted, after the others.
void add_frame(std::vector<ViewFrame>& frames, ViewFrame&& frame) {
  sort_contacts(frame);
  frames.push_back(std::move(frame));
}

// A world's bodies and fixtures as indices, in creation order and fixture-list order, a chain's
// children one segment fixture each (at its fixture's index plus the child's).
struct WorldIndex {
  std::unordered_map<const b2Body*, int> body;
  std::unordered_map<const b2Fixture*, int> fixture;  // its first child's
  std::vector<DrawShape::Role> roles;
  std::vector<ViewFixture> fixtures;
  int of(const b2Fixture* f, int child) const { return fixture.at(f) + child; }
};

// Adds fixture `f` of body `body` to `index`, a chain as its children, from frame `appears` on.
void add_fixture(WorldIndex& index, int body, const b2Fixture* f, int appears) {
  index.fixture[f] = static_cast<int>(index.fixtures.size());
  if (f->GetType() != b2Shape::e_chain) {
    index.fixtures.push_back(fixture_of(body, *f->GetShape()));
    index.fixtures.back().appears = appears;
    return;
  }
  const auto* chain = static_cast<const b2ChainShape*>(f->GetShape());
  for (int child = 0; child < chain->GetChildCount(); ++child) {
    b2EdgeShape edge;
    chain->GetChildEdge(&edge, child);
    index.fixtures.push_back(segment_of(body, edge));
    index.fixtures.back().appears = appears;
  }
}

WorldIndex index_of(const std::vector<b2Body*>& bodies) {
  WorldIndex index;
  for (const b2Body* b : bodies) {
    const int body = static_cast<int>(index.roles.size());
    index.body[b] = body;
    index.roles.push_back(role_of(*b));
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      add_fixture(index, body, f, 0);
    }
  }
  return index;
}

bool same_fixture(const ViewFixture& x, const ViewFixture& y) {
  return x.body == y.body && x.kind == y.kind && x.radius == y.radius && x.appears == y.appears &&
         x.disappears == y.disappears &&
         std::equal(x.points.begin(), x.points.end(), y.points.begin(), y.points.end(),
                    [](const b2Vec2& p, const b2Vec2& q) { return p.x == q.x && p.y == q.y; });
}

// After an edit before frame `step`: the fixtures gone from `bodies`, or whose shape changed (a
// new fixture at a freed address), end at `step`; those new take the next indices from it on.
void reindex(WorldIndex& index, const std::vector<b2Body*>& bodies, int step) {
  std::unordered_map<const b2Fixture*, int> live;
  for (const b2Body* b : bodies) {
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      live[f] = index.body.at(b);
    }
  }
  for (auto it = index.fixture.begin(); it != index.fixture.end();) {
    ViewFixture& was = index.fixtures[static_cast<std::size_t>(it->second)];
    const auto found = live.find(it->first);
    ViewFixture now;
    if (found != live.end() && it->first->GetType() != b2Shape::e_chain) {
      now = fixture_of(found->second, *it->first->GetShape());
      now.appears = was.appears;
    }
    if (found == live.end() ||
        (it->first->GetType() != b2Shape::e_chain && !same_fixture(now, was))) {
      was.disappears = step;
      it = index.fixture.erase(it);
    } else {
      ++it;
    }
  }
  for (const b2Body* b : bodies) {
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      if (index.fixture.count(f) == 0) add_fixture(index, index.body.at(b), f, step);
    }
  }
}

// `world`, its runner installed, stepped `steps` times: its frames, `bodies` and their fixtures
// by `index`; `before_step`, when given, is called before each step and `index` follows the
// fixtures it changes.
std::vector<ViewFrame> record_steps(scenes::World& world, const std::vector<b2Body*>& bodies,
                                    const scenes::Runner& runner, int steps, WorldIndex& index,
                                    const std::function<bool(int)>& before_step = {}) {
  std::vector<b2Transform> before(bodies.size());
  std::vector<ViewFrame> frames;
  for (int step = 0; step < steps; ++step) {
    if (before_step && before_step(step)) reindex(index, bodies, step);
    for (std::size_t i = 0; i < bodies.size(); ++i) before[i] = bodies[i]->GetTransform();
    world.step();
    ViewFrame frame;
    frame.collide_ms = world->GetProfile().collide;
    for (const b2Body* b : bodies) frame.poses.push_back(pose_of(*b));
    for (b2Contact* c = world->GetContactList(); c != nullptr; c = c->GetNext()) {
      const b2Fixture* fa = c->GetFixtureA();
      const b2Fixture* fb = c->GetFixtureB();
      const b2Body* ba = fa->GetBody();
      const b2Body* bb = fb->GetBody();
      ViewContact v;
      v.fixture_a = index.of(fa, c->GetChildIndexA());
      v.fixture_b = index.of(fb, c->GetChildIndexB());
      // A chain's manifold is its child edge's (`b2ChainAndPolygonContact`): the edge is shape A.
      b2EdgeShape edge;
      const b2Shape* shape_a = fa->GetShape();
      if (fa->GetType() == b2Shape::e_chain) {
        static_cast<const b2ChainShape*>(shape_a)->GetChildEdge(&edge, c->GetChildIndexA());
        shape_a = &edge;
      }
      v.manifold = view_of(*c->GetManifold(), ba->GetTransform(), *shape_a, bb->GetTransform(),
                           *fb->GetShape());
      if (runner && fa->GetType() == b2Shape::e_polygon && fb->GetType() == b2Shape::e_polygon) {
        // On the poses the step's Collide saw (time-of-impact re-evaluations, at other poses, can
        // show as marks).
        mark_against_box2d(v, *static_cast<const b2PolygonShape*>(fa->GetShape()),
                           before[index.body.at(ba)], ba->GetTransform(),
                           *static_cast<const b2PolygonShape*>(fb->GetShape()),
                           before[index.body.at(bb)], bb->GetTransform());
      }
      add_contact(frame, std::move(v));
    }
    add_frame(frames, std::move(frame));
  }
  return frames;
}

// A catalogue scene under one runner: both runners' worlds, built from the same seed, have the
// same bodies and fixtures; the first recorded sets the layout.
std::vector<ViewFrame> record_world(const scenes::Runner& runner, const box2d::Config& config,
                                    LockstepRecording& out) {
  const scenes::Installation installed(runner, config);
  scenes::SceneWorld scene(out.scene, out.seed);
  WorldIndex index = index_of(scene.world().bodies());
  if (out.bodies.empty()) {
    out.bodies = index.roles;
    out.fixtures = index.fixtures;
  } else if (index.roles.size() != out.bodies.size() ||
             index.fixtures.size() != out.fixtures.size()) {
    throw std::logic_error("the two runners' worlds of '" + out.scene + "' differ in bodies");
  }
  return record_steps(scene.world(), scene.world().bodies(), runner, out.steps, index);
}

// The paper's triangles on their paths: one kinematic body each, their overlapping pairs handed
// to the runner's collide function (the plug-in's with one memory per pair, as a contact keeps).
std::vector<ViewFrame> record_paper(const scenes::Runner& runner, const box2d::Config& config,
                                    LockstepRecording& out) {
  namespace paper = scenes::paper;
  std::vector<b2PolygonShape> shapes(paper::type_count);
  for (int k = 0; k < paper::type_count; ++k) {
    b2Vec2 v[3];
    for (int i = 0; i < 3; ++i) {
      const Vec2<double>& p = paper::triangle_types()[k][i];
      v[i].Set(float(p.x()), float(p.y()));
    }
    shapes[k].Set(v, 3);
  }
  if (out.bodies.empty()) {
    for (int k = 0; k < paper::type_count; ++k) {
      out.bodies.push_back(DrawShape::Role::Kinematic);
      out.fixtures.push_back(fixture_of(k, shapes[k]));
    }
  }
  // One memory per pair i < j, at i * type_count + j.
  std::vector<box2d::ContactMemory> memory(paper::type_count * paper::type_count);
  std::vector<ViewFrame> frames;
  for (int step = 0; step < out.steps; ++step) {
    const double t = paper::start_time(out.seed) + step * paper::step_seconds;
    ViewFrame frame;
    std::vector<b2Transform> xf(paper::type_count);
    for (int k = 0; k < paper::type_count; ++k) {
      const paper::Pose p = paper::pose(k, t);
      xf[k].Set(b2Vec2(float(p.position.x()), float(p.position.y())), float(p.angle));
      frame.poses.push_back({xf[k].p.x, xf[k].p.y, float(p.angle)});
    }
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::pair<std::pair<int, int>, b2Manifold>> manifolds;
    for (const auto& [i, j] : paper::frame_at(t).pairs) {
      b2Manifold m;
      if (runner) {
        box2d::collide_polygons(&m, *runner, shapes[i], xf[i], shapes[j], xf[j],
                                &memory[i * paper::type_count + j], config);
      } else {
        b2CollidePolygons(&m, &shapes[i], xf[i], &shapes[j], xf[j]);
      }
      manifolds.push_back({{i, j}, m});
    }
    frame.collide_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (const auto& [pair, m] : manifolds) {
      const auto [i, j] = pair;
      ViewContact v;
      v.fixture_a = i;
      v.fixture_b = j;
      v.manifold = view_of(m, xf[i], shapes[i], xf[j], shapes[j]);
      if (runner) mark_against_box2d(v, shapes[i], xf[i], xf[i], shapes[j], xf[j], xf[j]);
      add_contact(frame, std::move(v));
    }
    add_frame(frames, std::move(frame));
  }
  return frames;
}

// Marks each touching contact of `frame` that `other` has touching too, deepest separations
// within the tolerance, and counts.
void agree(ViewFrame& frame, const ViewFrame& other) {
  std::map<std::pair<int, int>, float> deepest;
  for (const ViewContact& c : other.contacts) {
    if (c.manifold.points == 0) continue;
    deepest[std::minmax(c.fixture_a, c.fixture_b)] = c.manifold.deepest();
  }
  for (ViewContact& c : frame.contacts) {
    if (c.manifold.points == 0) continue;
    ++frame.touching;
    const auto hit = deepest.find(std::minmax(c.fixture_a, c.fixture_b));
    c.agrees = hit != deepest.end() &&
               std::abs(double(hit->second) - double(c.manifold.deepest())) <= agreement_tolerance;
    frame.agreeing += c.agrees;
  }
}

// Marks what the two runners agree on, step by step.
void agree_frames(LockstepRecording& out) {
  for (int step = 0; step < out.steps; ++step) {
    agree(out.frames[0][step], out.frames[1][step]);
    agree(out.frames[1][step], out.frames[0][step]);
  }
}

// A recording's header, before any frame; `steps` must be at least 1.
LockstepRecording empty_recording(std::string name, const std::array<scenes::Runner, 2>& runners,
                                  int steps, const std::array<box2d::Config, 2>& configs,
                                  double time_step) {
  if (steps < 1) throw std::invalid_argument("a recording needs at least 1 step");
  LockstepRecording out;
  out.scene = std::move(name);
  out.steps = steps;
  out.runners = runners;
  out.configs = configs;
  out.time_step = time_step;
  return out;
}

}  // namespace

float ViewManifold::deepest() const {
  if (points == 0) return 0;
  return points == 1 ? point[0].separation : std::min(point[0].separation, point[1].separation);
}

LockstepRecording record_lockstep(std::string_view name,
                                  const std::array<scenes::Runner, 2>& runners, int steps,
                                  std::uint64_t seed, const std::array<box2d::Config, 2>& configs) {
  if (scenes::find_scene(name) == nullptr) {
    throw std::invalid_argument("no scene called '" + std::string(name) + "'");
  }
  const bool paper = name == "paper";
  LockstepRecording out =
      empty_recording(std::string(name), runners, steps, configs,
                      paper ? scenes::paper::step_seconds : double(scenes::time_step));
  out.seed = seed;
  for (int r = 0; r < 2; ++r) {
    out.frames[r] = paper ? record_paper(runners[r], configs[r], out)
                          : record_world(runners[r], configs[r], out);
  }
  agree_frames(out);
  return out;
}

LockstepRecording record_sides(std::string name, const std::array<scenes::Runner, 2>& runners,
                               int steps, const std::array<box2d::Config, 2>& configs,
                               const std::function<SideWorld(int side)>& build) {
  LockstepRecording out =
      empty_recording(std::move(name), runners, steps, configs, double(scenes::time_step));
  std::array<WorldIndex, 2> index;
  std::array<int, 2> own_bodies{};
  std::array<int, 2> own_fixtures{};
  for (int side = 0; side < 2; ++side) {
    const scenes::Installation installed(runners[side], configs[side]);
    const SideWorld w = build(side);
    if (!w.world || w.own_bodies < 0 || w.own_bodies > static_cast<int>(w.world->bodies().size())) {
      throw std::logic_error("record_sides: side " + std::to_string(side) + " built no world");
    }
    index[side] = index_of(w.world->bodies());
    own_bodies[side] = w.own_bodies;
    own_fixtures[side] = 0;
    for (const ViewFixture& f : index[side].fixtures) own_fixtures[side] += f.body < w.own_bodies;
    out.frames[side] = record_steps(*w.world, w.world->bodies(), runners[side], steps, index[side]);
  }
  // The layout: A's own bodies and fixtures, B's, then the shared ones (A's and B's alike).
  // `place(own, side, i)`: where side `side`'s item `i` goes, `own` counting each side's own items.
  const auto place = [](const std::array<int, 2>& own, int side, int i) {
    return i < own[side] ? (side == 0 ? 0 : own[0]) + i : own[0] + own[1] + i - own[side];
  };
  const auto body_of = [&](int side, int b) { return place(own_bodies, side, b); };
  const auto fixture_of_side = [&](int side, int f) { return place(own_fixtures, side, f); };
  const auto shared_bodies = [&](int side) {
    return static_cast<int>(index[side].roles.size()) - own_bodies[side];
  };
  const auto shared_fixtures = [&](int side) {
    return static_cast<int>(index[side].fixtures.size()) - own_fixtures[side];
  };
  if (shared_bodies(0) != shared_bodies(1) || shared_fixtures(0) != shared_fixtures(1)) {
    throw std::logic_error("record_sides: the two sides' moving bodies differ");
  }
  out.bodies.resize(index[0].roles.size() + static_cast<std::size_t>(own_bodies[1]));
  out.fixtures.resize(index[0].fixtures.size() + static_cast<std::size_t>(own_fixtures[1]));
  for (int side = 0; side < 2; ++side) {
    for (std::size_t b = 0; b < index[side].roles.size(); ++b) {
      out.bodies[body_of(side, static_cast<int>(b))] = index[side].roles[b];
    }
    for (std::size_t f = 0; f < index[side].fixtures.size(); ++f) {
      ViewFixture v = index[side].fixtures[f];
      const bool own = v.body < own_bodies[side];
      v.body = body_of(side, v.body);
      v.side = own ? side : -1;
      out.fixtures[fixture_of_side(side, static_cast<int>(f))] = std::move(v);
    }
  }
  // Each side's frames in the layout; the other side's own bodies at their first recorded poses
  // (their fixtures are not drawn on this side).
  const std::array<std::vector<BodyPose>, 2> first_poses = {out.frames[0][0].poses,
                                                            out.frames[1][0].poses};
  for (int side = 0; side < 2; ++side) {
    const int other = 1 - side;
    for (ViewFrame& frame : out.frames[side]) {
      std::vector<BodyPose> poses(out.bodies.size());
      for (int b = 0; b < own_bodies[other]; ++b) {
        poses[body_of(other, b)] = first_poses[other][static_cast<std::size_t>(b)];
      }
      for (std::size_t b = 0; b < frame.poses.size(); ++b) {
        poses[body_of(side, static_cast<int>(b))] = frame.poses[b];
      }
      frame.poses = std::move(poses);
      for (ViewContact& c : frame.contacts) {
        c.fixture_a = fixture_of_side(side, c.fixture_a);
        c.fixture_b = fixture_of_side(side, c.fixture_b);
      }
      sort_contacts(frame);
    }
  }
  agree_frames(out);
  return out;
}

LockstepRecording record_edited(std::string name, const std::array<scenes::Runner, 2>& runners,
                                int steps, const std::array<box2d::Config, 2>& configs,
                                const std::function<EditedWorld(int side)>& build) {
  LockstepRecording out =
      empty_recording(std::move(name), runners, steps, configs, double(scenes::time_step));
  std::array<WorldIndex, 2> index;
  for (int side = 0; side < 2; ++side) {
    const scenes::Installation installed(runners[side], configs[side]);
    const EditedWorld w = build(side);
    if (!w.world || w.bodies.empty()) {
      throw std::logic_error("record_edited: side " + std::to_string(side) + " built no world");
    }
    index[side] = index_of(w.bodies);
    out.frames[side] =
        record_steps(*w.world, w.bodies, runners[side], steps, index[side], w.before_step);
  }
  const std::vector<ViewFixture>& a = index[0].fixtures;
  const std::vector<ViewFixture>& b = index[1].fixtures;
  if (index[0].roles != index[1].roles || a.size() != b.size() ||
      !std::equal(a.begin(), a.end(), b.begin(), same_fixture)) {
    throw std::logic_error("record_edited: the two sides' worlds made different fixtures");
  }
  out.bodies = index[0].roles;
  out.fixtures = a;
  agree_frames(out);
  return out;
}

}  // namespace dyop::experiments
