// libFuzzer target for `collide` on the convex pairs beyond two triangles: polygon–polygon (3 to 8
// vertices each) and polygon–circle, A a segment where it has 2 vertices, in float or double.
//
// Format: byte 0: bit 0 set: float, else double; bit 1 set: grid encoding, else raw (as
// fuzz_input.hpp's, over this input's numbers); bit 2 set: B is a circle. Byte 1: A's vertex count
// (low nibble mod 9) and B's (high nibble mod 9; a circle ignores it), so that counts the
// validation refuses come too. Then A's vertices x, y, ..., then B's vertices or the circle's
// centre and radius. Then 4 bytes: A's internal-edge masks (edges, closed vertices), then B's.
// Missing bytes read as zero.
//
// What it asserts, besides "no crash, no sanitizer report":
// - `Polygon<T>::make` (`Segment<T>::make` for 2 vertices) and `Circle<T>::check` decide every
//   input, and `make` agrees with `check`;
// - a valid pair is answered at every level, never `Invalid`, every field the level promises
//   finite, also with the masks, which change no status;
// - the separation is within the exact bound (double 1e-12, float 1e-5 of the pair's size) of the
//   exact rational reference, and the status is the exact sign's outside the touching band;
// - the answer does not depend on A's winding (bit for bit; a segment has none).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "dyop/convex_pair.hpp"
#include "exact_reference/exact_reference.hpp"
#include "fuzz_input.hpp"
#include "workloads/finite_fields.hpp"

namespace dyop::fuzz {
namespace {

struct ConvexInput {
  bool is_float = false;
  bool circle = false;
  workloads::RawPolygon a;
  workloads::RawPolygon b;    // when not `circle`
  workloads::RawCircle disk;  // when `circle`
  ShapeMasks masks_a;
  ShapeMasks masks_b;
};

ConvexInput decode_convex(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  ConvexInput out;
  const auto mode = in.get<std::uint8_t>();
  out.is_float = (mode & 1u) != 0;
  out.circle = (mode & 4u) != 0;
  const auto counts = in.get<std::uint8_t>();
  out.a.count = (counts & 0xFu) % (max_polygon_vertices + 1);
  out.b.count = out.circle ? 0 : (counts >> 4) % (max_polygon_vertices + 1);
  const int numbers = 2 * (out.a.count + out.b.count) + (out.circle ? 3 : 0);
  std::array<double, kMaxFuzzCoordinates> c{};
  read_coordinates(in, out.is_float, (mode & 2u) != 0, numbers, c.data());
  int k = 0;
  for (auto* p : {&out.a, &out.b}) {
    for (int i = 0; i < p->count; ++i, k += 2) {
      p->v[static_cast<std::size_t>(i)] =
          Vec2<double>(c[static_cast<std::size_t>(k)], c[static_cast<std::size_t>(k + 1)]);
    }
  }
  if (out.circle) {
    out.disk.center =
        Vec2<double>(c[static_cast<std::size_t>(k)], c[static_cast<std::size_t>(k + 1)]);
    out.disk.radius = c[static_cast<std::size_t>(k + 2)];
  }
  out.masks_a = {in.get<std::uint8_t>(), in.get<std::uint8_t>()};
  out.masks_b = {in.get<std::uint8_t>(), in.get<std::uint8_t>()};
  return out;
}

void print_polygon(const workloads::RawPolygon& p) {
  for (int i = 0; i < p.count; ++i) {
    const Vec2<double>& v = p.v[static_cast<std::size_t>(i)];
    std::fprintf(stderr, " (%.17g, %.17g)", v.x(), v.y());
  }
}

[[noreturn]] void fail(const char* what, const ConvexInput& in) {
  std::fprintf(stderr, "fuzz_convex: %s (%s) on A", what, in.is_float ? "float" : "double");
  print_polygon(in.a);
  if (in.circle) {
    std::fprintf(stderr, ", circle (%.17g, %.17g) r %.17g\n", in.disk.center.x(),
                 in.disk.center.y(), in.disk.radius);
  } else {
    std::fprintf(stderr, ", B");
    print_polygon(in.b);
    std::fprintf(stderr, "\n");
  }
  std::abort();
}

void require(bool ok, const char* what, const ConvexInput& in) {
  if (!ok) fail(what, in);
}

template <class T>
bool same_bits(T x, T y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

// Every check on a valid pair; `solve(a, query)` answers it with A given as `a`.
template <class T, class A, class Raw, class Solve>
void check_pair(const ConvexInput& in, const Raw& raw, const A& a, const A& a_reversed,
                T shape_size, Solve solve) {
  Status plain = Status::Invalid;
  for (Level level : all_levels) {
    ConvexQuery<T> q{level};
    q.margin = T(0.01) * shape_size;
    q.face_hysteresis = T(0.001) * shape_size;
    const Result<T> r = solve(a, q);
    require(r.status != Status::Invalid, "Invalid on a valid pair", in);
    require(workloads::finite_at(r, level), "NaN or inf in a field the level promises", in);
    plain = r.status;
    q.masks_a = in.masks_a;
    q.masks_b = in.masks_b;
    const Result<T> masked = solve(a, q);
    require(masked.status == r.status, "the masks change the status", in);
    require(workloads::finite_at(masked, level), "NaN or inf with masks", in);
  }
  const Result<T> r = solve(a, ConvexQuery<T>{Level::Depth});
  const Result<T> w = solve(a_reversed, ConvexQuery<T>{Level::Depth});
  require(w.status == r.status && same_bits(w.separation, r.separation) &&
              same_bits(w.normal.x(), r.normal.x()) && same_bits(w.normal.y(), r.normal.y()),
          "A's winding changes the answer", in);
  const workloads::ExactAnswer exact = workloads::exact_separation(raw);
  const double size = workloads::pair_size(raw);
  const double bound = workloads::exact_bound(workloads::precision_of<T>());
  require(std::abs(double(r.separation) - exact.separation) <= bound * size,
          "the separation is not within the exact bound", in);
  if (std::abs(exact.separation) > 4 * double(touching_tolerance<T>()) * size) {
    require(plain == (exact.sign < 0 ? Status::Penetrating : Status::Separated),
            "the status is not the exact one", in);
  }
}

// A validated (`a`, and `a_reversed` in the other winding: itself for a segment) against B.
template <class T, class A>
void run_against_b(const ConvexInput& in, const A& a, const A& a_reversed) {
  if (in.circle) {
    const Circle<T> disk = workloads::build<T>(in.disk);
    if (Circle<T>::check(disk.center, disk.radius) != ConvexError::None) return;
    check_pair<T>(in, workloads::RawCirclePair{in.a, in.disk}, a, a_reversed,
                  std::max(a.size(), disk.radius),
                  [&](const A& pa, const ConvexQuery<T>& q) { return collide(pa, disk, q); });
    return;
  }
  const PolygonOrError<T> b = workloads::build<T>(in.b);
  if (!b.ok()) return;
  check_pair<T>(in, workloads::RawPolygonPair{in.a, in.b}, a, a_reversed,
                std::max(a.size(), b.polygon.size()),
                [&](const A& pa, const ConvexQuery<T>& q) { return collide(pa, b.polygon, q); });
}

template <class T>
void run(const ConvexInput& in) {
  const auto va = workloads::vertices_in<T>(in.a);
  if (in.a.count == 2) {
    const SegmentOrError<T> s = Segment<T>::make(va[0], va[1]);
    require(s.error == Segment<T>::check(va[0], va[1]), "make and check disagree on A", in);
    if (s.ok()) run_against_b<T>(in, s.segment, s.segment);
    return;
  }
  const PolygonOrError<T> a = Polygon<T>::make(va.data(), in.a.count);
  require(a.error == Polygon<T>::check(va.data(), in.a.count), "make and check disagree on A", in);
  if (!a.ok()) return;
  const PolygonOrError<T> ra = workloads::build<T>(workloads::reversed(in.a));
  require(ra.ok(), "A refused in the other winding", in);
  run_against_b<T>(in, a.polygon, ra.polygon);
}

}  // namespace
}  // namespace dyop::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const dyop::fuzz::ConvexInput in = dyop::fuzz::decode_convex(data, size);
  if (in.is_float) {
    dyop::fuzz::run<float>(in);
  } else {
    dyop::fuzz::run<double>(in);
  }
  return 0;
}
