#include "internal_edges.hpp"

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <box2d/b2_world_callbacks.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <vector>

#include "dyop/box2d_internal_edges.hpp"
#include "edge_data_memo.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

// A non-static body with at most this many fixtures has its list walked instead of the broad
// phase queried. Why: the result is the same (every polygon of the body is a candidate; only
// those touching it count), and a walk costs tens of instructions per fixture against thousands
// for one query of a ground's broad phase: below a few dozen fixtures the walk is cheaper, and a
// split box or a star (2 to 10 fixtures) never pays for a query. A static body
// always queries: its group spans the other static bodies.
constexpr int walked_body_fixtures = 16;

const b2PolygonShape* polygon_of(const b2Fixture& f) {
  if (f.GetType() != b2Shape::e_polygon) return nullptr;
  return static_cast<const b2PolygonShape*>(f.GetShape());
}

float magnitude(const b2Vec2& v) { return std::max(std::abs(v.x), std::abs(v.y)); }

// A polygon of the edge group in the frame of the fixture whose masks are found, Box2D's order.
struct GroupPolygon {
  b2Vec2 v[b2_maxPolygonVertices];
  int count = 3;
  int next(int i) const { return i + 1 < count ? i + 1 : 0; }
};

GroupPolygon group_polygon(const b2PolygonShape& p) {
  GroupPolygon t;
  t.count = p.m_count;
  for (int i = 0; i < p.m_count; ++i) t.v[i] = p.m_vertices[i];
  return t;
}

// An edge of the group (a `b2EdgeShape`, or a chain's child edge) in the frame of the fixture whose
// masks are found.
struct GroupSegment {
  b2Vec2 a;
  b2Vec2 b;
};

// A fixture (and child, for a chain) the broad phase gives a group (`Group::gather`).
struct Candidate {
  const b2Fixture* fixture;
  int child;
};

// `h` with frame `xf` and the points `v[0..count)` in it mixed in (`mix_point`), and the count;
// then shifted into itself, so that the high bits of the products reach the low ones before
// fingerprints are summed.
std::uint64_t mix(std::uint64_t h, const b2Transform& xf, const b2Vec2* v, int count) {
  h = mix_word(mix_point(mix_point(h, xf.p), b2Vec2(xf.q.s, xf.q.c)),
               static_cast<std::uint64_t>(count));
  for (int i = 0; i < count; ++i) h = mix_point(h, v[i]);
  return h ^ (h >> 29);
}

// The polygon fixtures (triangles or any other vertex count) that share edges with one fixture's
// body (`share_edges`) near it: those whose broad-phase boxes overlap its own (or all of a small
// non-static body's), in its body's frame; the fixture's own polygon first. The edges and chains
// of the group near it apart (`segments`), for its junctions.
class Group {
 public:
  // `scratch` is emptied and filled: the calling thread's, reused so that finding masks
  // allocates nothing once it has grown to the largest neighbourhood seen.
  Group(const b2Fixture& self, const b2PolygonShape& own, std::vector<GroupPolygon>& scratch,
        std::vector<GroupSegment>& segment_scratch)
      : self_(self),
        body_(*self.GetBody()),
        own_(own),
        polygons_(scratch),
        segments_(segment_scratch) {
    polygons_.clear();
    segments_.clear();
    polygons_.push_back(group_polygon(own));
    const GroupPolygon& first = polygons_.front();
    for (int i = 0; i < first.count; ++i) own_scale_ = std::max(own_scale_, magnitude(first.v[i]));
  }

  // True when the group is its body's fixtures, walked (`walk`): a small non-static body. Else
  // the broad phase's candidates are gathered (`gather`), then considered (`consider_gathered`).
  bool walked() const {
    if (body_.GetType() == b2_staticBody) return false;
    int count = 0;
    const b2Fixture* f = body_.GetFixtureList();
    for (; f && count < walked_body_fixtures; f = f->GetNext()) ++count;
    return f == nullptr;
  }

  void walk() {
    for (const b2Fixture* f = body_.GetFixtureList(); f; f = f->GetNext()) {
      if (!takes(*f)) continue;
      for (int child = 0; child < f->GetShape()->GetChildCount(); ++child) consider(*f, child);
    }
  }

  // The broad phase's candidates for the group: the proxies whose boxes meet the polygon's own
  // box, not its proxy's (every polygon touching it overlaps it with its fattened box, and a
  // disabled body's fixture has no proxy); the broad phase's own query, which tells a chain's
  // child edges apart. Fingerprinted as they come (`fingerprint`).
  void gather(std::vector<Candidate>& candidates) {
    candidates_ = &candidates;
    candidates.clear();
    fingerprint_ = fingerprint_of_own();
    b2AABB box;
    own_.ComputeAABB(&box, body_.GetTransform(), 0);
    broad_phase().Query(this, box);
  }

  // b2BroadPhase's query callback: every proxy whose box meets the polygon's.
  bool QueryCallback(int32 proxy) {
    const auto* fp = static_cast<const b2FixtureProxy*>(broad_phase().GetUserData(proxy));
    const Candidate c{fp->fixture, fp->childIndex};
    if (!takes(*c.fixture)) return true;
    candidates_->push_back(c);
    fingerprint_ += fingerprint_of(c);
    return true;
  }

  // Everything the group's edge data is found from (`polygon_edge_data`), as one word: the own
  // polygon and its body's frame, and each candidate gathered that the group could take in, its
  // frame and its shape's points, summed (the broad phase's order is its own).
  std::uint64_t fingerprint() const { return fingerprint_; }

  void consider_gathered() {
    for (const Candidate& c : *candidates_) consider(*c.fixture, c.child);
  }

  const std::vector<GroupPolygon>& polygons() const { return polygons_; }
  const std::vector<GroupSegment>& segments() const { return segments_; }

  // Two points of the group are one point, and a point lies on an edge's line, within this
  // distance (metres). Why: a vertex of another body is placed in the world by its body's
  // transform and brought back into this body's frame by this one's; each placement rounds the
  // rotation's cosine and sine, two products and a sum, about 3·FLT_EPSILON of the magnitudes
  // involved (the vertex, the body origins), and the bodies' origins were themselves computed by
  // the caller in floats (i · tile, a few roundings). 16·FLT_EPSILON of the sum of the magnitudes
  // covers both placements and the caller's with a margin of two; within one frame only the
  // caller's rounding of its own coordinates counts. It is 2 µm per 1 m of magnitude: 0.2 mm at
  // 100 m from the origin, 2 mm at 1 km, below Box2D's linear slop (5 mm) and its weld distance
  // (2.5 mm) in any world Box2D handles well, so only what is one point for Box2D is one point
  // here.
  float tolerance() const {
    return tolerance_for(placed_ ? magnitude(body_.GetTransform().p) + other_origins_ : 0);
  }

 private:
  const b2BroadPhase& broad_phase() const {
    return body_.GetWorld()->GetContactManager().m_broadPhase;
  }

  // True when fixture `f` may be taken into the group: another fixture with edges, no sensor
  // (nothing collides with one: no part of the outline), of a body sharing edges with the own
  // body.
  bool takes(const b2Fixture& f) const {
    return &f != &self_ && !f.IsSensor() && f.GetType() != b2Shape::e_circle &&
           share_edges(body_, *f.GetBody());
  }

  // Takes fixture `f` (child `child`), which the group may take (`takes`), when it touches the own
  // polygon.
  void consider(const b2Fixture& f, int child) {
    const b2Body& body = *f.GetBody();
    const b2PolygonShape* p = polygon_of(f);
    if (!p) {
      consider_edge(f, child);
      return;
    }
    GroupPolygon t = group_polygon(*p);
    const b2Transform& mine = body_.GetTransform();
    const b2Transform& theirs = body.GetTransform();
    // Bodies at the same place (tiles made at the origin): one frame, the coordinates as given.
    const bool one_frame = &body == &body_ || (mine.p.x == theirs.p.x && mine.p.y == theirs.p.y &&
                                               mine.q.c == theirs.q.c && mine.q.s == theirs.q.s);
    float origins = 0;
    if (!one_frame) {
      for (int i = 0; i < t.count; ++i) t.v[i] = b2MulT(mine, b2Mul(theirs, t.v[i]));
      origins = magnitude(mine.p) + magnitude(theirs.p);
    }
    if (!touches(t, tolerance_for(origins))) return;
    if (!one_frame) {
      placed_ = true;
      other_origins_ = std::max(other_origins_, magnitude(theirs.p));
    }
    polygons_.push_back(t);
  }

  // An edge or a chain's child edge of the group, kept when it ends at or passes through one of
  // the own polygon's vertices (within the tolerance).
  void consider_edge(const b2Fixture& f, int child) {
    const b2Shape* shape = f.GetShape();
    b2EdgeShape edge;
    if (shape->m_type == b2Shape::e_chain) {
      static_cast<const b2ChainShape*>(shape)->GetChildEdge(&edge, child);
    } else if (shape->m_type == b2Shape::e_edge) {
      edge = *static_cast<const b2EdgeShape*>(shape);
    } else {
      return;
    }
    const b2Body& body = *f.GetBody();
    GroupSegment s{edge.m_vertex1, edge.m_vertex2};
    float origins = 0;
    if (&body != &body_) {
      const b2Transform& mine = body_.GetTransform();
      const b2Transform& theirs = body.GetTransform();
      s = {b2MulT(mine, b2Mul(theirs, s.a)), b2MulT(mine, b2Mul(theirs, s.b))};
      origins = magnitude(mine.p) + magnitude(theirs.p);
    }
    const float tol = tolerance_for(origins);
    const GroupPolygon& own = polygons_.front();
    for (int i = 0; i < own.count; ++i) {
      const b2Vec2 d = s.b - s.a;
      const float off = b2Cross(d, own.v[i] - s.a);
      const float along = b2Dot(d, own.v[i] - s.a);
      if (off * off <= tol * tol * d.LengthSquared() && along >= -tol * d.Length() &&
          along <= d.LengthSquared() + tol * d.Length()) {
        segments_.push_back(s);
        return;
      }
    }
  }

  // The tolerance for points placed through frames whose origins sum to `origins` in magnitude.
  float tolerance_for(float origins) const {
    return coincidence_epsilons * FLT_EPSILON * (own_scale_ + origins);
  }

  // True when `t` may bound the own polygon's outline: a vertex of it lies on the line of an own
  // edge, or an own vertex on the line of one of its edges (within `tol`). Only such polygons
  // have an edge collinear with an own edge or through an own vertex, all that the masks read;
  // the others (most of what the broad phase's fattened box meets) are left out of every pass.
  bool touches(const GroupPolygon& t, float tol) const {
    const GroupPolygon& own = polygons_.front();
    const float tol_sq = tol * tol;
    const auto on_line = [&](const b2Vec2& a, const b2Vec2& b, const b2Vec2& p) {
      const b2Vec2 d = b - a;
      const float off = b2Cross(d, p - a);
      return off * off <= tol_sq * d.LengthSquared();
    };
    for (int i = 0; i < own.count; ++i) {
      for (int k = 0; k < t.count; ++k) {
        if (on_line(own.v[i], own.v[own.next(i)], t.v[k])) return true;
      }
    }
    for (int k = 0; k < t.count; ++k) {
      for (int i = 0; i < own.count; ++i) {
        if (on_line(t.v[k], t.v[t.next(k)], own.v[i])) return true;
      }
    }
    return false;
  }

  // The own polygon and its frame, mixed (`fingerprint`).
  std::uint64_t fingerprint_of_own() const {
    return mix(0x5EED'ED6E'DA7A'0002u, body_.GetTransform(), own_.m_vertices, own_.m_count);
  }

  // Candidate `c` (`takes`), its frame and points (a polygon's vertices, an edge's or a chain
  // child's ends) and kind, mixed.
  static std::uint64_t fingerprint_of(const Candidate& c) {
    const b2Shape* shape = c.fixture->GetShape();
    const b2Transform& xf = c.fixture->GetBody()->GetTransform();
    const std::uint64_t kind = static_cast<std::uint64_t>(shape->m_type);
    if (shape->m_type == b2Shape::e_polygon) {
      const auto& p = *static_cast<const b2PolygonShape*>(shape);
      return mix(kind, xf, p.m_vertices, p.m_count);
    }
    if (shape->m_type == b2Shape::e_edge) {
      const auto& e = *static_cast<const b2EdgeShape*>(shape);
      const b2Vec2 ends[2] = {e.m_vertex1, e.m_vertex2};
      return mix(kind, xf, ends, 2);
    }
    const auto& chain = *static_cast<const b2ChainShape*>(shape);
    return mix(kind, xf, &chain.m_vertices[c.child], 2);
  }

  const b2Fixture& self_;
  const b2Body& body_;
  const b2PolygonShape& own_;
  std::vector<GroupPolygon>& polygons_;
  std::vector<GroupSegment>& segments_;
  // The tolerance's scale (see `tolerance`): 16 FLT_EPSILON.
  static constexpr float coincidence_epsilons = 16;
  float own_scale_ = 0;      // the largest magnitude of the own polygon's coordinates
  bool placed_ = false;      // a polygon of another frame was placed in this one
  float other_origins_ = 0;  // the largest magnitude of those frames' origins
  std::vector<Candidate>* candidates_ = nullptr;  // gathered (`gather`)
  std::uint64_t fingerprint_ = 0;                 // of the own polygon and the candidates
};

// The segment a→b as a line: where points lie along it and how far off it.
struct Line {
  b2Vec2 from{0, 0};
  b2Vec2 unit{0, 0};
  float length = 0;

  Line() = default;
  Line(const b2Vec2& a, const b2Vec2& b) : from(a) {
    const b2Vec2 d = b - a;
    length = d.Length();
    unit = (1.0f / length) * d;
  }
  float along(const b2Vec2& x) const { return b2Dot(x - from, unit); }
  float off(const b2Vec2& x) const { return b2Cross(unit, x - from); }
};

// Parameters along a line: [lo, hi].
struct Interval {
  float lo;
  float hi;
};

// An edge of the group, from a to b (its polygon on its left).
struct Segment {
  b2Vec2 a;
  b2Vec2 b;
  // Bit i: both ends within the tolerance of the own polygon's edge line i (`on_own_lines`).
  std::uint8_t on_own_lines = 0;
};

// True when `x` lies within `tol` of `line` (the test of the opposite covers).
bool within(const Line& line, const b2Vec2& x, float tol) { return !(std::abs(line.off(x)) > tol); }

// Bit i set when `x` lies within `tol` of `lines[i]`, for the own polygon's `count` lines.
std::uint8_t on_own_lines(const Line* lines, int count, const b2Vec2& x, float tol) {
  unsigned bits = 0;
  for (int i = 0; i < count; ++i) bits |= static_cast<unsigned>(within(lines[i], x, tol)) << i;
  return static_cast<std::uint8_t>(bits);
}

// Whether a line is covered just before a point of it and just after it.
struct StretchesCovered {
  bool before = false;
  bool after = false;
};

// Whether the edges among `edges` running the other way along `line` (both ends within `tol` of
// it: their polygons lie on its other side) cover the line just before the parameter `t`
// (reaching `t` within `tol`), and just after it. Only what `want_before` and `want_after` ask
// for is looked for; the walk stops once that is found.
StretchesCovered opposite_cover_next_to(const std::vector<Segment>& edges, const Line& line,
                                        float t, float tol, bool want_before, bool want_after) {
  StretchesCovered covered;
  for (const Segment& e : edges) {
    if (b2Dot(e.b - e.a, line.unit) >= 0) continue;
    if (!within(line, e.a, tol) || !within(line, e.b, tol)) continue;
    const float lo = line.along(e.b);
    const float hi = line.along(e.a);
    covered.before = covered.before || (lo < t - tol && hi >= t - tol);
    covered.after = covered.after || (hi > t + tol && lo <= t + tol);
    if ((covered.before || !want_before) && (covered.after || !want_after)) break;
  }
  return covered;
}

// The same for the own polygon's edge line `i`, whose ends' tests were made once per vertex
// (`Segment::on_own_lines`): a vertex is shared by two edges of its polygon, and most edges lie
// on no own line. Not one template with `opposite_cover_next_to`: each tests first what rejects
// cheapest for its callers, here the bit, there the direction (measured: docs/measurements.md,
// "Choices in the code").
void opposite_cover_own(const std::vector<Segment>& edges, const Line& line, int i,
                        std::vector<Interval>& out) {
  out.clear();
  for (const Segment& e : edges) {
    if (!((e.on_own_lines >> i) & 1)) continue;
    if (b2Dot(e.b - e.a, line.unit) >= 0) continue;
    out.push_back({line.along(e.b), line.along(e.a)});
  }
}

// True when the intervals cover [0, length] with no gap wider than `tol` (sorts them).
bool covers_wholly(std::vector<Interval>& cover, float length, float tol) {
  std::sort(cover.begin(), cover.end(),
            [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
  float reach = 0;
  for (const Interval& i : cover) {
    if (i.lo > reach + tol) break;
    reach = std::max(reach, i.hi);
  }
  return reach >= length - tol;
}

// The outline pieces (the stretches of the group's edges that no opposite edge covers) entering
// and leaving a vertex.
struct VertexOutline {
  b2Vec2 in{0, 0};
  b2Vec2 out{0, 0};
  int ins = 0;
  int outs = 0;

  // Gathers the pieces at `at` from every edge of `edges` that ends at it, starts at it, or (a
  // T-junction) passes through it. Only the stretch next to `at` counts: a neighbour's edge
  // covered elsewhere in part still bounds the outline here. What covers such a stretch passes
  // through `at` or ends there too, so the cover is looked for among these edges alone. Stops
  // once two pieces enter or two leave: the outline there is no simple one (`flat_or_reflex`),
  // cheaper than a cover built whole for every edge and searched after.
  void gather(const std::vector<Segment>& edges, const b2Vec2& at, float tol) {
    const float tol_sq = tol * tol;
    thread_local std::vector<Segment> near;  // the edges through `at`
    near.clear();
    for (const Segment& e : edges) {
      const b2Vec2 edge = e.b - e.a;
      const float off = b2Cross(edge, at - e.a);
      if (off * off <= tol_sq * edge.LengthSquared()) near.push_back(e);
    }
    for (const Segment& e : near) {
      const bool starts = (e.a - at).LengthSquared() <= tol_sq;
      const bool ends = !starts && (e.b - at).LengthSquared() <= tol_sq;
      const Line line(e.a, e.b);
      const float s = starts ? 0 : ends ? line.length : line.along(at);
      if (!starts && !ends && (s <= tol || s >= line.length - tol)) continue;  // off its ends
      const StretchesCovered covered = opposite_cover_next_to(near, line, s, tol, !starts, !ends);
      if (!starts && !covered.before) {
        in = e.b - e.a;
        ++ins;
      }
      if (!ends && !covered.after) {
        out = e.b - e.a;
        ++outs;
      }
      if (ins > 1 || outs > 1) return;
    }
  }

  // A simple outline vertex (one piece in, one out) turning by less than a corner, or reflex.
  bool flat_or_reflex() const { return ins == 1 && outs == 1 && turns_flat_or_reflex(in, out); }
};

// The rays at one end of a two-sided edge: the directions, in the edge's body frame, along which
// the group's edges leave that point.
class EndRays {
 public:
  EndRays(const b2Fixture& self, const b2Vec2& at, std::vector<b2Vec2>& scratch)
      : self_(self), body_(*self.GetBody()), at_(at), rays_(scratch) {
    rays_.clear();
  }

  void collect() {
    const float reach = 2 * tolerance_for(magnitude(body_.GetTransform().p));
    if (body_.GetType() != b2_staticBody) {
      for (const b2Fixture* f = body_.GetFixtureList(); f; f = f->GetNext()) {
        for (int child = 0; child < f->GetShape()->GetChildCount(); ++child) consider(*f, child);
      }
      return;
    }
    const b2Vec2 p = b2Mul(body_.GetTransform(), at_);
    b2AABB box;
    box.lowerBound = p - b2Vec2(reach, reach);
    box.upperBound = p + b2Vec2(reach, reach);
    broad_phase().Query(this, box);
  }

  // b2BroadPhase's query callback: every proxy whose box meets the end's.
  bool QueryCallback(int32 proxy) {
    const auto* fp = static_cast<const b2FixtureProxy*>(broad_phase().GetUserData(proxy));
    consider(*fp->fixture, fp->childIndex);
    return true;
  }

  const std::vector<b2Vec2>& rays() const { return rays_; }

 private:
  const b2BroadPhase& broad_phase() const {
    return body_.GetWorld()->GetContactManager().m_broadPhase;
  }

  // Points of two frames whose origins sum to `origins` in magnitude are one point within this
  // (`Group::tolerance`'s rule).
  float tolerance_for(float origins) const { return 16 * FLT_EPSILON * (magnitude(at_) + origins); }

  void consider(const b2Fixture& f, int child) {
    if (&f == &self_ || f.IsSensor()) return;
    const b2Body& body = *f.GetBody();
    if (!share_edges(body_, body)) return;
    b2Vec2 v[b2_maxPolygonVertices];
    int count = 0;
    bool closed = false;  // a polygon's outline closes on itself; an edge's does not
    const b2Shape* shape = f.GetShape();
    if (shape->m_type == b2Shape::e_polygon) {
      const auto& p = *static_cast<const b2PolygonShape*>(shape);
      count = p.m_count;
      for (int i = 0; i < count; ++i) v[i] = p.m_vertices[i];
      closed = true;
    } else if (shape->m_type == b2Shape::e_edge || shape->m_type == b2Shape::e_chain) {
      b2EdgeShape edge;
      if (shape->m_type == b2Shape::e_chain) {
        static_cast<const b2ChainShape*>(shape)->GetChildEdge(&edge, child);
      } else {
        edge = *static_cast<const b2EdgeShape*>(shape);
      }
      v[0] = edge.m_vertex1;
      v[1] = edge.m_vertex2;
      count = 2;
    } else {
      return;  // a circle is no part of an outline
    }
    const b2Transform& mine = body_.GetTransform();
    const b2Transform& theirs = body.GetTransform();
    float origins = 0;
    if (&body != &body_) {
      for (int i = 0; i < count; ++i) v[i] = b2MulT(mine, b2Mul(theirs, v[i]));
      origins = magnitude(mine.p) + magnitude(theirs.p);
    }
    const float tol = tolerance_for(origins);
    const int segments = closed ? count : 1;
    for (int i = 0; i < segments; ++i) {
      const b2Vec2& a = v[i];
      const b2Vec2& b = v[(i + 1) % count];
      const bool at_a = b2DistanceSquared(a, at_) <= tol * tol;
      const bool at_b = !at_a && b2DistanceSquared(b, at_) <= tol * tol;
      if (at_a || at_b) {
        rays_.push_back(at_a ? b - a : a - b);
        continue;
      }
      // Through the point, off both ends: a T-junction, rays both ways.
      const Line line(a, b);
      const float t = line.along(at_);
      if (t > tol && t < line.length - tol && within(line, at_, tol)) {
        rays_.push_back(b - a);
        rays_.push_back(a - b);
      }
    }
  }

  const b2Fixture& self_;
  const b2Body& body_;
  b2Vec2 at_;
  std::vector<b2Vec2>& rays_;
};

// `EdgeEnds::corner_cos` of a free space spanning `angle` (radians) beside an edge's end: its
// cosine in 127ths rounded down, where narrower than a half-turn by more than the flat tolerance.
std::int8_t corner_cos(float angle) {
  if (!(angle < b2_pi - std::asin(flat_outline_sine))) return -127;
  return static_cast<std::int8_t>(std::max(-127.0f, std::floor(127 * std::cos(angle))));
}

// The angle (0, 2π] from `from` to `to` turning counter-clockwise (`ccw`) or clockwise.
float turn_angle(const b2Vec2& from, const b2Vec2& to, bool ccw) {
  float a = std::atan2(b2Cross(from, to), b2Dot(from, to));
  if (!ccw) a = -a;
  return a <= 0 ? a + 2 * b2_pi : a;
}

}  // namespace

EdgeEnds edge_ends(const b2Fixture& fixture) {
  EdgeEnds out{};
  if (fixture.GetType() != b2Shape::e_edge) return out;
  const auto& edge = *static_cast<const b2EdgeShape*>(fixture.GetShape());
  // A flat or reflex end: the free space on that side spans at most a half-turn and the flat
  // tolerance.
  const float most = b2_pi + std::asin(flat_outline_sine);
  thread_local std::vector<b2Vec2> scratch;
  for (int k = 0; k < 2; ++k) {
    const b2Vec2& at = k == 0 ? edge.m_vertex1 : edge.m_vertex2;
    const b2Vec2 along = (k == 0 ? edge.m_vertex2 : edge.m_vertex1) - at;
    EndRays rays(fixture, at, scratch);
    rays.collect();
    // The front lies clockwise from the edge at its first end, counter-clockwise at its second.
    float front = 2 * b2_pi;
    float back = 2 * b2_pi;
    for (const b2Vec2& r : rays.rays()) {
      const float ccw = turn_angle(along, r, true);
      if (ccw >= 2 * b2_pi) continue;  // along the edge itself: no bound on either side
      const float cw = 2 * b2_pi - ccw;
      front = std::min(front, k == 0 ? cw : ccw);
      back = std::min(back, k == 0 ? ccw : cw);
    }
    const auto bit = static_cast<std::uint8_t>(1u << k);
    if (front <= most) out.closed_front |= bit;
    if (back <= most) out.closed_back |= bit;
    out.corner_cos[k][0] = corner_cos(front);
    out.corner_cos[k][1] = corner_cos(back);
  }
  return out;
}

bool beyond_corner(const EdgeEnds& ends, const b2Vec2& v1, const b2Vec2& v2, bool back,
                   const b2Vec2& c) {
  const int side = back ? 1 : 0;
  // The body's side's normal, unnormalised (|v2 − v1|): the front is right of v1 → v2.
  const b2Vec2 along = v2 - v1;
  const b2Vec2 normal = back ? b2Vec2(-along.y, along.x) : b2Vec2(along.y, -along.x);
  for (int k = 0; k < 2; ++k) {
    const int code = ends.corner_cos[k][side];
    if ((ends.neighbours() >> k & 1u) == 0 || code <= -127) continue;
    // In the frame of the end: x along the edge into it, y toward the body's side; the corner's
    // other edge leaves the end at angle θ from x toward y, and c lies beyond it when
    // cos θ · y > sin θ · x (both sides scaled by |v2 − v1|).
    const b2Vec2 d = c - (k == 0 ? v1 : v2);
    const float x = k == 0 ? b2Dot(along, d) : -b2Dot(along, d);
    const float y = b2Dot(normal, d);
    const float cos = static_cast<float>(code) / 127;
    const float sin = std::sqrt(std::max(0.0f, 1 - cos * cos));
    if (y > 0 && cos * y > sin * x) return true;
  }
  return false;
}

namespace {

// The counter-clockwise angle from `from` to `to`, in [0, 2π).
float ccw_angle(const b2Vec2& from, const b2Vec2& to) {
  const float a = std::atan2(b2Cross(from, to), b2Dot(from, to));
  return a < 0 ? a + 2 * b2_pi : a;
}

// The rays from `at` along `a`→`b` that end at `at` or pass through it, within `tol`, to `take`.
template <class Take>
void rays_at(const b2Vec2& at, const b2Vec2& a, const b2Vec2& b, float tol, const Take& take) {
  const bool at_a = b2DistanceSquared(a, at) <= tol * tol;
  const bool at_b = !at_a && b2DistanceSquared(b, at) <= tol * tol;
  if (at_a || at_b) {
    take(at_a ? b - a : a - b);
    return;
  }
  const Line line(a, b);
  const float t = line.along(at);
  if (t > tol && t < line.length - tol && within(line, at, tol)) {
    take(b - a);
    take(a - b);
  }
}

// The first vertex of `polygons.front()` where `segments` (edges of its group) meet it, as a
// junction (`Junction`): every ray from the vertex along the group's edges and polygons' edges
// that lies in the free space between its own edge in and its edge out, the first and the last
// met turning counter-clockwise from its edge in; none where no edge's ray is among them.
Junction junction_of(const std::vector<GroupPolygon>& polygons,
                     const std::vector<GroupSegment>& segments, float tol) {
  const GroupPolygon& own = polygons.front();
  const float half_turn = b2_pi + std::asin(flat_outline_sine);
  Junction j;
  for (int i = 0; i < own.count && j.vertex == Junction::none; ++i) {
    const b2Vec2& at = own.v[i];
    const b2Vec2 in = own.v[i > 0 ? i - 1 : own.count - 1] - at;
    const float out = ccw_angle(in, own.v[own.next(i)] - at);
    float first = out;
    float last = 0;
    b2Vec2 first_ray(0, 0);
    b2Vec2 last_ray(0, 0);
    bool edge_ray = false;
    const auto take = [&](const b2Vec2& ray, bool of_edge) {
      const float a = ccw_angle(in, ray);
      if (!(a > 0 && a < out)) return;  // along or within the polygon's own corner
      edge_ray = edge_ray || of_edge;
      if (a < first) first = a, first_ray = ray;
      if (a > last) last = a, last_ray = ray;
    };
    for (const GroupSegment& s : segments) {
      rays_at(at, s.a, s.b, tol, [&](const b2Vec2& ray) { take(ray, true); });
    }
    if (!edge_ray) continue;
    for (std::size_t k = 1; k < polygons.size(); ++k) {
      const GroupPolygon& t = polygons[k];
      for (int e = 0; e < t.count; ++e) {
        rays_at(at, t.v[e], t.v[t.next(e)], tol, [&](const b2Vec2& ray) { take(ray, false); });
      }
    }
    j.vertex = static_cast<std::uint8_t>(i);
    j.first = junction_angle(std::atan2(first_ray.y, first_ray.x));
    j.last = junction_angle(std::atan2(last_ray.y, last_ray.x));
    j.closed_in = first <= half_turn;
    j.closed_out = out - last <= half_turn;
  }
  return j;
}

}  // namespace

ShapeMasks junction_masks(const Junction& j, const b2PolygonShape& p, const b2Vec2& other) {
  if (j.vertex == Junction::none || j.vertex >= p.m_count) return {};
  const int i = j.vertex;
  const int before = i > 0 ? i - 1 : p.m_count - 1;
  const b2Vec2& at = p.m_vertices[i];
  const b2Vec2 in = p.m_vertices[before] - at;
  const float out = ccw_angle(in, p.m_vertices[i + 1 < p.m_count ? i + 1 : 0] - at);
  const auto angle_of = [&](std::int16_t code) {
    const float a = junction_angle(code);
    return ccw_angle(in, b2Vec2(std::cos(a), std::sin(a)));
  };
  const float body = ccw_angle(in, other - at);
  if (!(body > 0 && body < out)) return {};
  const auto bit = [](int k) { return static_cast<std::uint8_t>(1u << k); };
  ShapeMasks m;
  if (body < angle_of(j.first)) {  // next to the edge in: the edge out is hidden
    m.edges = bit(i);
    if (j.closed_in) m.closed_vertices = bit(i);
  } else if (body > angle_of(j.last)) {  // next to the edge out: the edge in is hidden
    m.edges = bit(before);
    if (j.closed_out) m.closed_vertices = bit(i);
  } else {  // between other edges: both hidden
    m.edges = static_cast<std::uint8_t>(bit(i) | bit(before));
    m.closed_vertices = bit(i);
  }
  return m;
}

ShapeMasks polygon_internal_edges(const b2Fixture& fixture) {
  return polygon_edge_data(fixture).masks;
}

namespace {

// The edge data of the group's own polygon (`polygon_edge_data`), its group collected.
PolygonEdgeData edge_data_of(const Group& group) {
  PolygonEdgeData out;
  const std::vector<GroupPolygon>& polygons = group.polygons();
  const float tol = group.tolerance();
  if (!group.segments().empty()) out.junction = junction_of(polygons, group.segments(), tol);
  if (polygons.size() == 1) return out;
  ShapeMasks& masks = out.masks;
  const GroupPolygon& self = polygons.front();
  const int n = self.count;
  Line lines[b2_maxPolygonVertices] = {};
  for (int i = 0; i < n; ++i) lines[i] = Line(self.v[i], self.v[self.next(i)]);
  thread_local std::vector<Segment> edges;
  edges.clear();
  for (const GroupPolygon& t : polygons) {
    std::uint8_t on[b2_maxPolygonVertices];
    for (int k = 0; k < t.count; ++k) on[k] = on_own_lines(lines, n, t.v[k], tol);
    for (int k = 0; k < t.count; ++k) {
      edges.push_back({t.v[k], t.v[t.next(k)], static_cast<std::uint8_t>(on[k] & on[t.next(k)])});
    }
  }

  thread_local std::vector<Interval> cover;
  for (int i = 0; i < n; ++i) {
    opposite_cover_own(edges, lines[i], i, cover);
    if (covers_wholly(cover, lines[i].length, tol)) {
      masks.edges |= static_cast<std::uint8_t>(1u << i);
    }
  }
  for (int i = 0; i < n; ++i) {
    const int before = i > 0 ? i - 1 : n - 1;
    const bool out_internal = (masks.edges >> i) & 1;
    const bool in_internal = (masks.edges >> before) & 1;
    // An own edge covered in part, next to the vertex (a T-junction where rectangles of two
    // heights meet under a flat top): as for an internal edge, the outline through the vertex
    // decides. A triangulated ground's edges are covered wholly or not at all near their ends.
    const bool covered_next_to =
        out_internal || in_internal ||
        opposite_cover_next_to(edges, lines[i], 0, tol, false, true).after ||
        opposite_cover_next_to(edges, lines[before], lines[before].length, tol, true, false).before;
    // A corner of the outline made by this polygon's own two edges: every direction between
    // their normals is the outline's, as for a lone polygon.
    if (!covered_next_to) continue;
    // Both edges internal: the vertex is inside the group, or on the outline between other
    // polygons' edges (a fan's apex touching the top), whose own pairs carry its contact with
    // their edges' normals; none of this polygon's pairs may push there.
    if (!(out_internal && in_internal)) {
      // One edge internal (or covered next to it): closed where the outline through the vertex
      // is flat or reflex. Every
      // polygon touching the vertex is in the group found, so the outline pieces there are all
      // seen.
      VertexOutline outline;
      outline.gather(edges, self.v[i], tol);
      if (!outline.flat_or_reflex()) continue;
    }
    masks.closed_vertices |= static_cast<std::uint8_t>(1u << i);
  }
  return out;
}

}  // namespace

PolygonEdgeData polygon_edge_data(const b2Fixture& fixture) {
  const b2PolygonShape* own = polygon_of(fixture);
  if (!own) return {};
  const b2Body& body = *fixture.GetBody();
  const bool alone = body.GetFixtureList() == &fixture && fixture.GetNext() == nullptr;
  if (alone && body.GetType() != b2_staticBody) return {};

  thread_local std::vector<GroupPolygon> scratch;
  thread_local std::vector<GroupSegment> segment_scratch;
  Group group(fixture, *own, scratch, segment_scratch);
  if (group.walked()) {
    group.walk();
    return edge_data_of(group);
  }
  thread_local std::vector<Candidate> candidates;
  group.gather(candidates);
  // A static polygon's group moves only when a static fixture near it changes: its edge data as
  // found last is memoised under the fingerprint (a moving body's frame moves every step).
  const bool memo = body.GetType() == b2_staticBody;
  if (memo) {
    if (const std::optional<PolygonEdgeData> held =
            memoised_edge_data(fixture, group.fingerprint())) {
      return *held;
    }
  }
  group.consider_gathered();
  const PolygonEdgeData found = edge_data_of(group);
  if (memo) memoise_edge_data(fixture, group.fingerprint(), found);
  return found;
}

InternalEdges triangle_internal_edges(const b2Fixture& fixture) {
  const b2PolygonShape* own = polygon_of(fixture);
  if (!own || own->m_count != 3) return {};
  const ShapeMasks m = polygon_internal_edges(fixture);
  return {m.edges, m.closed_vertices};
}

}  // namespace detail

InternalEdges triangle_internal_edges(const b2Fixture& fixture) {
  return detail::triangle_internal_edges(fixture);
}

ShapeMasks polygon_internal_edges(const b2Fixture& fixture) {
  return detail::polygon_internal_edges(fixture);
}

}  // namespace dyop::box2d
