#pragma once
/// \file
/// A triangle mesh added to a Box2D body in one call, its edge data fixed with it: the way to
/// build grounds, tile maps and bodies of triangles for the plug-in's internal-edge rule.
///
///     const b2Vec2 vertices[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
///     const int indices[] = {0, 1, 2, 0, 2, 3};
///     dyop::box2d::MeshResult r = dyop::box2d::add_triangles(*ground, vertices, 4, indices, 6);
///     if (!r.ok()) std::cerr << "triangle " << r.triangle << ": " << r.message << '\n';

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>

#include <cstdint>
#include <vector>

#include "dyop/box2d.hpp"

namespace dyop::box2d {

/// Why `add_triangles` refused a mesh; it then created nothing.
enum class MeshError : std::uint8_t {
  None,             ///< the mesh was added
  WorldLocked,      ///< called during a step (Box2D creates no fixture then)
  IndexCount,       ///< the index count is not a positive multiple of 3, or a count is negative
  IndexOutOfRange,  ///< an index outside [0, vertex_count): see `MeshResult::triangle`
  Triangle,         ///< `make_triangle` refused a triangle: see `MeshResult::triangle`
};

/// A static, human-readable description of `e`.
const char* describe(MeshError e);

/// The outcome of `add_triangles`, returned by value.
struct MeshResult {
  MeshError error = MeshError::None;  ///< always valid
  /// The triangle refused (its vertices are `indices[3·triangle ..]`); -1 when none or when the
  /// whole mesh is refused (`WorldLocked`, `IndexCount`).
  int triangle = -1;
  /// `error == Triangle`: what `make_triangle` found (`ShapeError::Triangle`: see
  /// `triangle_error`); `None` otherwise.
  ShapeError shape_error = ShapeError::None;
  TriangleError triangle_error = TriangleError::None;  ///< `shape_error == Triangle`: the reason
  const char* message = "";  ///< static, human-readable: what is wrong, or "mesh added"
  /// The fixtures created, one per triangle in the order given; empty unless `ok()`.
  std::vector<b2Fixture*> fixtures;
  bool ok() const { return error == MeshError::None; }  ///< true when `error == None`
};

/// Adds the triangles `indices[3t], indices[3t + 1], indices[3t + 2]` of `vertices` (body frame,
/// metres, any winding) to `body` as triangle fixtures made like `def` (density, friction,
/// filter...; `def.shape` is ignored), then fixes their edge data and that of the fixed triangles
/// next to them (`fix_internal_edges` in `dyop/box2d_internal_edges.hpp`). Every triangle is
/// checked first (`make_triangle`: degenerate, repeated or non-finite vertices, slivers Box2D
/// would assert on): one refused triangle, an index out of range or a locked world refuses the
/// whole mesh, and nothing is created.
MeshResult add_triangles(b2Body& body, const b2Vec2* vertices, int vertex_count, const int* indices,
                         int index_count, const b2FixtureDef& def = b2FixtureDef());

}  // namespace dyop::box2d
