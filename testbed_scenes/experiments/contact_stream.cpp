#include "experiments/contact_stream.hpp"

#include "dyop/box2d_internal_edges.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <unordered_map>

#include "experiments/progress.hpp"
#include "experiments/reference_face.hpp"
#include "scenes/builders.hpp"
#include "scenes/contact_probe.hpp"
#include "scenes/scene.hpp"
#include "scenes/world.hpp"

namespace dyop::experiments {
namespace {

using Clock = std::chrono::steady_clock;

// The timed replays' point counts end here, so that the compiler must do the work it times.
volatile std::uint64_t replay_sink = 0;

const b2PolygonShape* polygon(const b2Fixture* f) {
  return f->GetType() == b2Shape::e_polygon ? static_cast<const b2PolygonShape*>(f->GetShape())
                                            : nullptr;
}

void require_calls(const ContactStream& stream) {
  if (stream.calls.empty()) {
    throw std::invalid_argument("contact stream of '" + stream.scene +
                                "' is empty: nothing to replay");
  }
}

float deepest(const b2WorldManifold& w, int points) {
  return points == 1 ? w.separations[0] : std::min(w.separations[0], w.separations[1]);
}

void agree(const b2Manifold& got, const b2Manifold& ref, const StreamContact& c,
           const StreamCall& call, StreamAgreement& out) {
  ++out.calls;
  if (got.pointCount == ref.pointCount) ++out.same_point_count;
  if (got.pointCount == 0 || ref.pointCount == 0) return;
  ++out.both_points;
  if (got.type == ref.type &&
      reference_edge(got, c.shape_a, c.shape_b) == reference_edge(ref, c.shape_a, c.shape_b))
    ++out.same_face;
  b2WorldManifold wg, wr;
  wg.Initialize(&got, call.xf_a, c.shape_a.m_radius, call.xf_b, c.shape_b.m_radius);
  wr.Initialize(&ref, call.xf_a, c.shape_a.m_radius, call.xf_b, c.shape_b.m_radius);
  const double angle = std::atan2(std::abs(double(b2Cross(wg.normal, wr.normal))),
                                  double(b2Dot(wg.normal, wr.normal)));
  out.normal_angle_max = std::max(out.normal_angle_max, angle);
  const double diff =
      std::abs(double(deepest(wg, got.pointCount)) - double(deepest(wr, ref.pointCount)));
  out.separation_diff_max = std::max(out.separation_diff_max, diff);
}

struct Replay {
  std::uint64_t points = 0;  // points made, so that the work is used
  double seconds = 0;
};

// The whole stream once, through the plug-in's backend or (Box2D's own) `b2CollidePolygons`;
// `memory` holds one entry per contact and is reset first, untimed.
Replay replay_once(const ContactStream& stream, const scenes::Runner& backend,
                   const box2d::Config& config, std::vector<box2d::ContactMemory>& memory) {
  memory.assign(stream.contacts.size(), box2d::ContactMemory{});
  Replay r;
  b2Manifold m;
  const auto start = Clock::now();
  if (backend) {
    for (const StreamCall& call : stream.calls) {
      const StreamContact& c = stream.contacts[static_cast<std::size_t>(call.contact)];
      box2d::collide_polygons(&m, *backend, c.shape_a, call.xf_a, c.shape_b, call.xf_b,
                              &memory[static_cast<std::size_t>(call.contact)], config);
      r.points += static_cast<std::uint64_t>(m.pointCount);
    }
  } else {
    for (const StreamCall& call : stream.calls) {
      const StreamContact& c = stream.contacts[static_cast<std::size_t>(call.contact)];
      b2CollidePolygons(&m, &c.shape_a, call.xf_a, &c.shape_b, call.xf_b);
      r.points += static_cast<std::uint64_t>(m.pointCount);
    }
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

// One timed pass, ns per call: the stream repeated until `min_pass_ms`, memories reset between
// repetitions, so that every repetition starts as the world did.
double timed_pass(const ContactStream& stream, const scenes::Runner& backend,
                  const StreamOptions& options, std::vector<box2d::ContactMemory>& memory) {
  double total = 0;
  std::uint64_t calls = 0;
  do {
    const Replay r = replay_once(stream, backend, options.config, memory);
    replay_sink = replay_sink + r.points;
    total += r.seconds;
    calls += stream.calls.size();
  } while (total * 1e3 < options.min_pass_ms);
  return total * 1e9 / static_cast<double>(calls);
}

const scenes::WorldBuilder* checked_builder(std::string_view name, int steps) {
  const scenes::WorldBuilder* build = scenes::detail::find_builder(name);
  if (build == nullptr) {
    throw std::invalid_argument(scenes::find_scene(name) == nullptr
                                    ? "unknown scene '" + std::string(name) + "'"
                                    : "scene '" + std::string(name) +
                                          "' has no Box2D world: no contact stream");
  }
  if (steps < 2) throw std::invalid_argument("a contact stream needs at least 2 steps");
  return build;
}

}  // namespace

std::uint64_t ContactStream::triangle_calls() const {
  std::uint64_t n = 0;
  for (const StreamCall& c : calls) n += contacts[static_cast<std::size_t>(c.contact)].triangles;
  return n;
}

std::vector<std::string> stream_scenes() {
  std::vector<std::string> out;
  for (const scenes::SceneInfo& s : scenes::scene_catalog()) {
    if (scenes::detail::find_builder(s.name) != nullptr) out.emplace_back(s.name);
  }
  return out;
}

ContactStream record_stream(std::string_view name, int steps, std::uint64_t seed) {
  const scenes::WorldBuilder* build = checked_builder(name, steps);
  box2d::uninstall();

  ContactStream stream;
  stream.scene = std::string(name);
  stream.seed = seed;
  stream.steps = steps;
  scenes::World world;
  workloads::Random rng(seed);
  (*build)(world, rng);
  // The id of every live polygon contact. Keyed by the contact itself: Box2D may reuse a freed
  // contact's memory for a new one, but an ending contact is erased on the pass whose step
  // destroys it, so a reused address always starts a new id.
  std::unordered_map<const b2Contact*, std::int32_t> live;
  world.step();  // step 1: its contacts are created inside Step, unseen beforehand
  for (int step = 2; step <= steps; ++step) {
    for (const b2Contact* c = world->GetContactList(); c != nullptr; c = c->GetNext()) {
      const b2PolygonShape* a = polygon(c->GetFixtureA());
      const b2PolygonShape* b = polygon(c->GetFixtureB());
      if (a == nullptr || b == nullptr) continue;
      const scenes::CollideAction action = scenes::collide_action(world.get(), *c);
      if (action == scenes::CollideAction::Destroy) {
        live.erase(c);
        continue;
      }
      auto [it, created] = live.try_emplace(c, static_cast<std::int32_t>(stream.contacts.size()));
      if (created) {
        const bool triangles = a->m_count == 3 && b->m_count == 3;
        stream.contacts.push_back(
            {*a, *b, triangles,
             triangles ? InternalEdges::pair(box2d::triangle_internal_edges(*c->GetFixtureA()),
                                             box2d::triangle_internal_edges(*c->GetFixtureB()))
                       : InternalEdges{}});
      }
      if (action == scenes::CollideAction::Skip) continue;
      stream.calls.push_back({it->second, step, c->GetFixtureA()->GetBody()->GetTransform(),
                              c->GetFixtureB()->GetBody()->GetTransform()});
    }
    world.step();
  }
  return stream;
}

std::uint64_t world_evaluations(std::string_view name, int steps, std::uint64_t seed) {
  checked_builder(name, steps);
  const std::unique_ptr<scenes::Scene> scene =
      scenes::make_scene(name, box2d::Backend::Box2D, seed);
  scene->step();  // step 1 is not in the stream
  const box2d::Stats first = box2d::stats();
  for (int step = 2; step <= steps; ++step) scene->step();
  const box2d::Stats all = box2d::stats();
  return all.triangles(box2d::Backend::Box2D) - first.triangles(box2d::Backend::Box2D) +
         all.polygon_pairs - first.polygon_pairs;
}

std::vector<b2Manifold> replay_manifolds(const ContactStream& stream, box2d::Backend backend,
                                         const box2d::Config& config) {
  require_calls(stream);
  std::vector<box2d::ContactMemory> memory(stream.contacts.size());
  std::vector<b2Manifold> out(stream.calls.size());
  for (std::size_t i = 0; i < stream.calls.size(); ++i) {
    const StreamCall& call = stream.calls[i];
    const StreamContact& c = stream.contacts[static_cast<std::size_t>(call.contact)];
    box2d::collide_polygons(&out[i], backend, c.shape_a, call.xf_a, c.shape_b, call.xf_b,
                            &memory[static_cast<std::size_t>(call.contact)], config);
  }
  return out;
}

StreamAgreement compare_with_box2d(const ContactStream& stream, box2d::Backend backend,
                                   const box2d::Config& config) {
  require_calls(stream);
  std::vector<box2d::ContactMemory> memory(stream.contacts.size());
  StreamAgreement out;
  b2Manifold got, ref;
  for (const StreamCall& call : stream.calls) {
    const StreamContact& c = stream.contacts[static_cast<std::size_t>(call.contact)];
    box2d::collide_polygons(&got, backend, c.shape_a, call.xf_a, c.shape_b, call.xf_b,
                            &memory[static_cast<std::size_t>(call.contact)], config);
    b2CollidePolygons(&ref, &c.shape_a, call.xf_a, &c.shape_b, call.xf_b);
    agree(got, ref, c, call, out);
  }
  return out;
}

StreamResult measure_stream(const ContactStream& stream, const StreamOptions& options) {
  require_calls(stream);
  if (options.passes < 1) throw std::invalid_argument("stream timing needs at least 1 pass");
  StreamResult r;
  r.scene = stream.scene;
  r.steps = stream.steps;
  r.contacts = stream.contacts.size();
  r.calls = stream.calls.size();
  r.triangle_calls = stream.triangle_calls();

  // Runner k < backend_count is all_backends[k]; the last is box2d-own.
  constexpr int runners = box2d::backend_count + 1;
  auto backend_of = [](int k) -> scenes::Runner {
    if (k == box2d::backend_count) return std::nullopt;
    return box2d::all_backends[k];
  };
  r.runners.resize(runners);
  StreamAgreement own;
  b2Manifold m;
  for (const StreamCall& call : stream.calls) {
    const StreamContact& c = stream.contacts[static_cast<std::size_t>(call.contact)];
    b2CollidePolygons(&m, &c.shape_a, call.xf_a, &c.shape_b, call.xf_b);
    r.calls_with_points += m.pointCount > 0;
    agree(m, m, c, call, own);
  }
  for (int k = 0; k < runners; ++k) {
    const scenes::Runner b = backend_of(k);
    r.runners[k].runner = b;
    r.runners[k].agreement = b ? compare_with_box2d(stream, *b, options.config) : own;
    r.runners[k].ns_per_call = HUGE_VAL;
  }

  std::vector<box2d::ContactMemory> memory;
  for (int pass = 0; pass < options.passes; ++pass) {
    for (int k = 0; k < runners; ++k) {
      const double ns = timed_pass(stream, backend_of(k), options, memory);
      r.runners[k].ns_per_call = std::min(r.runners[k].ns_per_call, ns);
    }
  }
  const double base = r.runners.back().ns_per_call;
  for (StreamRunnerResult& x : r.runners)
    x.ratio_vs_box2d_own = base > 0 ? x.ns_per_call / base : 0;
  return r;
}

std::vector<StreamResult> run_streams(const StreamOptions& options, std::ostream& progress) {
  std::vector<StreamResult> out;
  for (const std::string& scene : options.scenes) {
    const auto start = Clock::now();
    const ContactStream stream = record_stream(scene, options.steps, options.seed);
    const std::uint64_t evaluations = world_evaluations(scene, options.steps, options.seed);
    const double worlds = std::chrono::duration<double>(Clock::now() - start).count();
    out.push_back(measure_stream(stream, options));
    out.back().world_evaluations = evaluations;
    const double total = std::chrono::duration<double>(Clock::now() - start).count();
    progress << "dyop bench: stream " << scene << ": " << stream.calls.size() << " calls in "
             << options.steps << " steps (worlds run in " << detail::fixed(worlds, 1)
             << " s, replayed in " << detail::fixed(total - worlds, 1) << " s)\n";
  }
  return out;
}

}  // namespace dyop::experiments
