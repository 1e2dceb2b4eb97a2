#include "edge_data.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_world.h>
#include <box2d/b2_world_callbacks.h>

#include <vector>

#include "dyop/box2d_internal_edges.hpp"
#include "internal_edges.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

// The fixtures with fixed edge data whose broad-phase boxes overlap a region.
class FixedInRegion : public b2QueryCallback {
 public:
  bool ReportFixture(b2Fixture* f) override {
    if (holds_edge_data(*f) && fixed_polygon_edges(*f)) found.push_back(f);
    return true;
  }
  std::vector<b2Fixture*> found;
};

// The polygon fixtures of `body` that can hold fixed edge data.
void add_polygons_of(const b2Body& body, std::vector<b2Fixture*>& out) {
  for (b2Fixture* f = const_cast<b2Body&>(body).GetFixtureList(); f; f = f->GetNext()) {
    if (holds_edge_data(*f)) out.push_back(f);
  }
}

}  // namespace

void fix_fixtures(b2World& world, const std::vector<b2Fixture*>& fixtures) {
  if (fixtures.empty()) return;
  // Marked first (empty masks), then found over the region they span: a triangle's masks read
  // its neighbours' shapes, never their edge data, so the order of the finds does not matter.
  b2AABB region;
  for (std::size_t i = 0; i < fixtures.size(); ++i) {
    b2Fixture& f = *fixtures[i];
    write_fixed_edges(f, {});
    b2AABB box;
    f.GetShape()->ComputeAABB(&box, f.GetBody()->GetTransform(), 0);
    if (i == 0) {
      region = box;
    } else {
      region.Combine(box);
    }
  }
  refresh_internal_edges(world, region);
}

}  // namespace detail

void fix_internal_edges(b2Body& body) {
  std::vector<b2Fixture*> fixtures;
  detail::add_polygons_of(body, fixtures);
  detail::fix_fixtures(*body.GetWorld(), fixtures);
}

void fix_internal_edges(b2World& world) {
  std::vector<b2Fixture*> fixtures;
  for (const b2Body* body = world.GetBodyList(); body; body = body->GetNext()) {
    detail::add_polygons_of(*body, fixtures);
  }
  detail::fix_fixtures(world, fixtures);
}

void fix_internal_edges(b2World& world, const std::vector<b2Fixture*>& fixtures) {
  std::vector<b2Fixture*> polygons;
  for (b2Fixture* f : fixtures) {
    if (f && detail::holds_edge_data(*f)) polygons.push_back(f);
  }
  detail::fix_fixtures(world, polygons);
}

int refresh_internal_edges(b2World& world, const b2AABB& region) {
  detail::FixedInRegion query;
  world.QueryAABB(&query, region);
  for (b2Fixture* f : query.found) {
    detail::write_fixed_edges(*f, detail::polygon_internal_edges(*f));
    detail::recompute_contacts_of(*f);  // a kept manifold was computed with the old masks
  }
  return static_cast<int>(query.found.size());
}

std::optional<InternalEdges> fixed_internal_edges(const b2Fixture& fixture) {
  return detail::fixed_edges(fixture);
}

std::optional<ShapeMasks> fixed_polygon_edges(const b2Fixture& fixture) {
  if (!detail::holds_edge_data(fixture)) return std::nullopt;
  return detail::fixed_polygon_edges(fixture);
}

}  // namespace dyop::box2d
