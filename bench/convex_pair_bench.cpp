// build/bin/dyop_convex_bench: one pair beyond two triangles per iteration, the plug-in's answer
// against Box2D's own function on the same pairs: BM_convex/<pair>/<class>/<who>, <pair> a
// `SetAsBox` box, a hexagon or a circle against a triangle, or against an edge (a one-sided one, a
// chain's, the body on its front), <class> overlapping (penetrating) or
// near (apart by less than the skins: a manifold with points), <who> `plugin`
// (`collide_polygons` / `collide_polygon_and_circle` with `Backend::Dyop` and a `ContactMemory`
// per pair, as a world's contact keeps one: the shapes looked at once; `collide_edge_and_polygon`
// / `collide_edge_and_circle` for edges), `plugin-cold` (the same without a `ContactMemory`: the
// shapes looked at on every call) or `box2d` (`b2CollidePolygons` / `b2CollidePolygonAndCircle`,
// `b2CollideEdgeAndPolygon` / `b2CollideEdgeAndCircle`). 32,768 distinct seeded pairs per class, so
// that no branch predictor learns them; compare the two rows of a pair and class in one run.
#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/convex_pair.hpp"

namespace {

using namespace dyop;

constexpr int kPairs = 32768;
constexpr std::uint32_t kSeed = 2026;
// Apart by less than this is `near` (metres): below the two polygon skins (2·b2_polygonRadius),
// so Box2D's manifold has points.
constexpr double kNear = 2 * b2_polygonRadius;

enum class Shape { Box, Hexagon, Circle };
enum class Class { Overlapping, Near };
// What B meets: a triangle fixture, or an edge.
enum class Ground { Triangle, Edge };

std::string name(Shape s, Ground g) {
  return std::string(s == Shape::Box       ? "box-"
                     : s == Shape::Hexagon ? "hexagon-"
                                           : "circle-") +
         (g == Ground::Triangle ? "triangle" : "edge");
}
const char* name(Class c) { return c == Class::Overlapping ? "overlapping" : "near"; }

// A triangle fixture's shape or an edge (A) and a box, hexagon or circle (B), each with its body's
// transform.
struct PairSet {
  std::vector<b2PolygonShape> triangle;
  std::vector<b2EdgeShape> edge;
  std::vector<b2Transform> xf_a;
  std::vector<b2PolygonShape> polygon;
  std::vector<b2CircleShape> circle;
  std::vector<b2Transform> xf_b;
};

Vec2<double> world(const b2Transform& xf, const b2Vec2& v) {
  const b2Vec2 w = b2Mul(xf, v);
  return Vec2<double>(w.x, w.y);
}

// The pair's separation in double (the solver's, exact; skins not counted), to sort pairs into
// classes; `a` is a polygon or a segment in double.
template <class A>
double separation(const A& a, Shape s, const b2PolygonShape& p, const b2CircleShape& c,
                  const b2Transform& xb) {
  if (s == Shape::Circle)
    return collide(a, Circle<double>{world(xb, c.m_p), c.m_radius}).separation;
  Vec2<double> b[b2_maxPolygonVertices];
  for (int i = 0; i < p.m_count; ++i) b[i] = world(xb, p.m_vertices[i]);
  return collide(a, Polygon<double>::make(b, p.m_count).polygon).separation;
}

const PairSet& pairs_of(Shape s, Class c, Ground g) {
  static std::map<std::tuple<Shape, Class, Ground>, PairSet> sets;
  auto it = sets.find({s, c, g});
  if (it != sets.end()) return it->second;
  PairSet& out = sets[{s, c, g}];
  std::mt19937 rng(kSeed + 7 * static_cast<std::uint32_t>(s) + static_cast<std::uint32_t>(c) +
                   101 * static_cast<std::uint32_t>(g));
  std::uniform_real_distribution<float> u(-1, 1);
  while (static_cast<int>(out.xf_a.size()) < kPairs) {
    const b2Vec2 p[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const box2d::TriangleShape t = box2d::make_triangle(p[0], p[1], p[2]);
    if (!t.ok() || t.shape.m_centroid.Length() > 0.5f) continue;
    // An edge from the triangle's first vertex to its second, turned so that the triangle's
    // centroid (near where B is placed) lies on its front; its ghosts going on straight.
    const bool ccw = b2Cross(p[1] - p[0], t.shape.m_centroid - p[0]) < 0;
    const b2Vec2 e0 = ccw ? p[0] : p[1];
    const b2Vec2 e1 = ccw ? p[1] : p[0];
    b2EdgeShape edge;
    edge.SetOneSided(e0 - (e1 - e0), e0, e1, e1 + (e1 - e0));
    b2Transform xa(b2Vec2(10 * u(rng), 10 * u(rng)), b2Rot(3.14159f * u(rng)));
    b2Transform xb(b2Mul(xa, b2Vec2(0.8f * u(rng), 0.8f * u(rng))), b2Rot(3.14159f * u(rng)));
    b2PolygonShape polygon;
    b2CircleShape circle;
    const float size = 0.2f + 0.3f * std::abs(u(rng));
    if (s == Shape::Box) {
      polygon.SetAsBox(size, 0.5f * size + 0.1f);
    } else if (s == Shape::Hexagon) {
      b2Vec2 v[6];
      for (int i = 0; i < 6; ++i)
        v[i].Set(size * std::cos(1.0472f * i), size * std::sin(1.0472f * i));
      polygon.Set(v, 6);
    } else {
      circle.m_radius = size;
    }
    double d = 0;
    if (g == Ground::Triangle) {
      Vec2<double> a[3];
      for (int i = 0; i < 3; ++i) a[i] = world(xa, t.shape.m_vertices[i]);
      d = separation(Polygon<double>::make(a, 3).polygon, s, polygon, circle, xb);
    } else {
      const SegmentOrError<double> a =
          Segment<double>::make(world(xa, edge.m_vertex1), world(xa, edge.m_vertex2));
      if (!a.ok()) continue;
      // Box2D's one-sided rule would answer nothing: a pair the body is behind is no pair here.
      const b2Vec2 centroid = b2MulT(xa, b2Mul(xb, s == Shape::Circle ? circle.m_p : b2Vec2(0, 0)));
      if (b2Cross(centroid - edge.m_vertex1, edge.m_vertex2 - edge.m_vertex1) < 0) continue;
      d = separation(a.segment, s, polygon, circle, xb);
    }
    const bool keep = c == Class::Overlapping ? d < -0.01 : d > 0 && d < kNear;
    if (!keep) continue;
    out.triangle.push_back(t.shape);
    out.edge.push_back(edge);
    out.xf_a.push_back(xa);
    out.polygon.push_back(polygon);
    out.circle.push_back(circle);
    out.xf_b.push_back(xb);
  }
  return out;
}

// `cold`: no `ContactMemory` given.
void bm_plugin(benchmark::State& state, Shape s, Class c, Ground g, bool cold) {
  const PairSet& p = pairs_of(s, c, g);
  std::vector<box2d::ContactMemory> memory(p.triangle.size());
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    box2d::ContactMemory* m = cold ? nullptr : &memory[i];
    if (g == Ground::Edge) {
      if (s == Shape::Circle) {
        box2d::collide_edge_and_circle(&manifold, box2d::Backend::Dyop, p.edge[i], p.xf_a[i],
                                       p.circle[i], p.xf_b[i], m);
      } else {
        box2d::collide_edge_and_polygon(&manifold, box2d::Backend::Dyop, p.edge[i], p.xf_a[i],
                                        p.polygon[i], p.xf_b[i], m);
      }
    } else if (s == Shape::Circle) {
      box2d::collide_polygon_and_circle(&manifold, box2d::Backend::Dyop, p.triangle[i], p.xf_a[i],
                                        p.circle[i], p.xf_b[i], m);
    } else {
      box2d::collide_polygons(&manifold, box2d::Backend::Dyop, p.triangle[i], p.xf_a[i],
                              p.polygon[i], p.xf_b[i], m);
    }
    benchmark::DoNotOptimize(manifold);
    if (++i == p.triangle.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void bm_box2d(benchmark::State& state, Shape s, Class c, Ground g) {
  const PairSet& p = pairs_of(s, c, g);
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    if (g == Ground::Edge) {
      if (s == Shape::Circle) {
        b2CollideEdgeAndCircle(&manifold, &p.edge[i], p.xf_a[i], &p.circle[i], p.xf_b[i]);
      } else {
        b2CollideEdgeAndPolygon(&manifold, &p.edge[i], p.xf_a[i], &p.polygon[i], p.xf_b[i]);
      }
    } else if (s == Shape::Circle) {
      b2CollidePolygonAndCircle(&manifold, &p.triangle[i], p.xf_a[i], &p.circle[i], p.xf_b[i]);
    } else {
      b2CollidePolygons(&manifold, &p.triangle[i], p.xf_a[i], &p.polygon[i], p.xf_b[i]);
    }
    benchmark::DoNotOptimize(manifold);
    if (++i == p.triangle.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  for (Ground g : {Ground::Triangle, Ground::Edge}) {
    for (Shape s : {Shape::Box, Shape::Hexagon, Shape::Circle}) {
      for (Class c : {Class::Overlapping, Class::Near}) {
        const std::string stem = "BM_convex/" + name(s, g) + "/" + name(c);
        benchmark::RegisterBenchmark((stem + "/plugin").c_str(), bm_plugin, s, c, g, false);
        benchmark::RegisterBenchmark((stem + "/plugin-cold").c_str(), bm_plugin, s, c, g, true);
        benchmark::RegisterBenchmark((stem + "/box2d").c_str(), bm_box2d, s, c, g);
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
