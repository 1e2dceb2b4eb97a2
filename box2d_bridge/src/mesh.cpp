#include "dyop/box2d_mesh.hpp"

#include <box2d/b2_world.h>

#include "edge_data.hpp"

namespace dyop::box2d {
namespace {

MeshResult refused(MeshError e, int triangle = -1) {
  MeshResult out;
  out.error = e;
  out.triangle = triangle;
  out.message = describe(e);
  return out;
}

}  // namespace

const char* describe(MeshError e) {
  switch (e) {
    case MeshError::None:
      return "mesh added";
    case MeshError::WorldLocked:
      return "the world is stepping: add the mesh between steps";
    case MeshError::IndexCount:
      return "the index count is not a positive multiple of 3 (or a count is negative)";
    case MeshError::IndexOutOfRange:
      return "a vertex index outside [0, vertex_count)";
    case MeshError::Triangle:
      return "a triangle Box2D cannot take (see shape_error)";
  }
  return "unknown mesh error";
}

MeshResult add_triangles(b2Body& body, const b2Vec2* vertices, int vertex_count, const int* indices,
                         int index_count, const b2FixtureDef& def) {
  if (body.GetWorld()->IsLocked()) return refused(MeshError::WorldLocked);
  if (vertex_count < 0 || index_count <= 0 || index_count % 3 != 0 || !indices) {
    return refused(MeshError::IndexCount);
  }
  const int triangles = index_count / 3;
  std::vector<TriangleShape> shapes;
  shapes.reserve(static_cast<std::size_t>(triangles));
  for (int t = 0; t < triangles; ++t) {
    const int* i = indices + 3 * t;
    for (int k = 0; k < 3; ++k) {
      if (!vertices || i[k] < 0 || i[k] >= vertex_count) {
        return refused(MeshError::IndexOutOfRange, t);
      }
    }
    shapes.push_back(make_triangle(vertices[i[0]], vertices[i[1]], vertices[i[2]]));
    const TriangleShape& shape = shapes.back();
    if (!shape.ok()) {
      MeshResult out = refused(MeshError::Triangle, t);
      out.shape_error = shape.error;
      out.triangle_error = shape.triangle_error;
      out.message = shape.message;
      return out;
    }
  }
  MeshResult out;
  out.message = describe(MeshError::None);
  out.fixtures.reserve(shapes.size());
  b2FixtureDef each = def;
  for (const TriangleShape& shape : shapes) {
    each.shape = &shape.shape;
    out.fixtures.push_back(body.CreateFixture(&each));
  }
  detail::fix_fixtures(*body.GetWorld(), out.fixtures);
  return out;
}

}  // namespace dyop::box2d
