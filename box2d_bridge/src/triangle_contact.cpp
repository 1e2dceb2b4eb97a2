#include "triangle_contact.hpp"

#include <box2d/b2_block_allocator.h>
#include <box2d/b2_fixture.h>

#include <new>

namespace dyop::box2d::detail {
namespace {

Backend next_backend = Backend::Dyop;
Config next_config;
// Counted in the constructor and destructor, so a contact is counted whoever destroys it.
int live_count = 0;

}  // namespace

b2Contact* TriangleContact::create(b2Fixture* fixture_a, int32, b2Fixture* fixture_b, int32,
                                   b2BlockAllocator* allocator) {
  void* memory = allocator->Allocate(sizeof(TriangleContact));
  return new (memory) TriangleContact(fixture_a, fixture_b, next_backend, next_config);
}

void TriangleContact::destroy(b2Contact* contact, b2BlockAllocator* allocator) {
  static_cast<TriangleContact*>(contact)->~TriangleContact();
  allocator->Free(contact, sizeof(TriangleContact));
}

void TriangleContact::use(Backend backend, const Config& config) {
  next_backend = backend;
  next_config = config;
}

int TriangleContact::live() { return live_count; }

TriangleContact::TriangleContact(b2Fixture* fixture_a, b2Fixture* fixture_b, Backend backend,
                                 const Config& config)
    : b2Contact(fixture_a, 0, fixture_b, 0), backend_(backend), config_(config) {
  ++live_count;
}

TriangleContact::~TriangleContact() { --live_count; }

void TriangleContact::Evaluate(b2Manifold* manifold, const b2Transform& xf_a,
                               const b2Transform& xf_b) {
  // The registry dispatches only polygon–polygon pairs here.
  evaluate_pair(manifold, backend_, config_,
                *static_cast<const b2PolygonShape*>(m_fixtureA->GetShape()), xf_a,
                *static_cast<const b2PolygonShape*>(m_fixtureB->GetShape()), xf_b, state_);
}

}  // namespace dyop::box2d::detail
