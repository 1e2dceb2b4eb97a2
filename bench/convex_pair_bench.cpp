// build/bin/dyop_convex_bench: one pair beyond two triangles per iteration, the plug-in's answer
// against Box2D's own function on the same pairs: BM_convex/<pair>/<class>/<who>, <pair> a
// `SetAsBox` box, a hexagon or a circle against a triangle, <class> overlapping (penetrating) or
// near (apart by less than the skins: a manifold with points), <who> `plugin`
// (`collide_polygons` / `collide_polygon_and_circle` with `Backend::Dyop` and a `ContactMemory`
// per pair, as a world's contact keeps one: the shapes looked at once), `plugin-cold` (the same
// without a `ContactMemory`: the shapes looked at on every call) or `box2d`
// (`b2CollidePolygons` / `b2CollidePolygonAndCircle`). 32,768 distinct seeded pairs per class, so
// that no branch predictor learns them; compare the two rows of a pair and class in one run.
#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
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

const char* name(Shape s) {
  return s == Shape::Box       ? "box-triangle"
         : s == Shape::Hexagon ? "hexagon-triangle"
                               : "circle-triangle";
}
const char* name(Class c) { return c == Class::Overlapping ? "overlapping" : "near"; }

// A triangle fixture's shape (A) and a box, hexagon or circle (B), each with its body's transform.
struct PairSet {
  std::vector<b2PolygonShape> triangle;
  std::vector<b2Transform> xf_a;
  std::vector<b2PolygonShape> polygon;
  std::vector<b2CircleShape> circle;
  std::vector<b2Transform> xf_b;
};

// The pair's separation in double (the solver's, exact; skins not counted), to sort pairs into
// classes.
double separation(const b2PolygonShape& t, const b2Transform& xa, Shape s, const b2PolygonShape& p,
                  const b2CircleShape& c, const b2Transform& xb) {
  const auto world = [](const b2Transform& xf, const b2Vec2& v) {
    const b2Vec2 w = b2Mul(xf, v);
    return Vec2<double>(w.x, w.y);
  };
  Vec2<double> a[3];
  for (int i = 0; i < 3; ++i) a[i] = world(xa, t.m_vertices[i]);
  const Polygon<double> pa = Polygon<double>::make(a, 3).polygon;
  if (s == Shape::Circle) {
    return collide(pa, Circle<double>{world(xb, c.m_p), c.m_radius}).separation;
  }
  Vec2<double> b[b2_maxPolygonVertices];
  for (int i = 0; i < p.m_count; ++i) b[i] = world(xb, p.m_vertices[i]);
  return collide(pa, Polygon<double>::make(b, p.m_count).polygon).separation;
}

const PairSet& pairs_of(Shape s, Class c) {
  static std::map<std::pair<Shape, Class>, PairSet> sets;
  auto it = sets.find({s, c});
  if (it != sets.end()) return it->second;
  PairSet& out = sets[{s, c}];
  std::mt19937 rng(kSeed + 7 * static_cast<std::uint32_t>(s) + static_cast<std::uint32_t>(c));
  std::uniform_real_distribution<float> u(-1, 1);
  while (static_cast<int>(out.triangle.size()) < kPairs) {
    const b2Vec2 p[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const box2d::TriangleShape t = box2d::make_triangle(p[0], p[1], p[2]);
    if (!t.ok() || t.shape.m_centroid.Length() > 0.5f) continue;
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
    const double d = separation(t.shape, xa, s, polygon, circle, xb);
    const bool keep = c == Class::Overlapping ? d < -0.01 : d > 0 && d < kNear;
    if (!keep) continue;
    out.triangle.push_back(t.shape);
    out.xf_a.push_back(xa);
    out.polygon.push_back(polygon);
    out.circle.push_back(circle);
    out.xf_b.push_back(xb);
  }
  return out;
}

// `cold`: no `ContactMemory` given.
void bm_plugin(benchmark::State& state, Shape s, Class c, bool cold) {
  const PairSet& p = pairs_of(s, c);
  std::vector<box2d::ContactMemory> memory(p.triangle.size());
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    box2d::ContactMemory* m = cold ? nullptr : &memory[i];
    if (s == Shape::Circle) {
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

void bm_box2d(benchmark::State& state, Shape s, Class c) {
  const PairSet& p = pairs_of(s, c);
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    if (s == Shape::Circle) {
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
  for (Shape s : {Shape::Box, Shape::Hexagon, Shape::Circle}) {
    for (Class c : {Class::Overlapping, Class::Near}) {
      const std::string stem = std::string("BM_convex/") + name(s) + "/" + name(c);
      benchmark::RegisterBenchmark((stem + "/plugin").c_str(), bm_plugin, s, c, false);
      benchmark::RegisterBenchmark((stem + "/plugin-cold").c_str(), bm_plugin, s, c, true);
      benchmark::RegisterBenchmark((stem + "/box2d").c_str(), bm_box2d, s, c);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
