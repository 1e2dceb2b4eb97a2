#include "scenes/world_scene.hpp"

#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "dyop/box2d_internal_edges.hpp"

namespace dyop::scenes {
namespace {

bool finite(const b2Vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

bool finite_state(const b2Body* b) {
  return finite(b->GetPosition()) && std::isfinite(b->GetAngle()) &&
         finite(b->GetLinearVelocity()) && std::isfinite(b->GetAngularVelocity());
}

// A body-frame point in world coordinates, in double: exact enough 10 km from the origin.
Vec2<double> world_point(const b2Transform& xf, const b2Vec2& v) {
  const double c = xf.q.c, s = xf.q.s;
  return {double(xf.p.x) + c * v.x - s * v.y, double(xf.p.y) + s * v.x + c * v.y};
}

}  // namespace

WorldScene::WorldScene(std::string name, const Runner& runner, std::uint64_t seed,
                       const box2d::Config& skips, const WorldBuilder& build)
    : name_(std::move(name)),
      runner_(runner),
      seed_(seed),
      skips_(skips),
      installation_(runner, skips),
      world_(std::make_unique<World>()) {
  workloads::Random rng(seed);
  build_ = build(*world_, rng);
  if (build_.fix_edge_data) box2d::fix_internal_edges(world_->get());
  for (const Slider& s : build_.sliders) slider_start_x_.push_back(s.body->GetPosition().x);
  // Box2D's own contact answers as `b2CollidePolygons`, which is what the probe checks for `box2d`.
  probe_ = std::make_unique<ContactProbe>(runner.value_or(box2d::Backend::Box2D));
}

WorldScene::~WorldScene() {
  if (spawned_) world_->get().DestroyBody(spawned_);
  world_.reset();
}

void WorldScene::spawn_far_away() { spawning_ = true; }

void WorldScene::check_manifolds() {
  if (manifold_check_) return;
  manifold_check_ = std::make_unique<ManifoldCheck>();
  world_->get().SetContactListener(manifold_check_.get());
}

void WorldScene::step() {
  if (build_.before_step) build_.before_step(steps_);
  if (spawning_ && spawned_) {
    world_->get().DestroyBody(spawned_);
    spawned_ = nullptr;
  } else if (spawning_) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(spawn_distance, spawn_distance);
    spawned_ = world_->get().CreateBody(&def);
    b2PolygonShape triangle;
    const b2Vec2 corners[3] = {b2Vec2(0.0f, 0.0f), b2Vec2(1.0f, 0.0f), b2Vec2(0.0f, 1.0f)};
    triangle.Set(corners, 3);
    spawned_->CreateFixture(&triangle, 1.0f);
  }
  const bool measured = steps_ > 0;  // step 1's contacts are created inside Step
  const ContactProbe::Updates u = probe_->before_step(world_->get(), errors_);

  const auto start = std::chrono::steady_clock::now();
  world_->step();
  const auto end = std::chrono::steady_clock::now();
  ++steps_;
  step_ms_.push_back(std::chrono::duration<double, std::milli>(end - start).count());
  if (measured) {
    step_ms_measured_ += step_ms_.back();
    collide_ms_ += world_->get().GetProfile().collide;
    solve_toi_ms_ += world_->get().GetProfile().solveTOI;
    updates_.contacts += u.contacts;
    updates_.triangles += u.triangles;
  }

  if (measured) {
    for (const b2Contact* c = world_->get().GetContactList(); c != nullptr; c = c->GetNext()) {
      toi_swept_ += static_cast<std::uint64_t>(toi_swept(*c));
    }
  }
  ContactProbe::measure_penetration(world_->get(), penetration_);
  for (const b2Body* b : world_->bodies()) nan_ = nan_ || !finite_state(b);
  if (steps_ == settle_steps) {
    for (const b2Body* b : build_.watched) watched_start_.push_back(b->GetPosition());
  }
  for (std::size_t i = 0; i < watched_start_.size(); ++i) {
    const double d = (build_.watched[i]->GetPosition() - watched_start_[i]).Length();
    top_displacement_ = std::max(top_displacement_, d);
  }
  for (Slider& s : build_.sliders) {
    SliderFigures& f = s.figures;
    f.max_vertical_speed =
        std::max(f.max_vertical_speed, double(std::abs(s.body->GetLinearVelocity().y)));
    f.max_angular_speed =
        std::max(f.max_angular_speed, double(std::abs(s.body->GetAngularVelocity())));
  }
}

SceneMetrics WorldScene::metrics() const {
  SceneMetrics m;
  m.scene = name_;
  m.runner = runner_;
  m.seed = seed_;
  m.steps = steps_;
  for (const b2Body* b : world_->bodies()) {
    ++m.bodies;
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      m.triangles += is_triangle(f);
    }
    if (b->GetType() == b2_dynamicBody) {
      // GetInertia is about the body origin; the energy wants it about the centre of mass.
      const double mass = b->GetMass();
      const double inertia =
          b->GetInertia() - mass * b2Dot(b->GetLocalCenter(), b->GetLocalCenter());
      const double v2 = b2Dot(b->GetLinearVelocity(), b->GetLinearVelocity());
      const double w = b->GetAngularVelocity();
      m.kinetic_energy_final += 0.5 * mass * v2 + 0.5 * inertia * w * w;
    }
  }
  m.hash = state_hash(*world_);
  m.triangle_pairs = updates_.triangles;
  m.contact_updates = updates_.contacts;
  m.toi_swept = toi_swept_;
  if (runner_) {  // the plug-in's counters mean nothing when Box2D's own contact answers
    const box2d::Stats s = box2d::stats();
    m.plugin_evaluations = s.evaluations();
    m.fallbacks = s.fallbacks;
    m.skip_config = skips_;
    m.skips = s.skipped;
    m.recycled = s.recycled;
    m.contacts_made = s.contacts;
    m.answered = s.answered();
  }
  m.step_ms_median = median(step_ms_);
  m.step_ms_total = step_ms_measured_;
  m.narrowphase_ms_total = collide_ms_;
  m.solve_toi_ms_total = solve_toi_ms_;
  m.narrowphase_ns_per_pair =
      updates_.contacts > 0 ? collide_ms_ * 1e6 / static_cast<double>(updates_.contacts) : 0;
  add_accuracy(errors_, penetration_, m);
  if (!watched_start_.empty()) m.top_displacement = top_displacement_;
  if (manifold_check_) m.manifold_errors = manifold_check_->errors();
  if (!build_.sliders.empty()) {
    std::vector<SliderFigures> sliders;
    const double seconds = steps_ * double(time_step);
    for (std::size_t i = 0; i < build_.sliders.size(); ++i) {
      const Slider& s = build_.sliders[i];
      sliders.push_back(s.figures);
      const double travelled = s.body->GetPosition().x - slider_start_x_[i];
      sliders.back().travel = steps_ > 0 ? travelled / (s.speed * seconds) : 0;
    }
    m.slide = summarize_sliders(std::move(sliders));
  }
  m.nan_detected = nan_ || !all_finite(m);
  return m;
}

Drawing WorldScene::drawing() const {
  Drawing d;
  d.title = name_ + " / " + name(runner_) + ", seed " + std::to_string(seed_) + ", step " +
            std::to_string(steps_);
  for (const b2Body* b : world_->bodies()) {
    DrawShape::Role role = b->GetType() == b2_staticBody      ? DrawShape::Role::Static
                           : b->GetType() == b2_kinematicBody ? DrawShape::Role::Kinematic
                                                              : DrawShape::Role::Dynamic;
    const b2Transform& xf = b->GetTransform();
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      DrawShape s;
      s.role = role;
      switch (f->GetType()) {
        case b2Shape::e_polygon: {
          const auto* p = static_cast<const b2PolygonShape*>(f->GetShape());
          for (int i = 0; i < p->m_count; ++i)
            s.points.push_back(world_point(xf, p->m_vertices[i]));
          break;
        }
        case b2Shape::e_circle: {
          const auto* c = static_cast<const b2CircleShape*>(f->GetShape());
          s.kind = DrawShape::Kind::Circle;
          s.radius = c->m_radius;
          s.points.push_back(world_point(xf, c->m_p));
          s.points.push_back(world_point(xf, c->m_p + b2Vec2(c->m_radius, 0.0f)));
          break;
        }
        case b2Shape::e_edge: {
          const auto* e = static_cast<const b2EdgeShape*>(f->GetShape());
          s.kind = DrawShape::Kind::Segment;
          s.points.push_back(world_point(xf, e->m_vertex1));
          s.points.push_back(world_point(xf, e->m_vertex2));
          break;
        }
        default:
          continue;  // the scenes make no chains
      }
      d.shapes.push_back(std::move(s));
    }
  }
  return d;
}

}  // namespace dyop::scenes
