#pragma once
/// \file
/// What the grounds and terrain sections of `dyop compare` measure a ground by: its rings as
/// Box2D's chain loops take them, their length, and the bytes of its fixtures and broad-phase
/// proxies (Box2D 2.4.1's objects, x86-64; what a user's level costs per metre of boundary).

#include <box2d/b2_broad_phase.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_fixture.h>

#include <cstddef>
#include <vector>

namespace dyop::experiments {

/// Bytes of one broad-phase proxy: the fixture's proxy record and its tree leaf, with an inner
/// node amortised per leaf.
inline constexpr std::size_t proxy_bytes = sizeof(b2FixtureProxy) + 2 * sizeof(b2TreeNode);

/// Bytes of `count` fixtures of shape type `Shape` with one proxy each (polygons, edges).
template <class Shape>
double fixtures_bytes(std::size_t count) {
  return static_cast<double>(count * (sizeof(b2Fixture) + sizeof(Shape) + proxy_bytes));
}

/// Bytes of a chain fixture: the fixture, the shape, its vertices (a loop keeps one more) and one
/// proxy per edge.
double chain_bytes(const b2ChainShape& chain);

/// The signed area of `ring` (m²): positive when counter-clockwise.
double signed_area(const std::vector<b2Vec2>& ring);

/// `rings` (the outline, then its holes; either winding) as chain loops: the outline
/// counter-clockwise, its holes clockwise (the solid on each loop's left: Box2D's one-sided chains
/// collide on the right).
std::vector<std::vector<b2Vec2>> chain_loops_of(std::vector<std::vector<b2Vec2>> rings);

/// The length of every loop's edges, the closing one included (metres).
double boundary_length(const std::vector<std::vector<b2Vec2>>& loops);

}  // namespace dyop::experiments
