#include "edge_data.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_world.h>
#include <box2d/b2_world_callbacks.h>

#include <vector>

#include "dyop/box2d_internal_edges.hpp"
#include "internal_edges.hpp"
#include "contact.hpp"
#include "pair_families.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

// True when `f` holds fixed edge data.
bool has_fixed_edge_data(const b2Fixture& f) {
  if (holds_edge_data(f)) return fixed_polygon_edges(f).has_value();
  return two_sided_edge(f) && fixed_edge_ends(f).has_value();
}

// Writes `f`'s fixed edge data as it is now: a polygon's masks, or a two-sided edge's ends.
void write_found_edge_data(b2Fixture& f) {
  if (holds_edge_data(f)) {
    write_fixed_edges(f, polygon_edge_data(f));
  } else {
    write_fixed_edge_ends(f, edge_ends(f));
  }
}

// The fixtures with fixed edge data whose broad-phase boxes overlap a region.
class FixedInRegion : public b2QueryCallback {
 public:
  bool ReportFixture(b2Fixture* f) override {
    if (has_fixed_edge_data(*f)) found.push_back(f);
    return true;
  }
  std::vector<b2Fixture*> found;
};

// The fixtures of `body` that can hold fixed edge data (`fixes_edge_data`).
void add_fixable_of(const b2Body& body, std::vector<b2Fixture*>& out) {
  for (b2Fixture* f = const_cast<b2Body&>(body).GetFixtureList(); f; f = f->GetNext()) {
    if (fixes_edge_data(*f)) out.push_back(f);
  }
}

}  // namespace

void fix_fixtures(b2World& world, const std::vector<b2Fixture*>& fixtures) {
  if (fixtures.empty()) return;
  // Marked first (empty masks), then found over the region they span: a fixture's masks read its
  // neighbours' shapes, never their edge data, so the order of the finds does not matter.
  b2AABB region;
  for (std::size_t i = 0; i < fixtures.size(); ++i) {
    b2Fixture& f = *fixtures[i];
    if (holds_edge_data(f)) {
      write_fixed_edges(f, PolygonEdgeData{});
    } else {
      write_fixed_edge_ends(f, {});
    }
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
  detail::add_fixable_of(body, fixtures);
  detail::fix_fixtures(*body.GetWorld(), fixtures);
}

void fix_internal_edges(b2World& world) {
  std::vector<b2Fixture*> fixtures;
  for (const b2Body* body = world.GetBodyList(); body; body = body->GetNext()) {
    detail::add_fixable_of(*body, fixtures);
  }
  detail::fix_fixtures(world, fixtures);
}

void fix_internal_edges(b2World& world, const std::vector<b2Fixture*>& fixtures) {
  std::vector<b2Fixture*> fixable;
  for (b2Fixture* f : fixtures) {
    if (f && detail::fixes_edge_data(*f)) fixable.push_back(f);
  }
  detail::fix_fixtures(world, fixable);
}

int refresh_internal_edges(b2World& world, const b2AABB& region) {
  detail::FixedInRegion query;
  world.QueryAABB(&query, region);
  for (b2Fixture* f : query.found) {
    detail::write_found_edge_data(*f);
    detail::recompute_contacts_of(*f);  // a kept manifold was computed with the old masks
  }
  return static_cast<int>(query.found.size());
}

std::optional<InternalEdges> fixed_internal_edges(const b2Fixture& fixture) {
  return detail::fixed_edges(fixture);
}

ShapeMasks edge_internal_edges(const b2Fixture& fixture, int child, bool back) {
  const b2Shape* shape = fixture.GetShape();
  if (shape->m_type == b2Shape::e_chain) {
    const auto& chain = *static_cast<const b2ChainShape*>(shape);
    if (child < 0 || child >= chain.GetChildCount()) return {};
    b2EdgeShape edge;
    chain.GetChildEdge(&edge, child);
    return detail::one_sided_masks(edge);
  }
  if (shape->m_type != b2Shape::e_edge) return {};
  const auto& edge = *static_cast<const b2EdgeShape*>(shape);
  if (edge.m_oneSided) return detail::one_sided_masks(edge);
  return detail::side_masks(edge_ends(fixture), back);
}

EdgeEnds edge_ends(const b2Fixture& fixture) {
  if (!detail::two_sided_edge(fixture)) return {};
  const std::optional<EdgeEnds> fixed = detail::fixed_edge_ends(fixture);
  return fixed ? *fixed : detail::edge_ends(fixture);
}

std::optional<ShapeMasks> fixed_edge_internal_edges(const b2Fixture& fixture, bool back) {
  if (!detail::two_sided_edge(fixture)) return std::nullopt;
  const std::optional<EdgeEnds> fixed = detail::fixed_edge_ends(fixture);
  if (!fixed) return std::nullopt;
  return detail::side_masks(*fixed, back);
}

std::optional<ShapeMasks> fixed_polygon_edges(const b2Fixture& fixture) {
  if (!detail::holds_edge_data(fixture)) return std::nullopt;
  return detail::fixed_polygon_edges(fixture);
}

}  // namespace dyop::box2d
