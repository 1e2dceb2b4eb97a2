// Guide, step 6: debug drawing. A `b2Draw` that writes SVG draws a small level (a ground of
// triangles, a `SetAsBox` step on it, a chain slope) with a crate and a box of two triangles
// resting on it: Box2D's own `DebugDraw` for the shapes, then the plug-in's
// `draw_internal_edges` (outline edges, internal edges, closed vertices) and `draw_contacts`
// (manifold points and normals). Writes the picture to the file named by the first argument, if
// any. Exits non-zero unless internal edges, closed vertices and contact points were all drawn.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include <dyop/box2d.hpp>
#include <dyop/box2d_draw.hpp>

#include "glide.hpp"
#include "triangle_ground.hpp"

namespace {

// b2Draw as SVG elements, y up, 100 pixels a metre; counts what it drew, by colour.
class SvgDraw : public b2Draw {
 public:
  std::string svg;
  int internal = 0, closed = 0, points = 0;
  dyop::box2d::DrawStyle style;

  void DrawSegment(const b2Vec2& p, const b2Vec2& q, const b2Color& c) override {
    internal += same(c, style.internal);
    line(p, q, c, 1);
  }
  void DrawPoint(const b2Vec2& p, float size, const b2Color& c) override {
    closed += same(c, style.closed);
    points += same(c, style.point);
    svg += "<circle cx='" + x(p) + "' cy='" + y(p) + "' r='" + std::to_string(size / 2) +
           "' fill='" + rgb(c) + "'/>\n";
  }
  void DrawPolygon(const b2Vec2* v, int32 n, const b2Color& c) override {
    for (int i = 0; i < n; ++i) line(v[i], v[(i + 1) % n], c, 0.5f);
  }
  void DrawSolidPolygon(const b2Vec2* v, int32 n, const b2Color& c) override {
    DrawPolygon(v, n, c);
  }
  void DrawCircle(const b2Vec2& centre, float radius, const b2Color& c) override {
    svg += "<circle cx='" + x(centre) + "' cy='" + y(centre) + "' r='" +
           std::to_string(100 * radius) + "' fill='none' stroke='" + rgb(c) + "'/>\n";
  }
  void DrawSolidCircle(const b2Vec2& centre, float radius, const b2Vec2&,
                       const b2Color& c) override {
    DrawCircle(centre, radius, c);
  }
  void DrawTransform(const b2Transform&) override {}

 private:
  static bool same(const b2Color& a, const b2Color& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  }
  static std::string x(const b2Vec2& p) { return std::to_string(100 * (p.x + 1)); }
  static std::string y(const b2Vec2& p) { return std::to_string(100 * (3 - p.y)); }
  static std::string rgb(const b2Color& c) {
    return "rgb(" + std::to_string(int(255 * c.r)) + "," + std::to_string(int(255 * c.g)) + "," +
           std::to_string(int(255 * c.b)) + ")";
  }
  void line(const b2Vec2& p, const b2Vec2& q, const b2Color& c, float width) {
    svg += "<line x1='" + x(p) + "' y1='" + y(p) + "' x2='" + x(q) + "' y2='" + y(q) +
           "' stroke='" + rgb(c) + "' stroke-width='" + std::to_string(width) + "'/>\n";
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  SvgDraw draw;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef def;
    b2Body* ground = world.CreateBody(&def);
    example::add_triangle_ground(ground, 0, 6, 1);  // 1 m cells of two triangles, top at y = 0
    b2PolygonShape step;                            // a step on the ground
    step.SetAsBox(0.5f, 0.25f, b2Vec2(4.5f, 0.25f), 0);
    ground->CreateFixture(&step, 0);
    const b2Vec2 slope[] = {{6, 0}, {7, 0.5f}, {8, 1.5f}};
    b2ChainShape chain;
    chain.CreateChain(slope, 3, b2Vec2(5, 0), b2Vec2(9, 2));
    ground->CreateFixture(&chain, 0);

    example::add_crate(world, b2Vec2(1.5f, 0.5f), 0.5f, b2Vec2(0, 0));
    example::add_pushed(world, example::Shape::TriangleBox, b2Vec2(3, 0), 0);
    for (int i = 0; i < 60; ++i) world.Step(1.0f / 60, 8, 3);

    draw.SetFlags(b2Draw::e_shapeBit);
    world.SetDebugDraw(&draw);
    world.DebugDraw();                              // Box2D's shapes
    dyop::box2d::draw_internal_edges(world, draw);  // the rule's view of every edge
    dyop::box2d::draw_contacts(world, draw);        // the touching contacts' points
  }
  dyop::box2d::uninstall();

  std::printf("drew %d internal edges, %d closed vertices, %d contact points\n", draw.internal,
              draw.closed, draw.points);
  if (argc > 1) {
    if (FILE* f = std::fopen(argv[1], "w")) {
      std::fprintf(f,
                   "<svg xmlns='http://www.w3.org/2000/svg' width='1000' height='500'>\n"
                   "<rect width='100%%' height='100%%' fill='black'/>\n%s</svg>\n",
                   draw.svg.c_str());
      std::fclose(f);
      std::printf("wrote %s\n", argv[1]);
    }
  }
  const bool ok = draw.internal > 0 && draw.closed > 0 && draw.points > 0;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
