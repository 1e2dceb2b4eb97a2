#pragma once
// Internal: the batch kernel behind `penetrate_batch`, written once over a "lanes" type so the
// portable path (one pair per step), the AVX2 path (8 float or 4 double pairs per instruction) and
// the AVX-512 path (16 or 8) run the same algorithm: validation as `Triangle<T>::make` decides it,
// the six overlaps of `sat` in a frame at A's first vertex, and for pairs found apart the exact
// distance, settled by one of two certificates or, failing both (pairs with parallel edges), by
// all vertex–edge distances. The only branches on the data are per block: "is any pair apart",
// "does any need more".
//
// Every lanes type performs the same IEEE operations in the same order on each pair, so all
// kernels give the same bits (tests/dyop/batch_kernels_test.cpp): every translation unit that
// includes this header is compiled with -ffp-contract=off, fusing happens only where `fma` is
// called, and the reciprocal square root is one shared refinement (`refine_inv_sqrt`) of the same
// hardware estimate (the SSE `rsqrtps` family, the same table for one lane or sixteen on a given
// CPU).
//
// This header includes no library header (no Eigen, no iostream) and calls no function of the
// standard library: the AVX2 and AVX-512 translation units include it and are compiled for those
// instruction sets, and any inline function it emitted could be the copy the linker keeps for the
// whole program, running AVX2 code on a CPU without it. Every template here is instantiated with
// the including file's lanes type, which lives in an unnamed namespace, so every instantiation is
// local.
//
// A lanes type `L` provides:
// - `T` (scalar), `V` (kWidth scalars, with + - * / and unary -), `M` (a mask), `kWidth`;
// - `kHasRangeLimit`: true when `inv_sqrt` takes only arguments in [kEstimateMin, kEstimateMax]
//   (rows with a squared edge length outside are redone by the portable lanes);
// - load, store, splat, infinity, fma (a·b + c, rounded once), min and max (x86's: `a < b ? a :
//   b`, `a > b ? a : b`), abs, flip (x with its sign flipped where s is negative), sqrt,
//   rsqrt_estimate (the hardware estimate of 1/sqrt, taken in float), inv_sqrt;
// - lt, gt, both, either, but_not (a and not b), select (m ? a : b, for values and masks), bits
//   (lane k's mask as bit k), min_where (m ? min(least, x) : least);
// - for arguments known to be non-negative and not NaN: min_nonneg, max_nonneg, lt_nonneg (the
//   vector lanes do them in the integer unit where they can: such floats order as their bits do);
// - within (every one of n coordinates finite with magnitude ≤ limit; a NaN may instead be left
//   to the flatness test, which it always fails) and store_status (the codes below).

#include <cstddef>
#include <cstdint>

namespace dyop::detail {

// `dyop::Status` as numbers (batch.cpp checks that they agree with the enum).
inline constexpr std::uint8_t kStatusSeparated = 0;
inline constexpr std::uint8_t kStatusTouching = 1;
inline constexpr std::uint8_t kStatusPenetrating = 2;
inline constexpr std::uint8_t kStatusInvalid = 3;

// A checked `PairBatch` plus its outputs, as plain pointers.
template <class T>
struct BatchView {
  const T* a[6];  // ax0, ay0, ax1, ay1, ax2, ay2
  const T* b[6];  // bx0, by0, bx1, by1, bx2, by2
  std::uint8_t* status;
  T* separation;  // null at Level::Overlap, as are the normals
  T* normal_x;
  T* normal_y;
  std::size_t count;
};

// The library's named tolerances, passed in (see the note on includes above).
template <class T>
struct BatchLimits {
  T max_coordinate;        // max_coordinate<T>()
  T min_size_sq;           // min_size<T>()²
  T degenerate_tolerance;  // degenerate_tolerance<T>()
  T touching_tolerance;    // touching_tolerance<T>()
};

// The squared lengths the estimate takes: normal floats (it is taken in float, and flushes
// subnormals to zero).
template <class T>
inline constexpr T kEstimateMin = T(0x1p-126f);
template <class T>
inline constexpr T kEstimateMax = T(0x1.fffffep127f);

// 1/sqrt(q) from the estimate y of `L::rsqrt_estimate` (relative error ε ≤ 1.5·2⁻¹²), the same
// operations in every lanes type. Float: one Halley step, y·(1 + e/2 + 3e²/8) with e = 1 − q·y²,
// whose error is cubic in ε: ≤ 2 ulp. Double: the series y·(1 − e)^(-1/2) to the 4th order, error
// ≈ (63/256)·(2ε)⁵ ≈ 5e-17: ≤ 2 ulp. The residual e is fused, so exact to an ulp.
template <class L>
typename L::V refine_inv_sqrt(typename L::V q, typename L::V y) {
  using T = typename L::T;
  using V = typename L::V;
  const V e = L::fma(-(q * y), y, L::splat(T(1)));
  V p;
  if constexpr (sizeof(T) == sizeof(float)) {
    p = L::fma(e, L::splat(T(0.375)), L::splat(T(0.5)));
  } else {
    p = L::fma(e, L::splat(T(35.0 / 128)), L::splat(T(5.0 / 16)));
    p = L::fma(p, e, L::splat(T(3.0 / 8)));
    p = L::fma(p, e, L::splat(T(1.0 / 2)));
  }
  return L::fma(y * e, p, y);
}

// Recomputes one row with the portable lanes (defined in batch.cpp): the vector paths hand it the
// rows their reciprocal square root cannot take (a squared edge length out of its range).
template <class T>
void penetrate_row_portable(const BatchView<T>& v, const BatchLimits<T>& lim, bool depth,
                            std::size_t row);

// `sat`'s status (and with kDepth its separation and normal) for `L::kWidth` pairs at a time: the
// algorithm itself, run with the lanes `dyop::BatchKernel` chooses.
template <class L, bool kDepth>
struct SatOverLanes {
  using T = typename L::T;
  using V = typename L::V;
  using M = typename L::M;
  static constexpr int kWidth = L::kWidth;

  struct Vec {
    V x, y;
  };

  static V dot(const Vec& u, const Vec& p) { return L::fma(u.x, p.x, u.y * p.y); }
  static V squared(const Vec& e) { return e.x * e.x + e.y * e.y; }  // as squaredNorm()
  static V min3(V p, V q, V r) { return L::min(L::min(p, q), r); }
  static V max3(V p, V q, V r) { return L::max(L::max(p, q), r); }

  // Twice the area against the flatness bound on the longest edge², as Triangle<T>::make tests it.
  static M well_shaped(V area, V longest_sq, const BatchLimits<T>& lim) {
    return L::gt(L::abs(area), L::splat(lim.degenerate_tolerance) * longest_sq);
  }

  // Which of six overlaps is the least (the first on ties), as the masks of a three-level tree:
  // the minimum is on the critical path (a tree, not a chain), and the same masks then pick
  // whatever else goes with the winning axis.
  struct Order {
    M m01, m23, m45, m03, m05;
  };
  static Order order(const V (&o)[6], V& least) {
    Order t;
    t.m01 = L::lt(o[1], o[0]);
    t.m23 = L::lt(o[3], o[2]);
    t.m45 = L::lt(o[5], o[4]);
    const V o01 = L::select(t.m01, o[1], o[0]);
    const V o23 = L::select(t.m23, o[3], o[2]);
    const V o45 = L::select(t.m45, o[5], o[4]);
    t.m03 = L::lt(o23, o01);
    const V o03 = L::select(t.m03, o23, o01);
    t.m05 = L::lt(o45, o03);
    least = L::select(t.m05, o45, o03);
    return t;
  }
  template <class X>
  static X pick(const Order& t, const X (&x)[6]) {
    const X x03 = L::select(t.m03, L::select(t.m23, x[3], x[2]), L::select(t.m01, x[1], x[0]));
    return L::select(t.m05, L::select(t.m45, x[5], x[4]), x03);
  }

  // Keeps in (least, dir) the smaller of two non-negative values and the direction that goes
  // with it.
  static void keep_nearer(V& least, Vec& dir, V value, const Vec& value_dir) {
    const M less = L::lt_nonneg(value, least);
    least = L::min_nonneg(value, least);
    dir.x = L::select(less, value_dir.x, dir.x);
    dir.y = L::select(less, value_dir.y, dir.y);
  }

  // One pair in A's frame (a_0 is the origin), edges in the caller's order (edge i from vertex i
  // to i + 1), and the projections the overlaps are made of, all without a square root: the
  // projections are taken on the edges' perpendiculars as they are (length |e|) and scaled by
  // 1/|e| afterwards, so that they do not wait for the reciprocal square roots.
  struct Pair {
    Vec a1, a2;        // A's vertices 1 and 2
    Vec b[3];          // B's vertices
    Vec ea[3], eb[3];  // edge vectors
    V qa[3], qb[3];    // their squared lengths
    V area_a, area_b;  // twice the signed areas
    Vec ma[3], mb[3];  // A's outward perpendiculars; B's inward ones (both point from A to B)
    V pb[3][3];        // ma[i]·b[j]
    V ca1;             // ma[1]·a1: A's edge 1's line (edges 0 and 2 pass through the origin)
    V pa[3][2];        // mb[j]·a1, mb[j]·a2 (mb[j]·a0 = 0)
    V cb[3];           // mb[j]·b[j]: B's edge j's line
  };

  static void load(const BatchView<T>& v, std::size_t row, V (&in)[12]) {
    for (int k = 0; k < 6; ++k) {
      in[k] = L::load(v.a[k] + row);
      in[6 + k] = L::load(v.b[k] + row);
    }
  }

  static Pair geometry(const V (&in)[12]) {
    Pair p;
    const V ax0 = in[0], ay0 = in[1];
    p.a1 = {in[2] - ax0, in[3] - ay0};
    p.a2 = {in[4] - ax0, in[5] - ay0};
    p.ea[0] = p.a1;
    p.ea[1] = {in[4] - in[2], in[5] - in[3]};
    p.ea[2] = {-p.a2.x, -p.a2.y};
    p.area_a = p.a1.x * p.a2.y - p.a1.y * p.a2.x;  // cross(p1 − p0, p2 − p0)
    // B's edges from its own coordinates (as Triangle<T>::make), its vertices in A's frame.
    for (int i = 0; i < 3; ++i) {
      const int n = i == 2 ? 0 : i + 1;
      p.eb[i] = {in[6 + 2 * n] - in[6 + 2 * i], in[7 + 2 * n] - in[7 + 2 * i]};
      p.b[i] = {in[6 + 2 * i] - ax0, in[7 + 2 * i] - ay0};
    }
    // cross(p1 − p0, p2 − p0) with p2 − p0 = −e2: the same products, so the same rounding.
    p.area_b = p.eb[0].y * p.eb[2].x - p.eb[0].x * p.eb[2].y;
    for (int i = 0; i < 3; ++i) {
      p.qa[i] = squared(p.ea[i]);
      p.qb[i] = squared(p.eb[i]);
      // right_perp(e) = (e.y, −e.x) is outward for a counter-clockwise triangle and inward for a
      // clockwise one, so its sign follows the area's.
      p.ma[i] = {L::flip(p.ea[i].y, p.area_a), L::flip(p.ea[i].x, -p.area_a)};
      p.mb[i] = {L::flip(p.eb[i].y, -p.area_b), L::flip(p.eb[i].x, p.area_b)};
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) p.pb[i][j] = dot(p.ma[i], p.b[j]);
      p.cb[i] = dot(p.mb[i], p.b[i]);
      p.pa[i][0] = dot(p.mb[i], p.a1);
      p.pa[i][1] = dot(p.mb[i], p.a2);
    }
    p.ca1 = dot(p.ma[1], p.a1);
    return p;
  }

  static void inverse_lengths(const Pair& p, V (&r)[6]) {
    for (int i = 0; i < 3; ++i) {
      r[i] = L::inv_sqrt(p.qa[i]);
      r[3 + i] = L::inv_sqrt(p.qb[i]);
    }
  }

  static void unit_axes(const Pair& p, const V (&r)[6], Vec (&na)[3], Vec (&ub)[3]) {
    for (int i = 0; i < 3; ++i) {
      na[i] = {p.ma[i].x * r[i], p.ma[i].y * r[i]};
      ub[i] = {p.mb[i].x * r[3 + i], p.mb[i].y * r[3 + i]};
    }
  }

  // For a pair apart, the distance d is at least the largest gap over the six axes (−least
  // overlap), and at most any vertex–edge distance. Two certificates settle almost every pair
  // without the 18 vertex–edge distances (measured: all but pairs with parallel edges):
  //
  // (1) The other triangle's deepest vertex along the widest-gap axis projects inside that axis's
  //     edge: its distance to the edge is the gap itself, so d = gap and the normal is the axis.
  //     `deep_vertex_inside` tests this for one axis; the widest one is picked afterwards.
  static M deep_vertex_inside(const Vec& e, V q, const Vec& start, const V (&along)[3],
                              const Vec (&verts)[3], bool deepest_is_least) {
    const M one = deepest_is_least ? L::lt(along[1], along[0]) : L::gt(along[1], along[0]);
    const V best = L::select(one, along[1], along[0]);
    const M two = deepest_is_least ? L::lt(along[2], best) : L::gt(along[2], best);
    const Vec deep = {L::select(two, verts[2].x, L::select(one, verts[1].x, verts[0].x)),
                      L::select(two, verts[2].y, L::select(one, verts[1].y, verts[0].y))};
    // Inside: t = e·(deep − start) in (0, |e|²), that is |t − |e|²/2| < |e|²/2.
    const V half = L::splat(T(0.5)) * q;
    return L::lt_nonneg(L::abs(dot(e, {deep.x - start.x, deep.y - start.y}) - half), half);
  }

  // (2) The nearest vertex pair (a_i, b_j), D = b_j − a_i, supports both triangles along D:
  //     min_B(D·b) − max_A(D·a) = |D|² (up to rounding, within the touching tolerance of the
  //     pair's size), so the gap along D equals |D| and d = |D|, normal D/|D|.
  static M nearest_vertices(const Pair& p, V r_least, T tol, V& dist, Vec& normal) {
    V least = squared(p.b[0]);
    Vec dir = p.b[0];
    for (int j = 0; j < 3; ++j) {
      for (int i = j == 0 ? 1 : 0; i < 3; ++i) {
        const Vec& a = i == 1 ? p.a1 : p.a2;
        const Vec d = i == 0 ? p.b[j] : Vec{p.b[j].x - a.x, p.b[j].y - a.y};
        keep_nearer(least, dir, squared(d), d);
      }
    }
    dist = L::sqrt(least);
    normal = {dir.x / dist, dir.y / dist};
    const V gap = min3(dot(dir, p.b[0]), dot(dir, p.b[1]), dot(dir, p.b[2])) -
                  max3(L::splat(T(0)), dot(dir, p.a1), dot(dir, p.a2));
    // (|D|² − gap)/|D| < tol·(|D| + longest edge), multiplied through by 1/longest.
    return L::lt((least - gap) * r_least,
                 L::splat(tol) * dist * L::fma(dist, r_least, L::splat(T(1))));
  }

  // Otherwise (rare): the least of the nine vertex–vertex distances and of the eighteen
  // vertex–edge-interior ones, the latter measured along the edge's normal (as closest_on_edge
  // does) from the projections the overlaps were made of.
  [[gnu::always_inline]] static void all_features(const Pair& p, V& dist, Vec& normal) {
    V r[6];
    inverse_lengths(p, r);
    Vec na[3], ub[3];
    unit_axes(p, r, na, ub);
    Vec d[3][3];  // d[i][j] = b_j − a_i
    for (int j = 0; j < 3; ++j) {
      d[0][j] = p.b[j];
      d[1][j] = {p.b[j].x - p.a1.x, p.b[j].y - p.a1.y};
      d[2][j] = {p.b[j].x - p.a2.x, p.b[j].y - p.a2.y};
    }
    V vertices = squared(d[0][0]);
    Vec vertices_dir = d[0][0];
    for (int k = 1; k < 9; ++k) {
      keep_nearer(vertices, vertices_dir, squared(d[k / 3][k % 3]), d[k / 3][k % 3]);
    }
    // A vertex projects inside an edge when t = e·(vertex − start) is in (0, |e|²), that is
    // |t − |e|²/2| < |e|²/2; here d = start − vertex for B's edges, vertex − start for A's.
    // Per edge, the least |projection − line| over its three vertices, then times 1/|e|.
    const V half = L::splat(T(0.5));
    V edge = L::infinity();
    Vec edge_dir = na[0];
    auto keep_edge = [&](V least, V r, const Vec& dir) {
      const V h = least * r;
      keep_nearer(edge, edge_dir, h * h, dir);
    };
    for (int j = 0; j < 3; ++j) {  // A's vertices against B's edge j (starting at b_j)
      const V hq = half * p.qb[j];
      V least = L::infinity();
      for (int i = 0; i < 3; ++i) {
        const M inside = L::lt_nonneg(L::abs(dot(p.eb[j], d[i][j]) + hq), hq);
        const V h = (i == 0 ? L::splat(T(0)) : p.pa[j][i - 1]) - p.cb[j];
        least = L::min_where(least, L::abs(h), inside);
      }
      keep_edge(least, r[3 + j], ub[j]);
    }
    for (int i = 0; i < 3; ++i) {  // B's vertices against A's edge i (starting at a_i)
      const V hq = half * p.qa[i];
      V least = L::infinity();
      for (int j = 0; j < 3; ++j) {
        const M inside = L::lt_nonneg(L::abs(dot(p.ea[i], d[i][j]) - hq), hq);
        const V h = i == 1 ? p.pb[i][j] - p.ca1 : p.pb[i][j];
        least = L::min_where(least, L::abs(h), inside);
      }
      keep_edge(least, r[i], na[i]);
    }
    const M vertex_pair = L::lt_nonneg(vertices, edge);
    dist = L::sqrt(L::min_nonneg(vertices, edge));
    normal.x = L::select(vertex_pair, vertices_dir.x / dist, edge_dir.x);
    normal.y = L::select(vertex_pair, vertices_dir.y / dist, edge_dir.y);
  }

  // Separation and normal of the lanes `apart`, which hold the gap and the widest-gap axis.
  [[gnu::always_inline]] static void settle_apart(const Pair& p, const Order& widest, M apart,
                                                  V r_least, T tol, V& s, Vec& axis) {
    const Vec origin = {L::splat(T(0)), L::splat(T(0))};
    const Vec a[3] = {origin, p.a1, p.a2};
    M inside[6];
    for (int i = 0; i < 3; ++i) {
      inside[i] = deep_vertex_inside(p.ea[i], p.qa[i], a[i], p.pb[i], p.b, true);
      const V along[3] = {L::splat(T(0)), p.pa[i][0], p.pa[i][1]};
      inside[3 + i] = deep_vertex_inside(p.eb[i], p.qb[i], p.b[i], along, a, false);
    }
    const M rest = L::but_not(apart, pick(widest, inside));
    if (L::bits(rest) == 0) return;
    V dist;
    Vec normal;
    const M certified = nearest_vertices(p, r_least, tol, dist, normal);
    const M by_vertices = L::both(rest, certified);
    s = L::select(by_vertices, dist, s);
    axis = {L::select(by_vertices, normal.x, axis.x), L::select(by_vertices, normal.y, axis.y)};
    const M left = L::but_not(rest, certified);
    if (L::bits(left) == 0) return;
    all_features(p, dist, normal);
    s = L::select(left, dist, s);
    axis = {L::select(left, normal.x, axis.x), L::select(left, normal.y, axis.y)};
  }

  // `settle_apart` for rows [row, row + kWidth) with their geometry computed again, from the same
  // inputs by the same operations (so to the same bits).
  [[gnu::noinline]] static void settle_apart_again(const BatchView<T>& v, std::size_t row,
                                                   const Order& widest, M apart, V r_least, T tol,
                                                   V& s, Vec& axis) {
    V in[12];
    load(v, row, in);
    settle_apart(geometry(in), widest, apart, r_least, tol, s, axis);
  }

  // Rows [row, row + kWidth): writes their status (and at Level::Depth separation and normal);
  // returns the lanes (bit k: row + k) to be redone by the portable path, plus kAnyApart when some
  // pair of the block needed its distance. kKeep: the pairs apart take the geometry computed
  // above; otherwise `settle_apart_again` computes it a second time. Kept, its sixty-odd vectors
  // outlive the registers and every block stores them to the stack; computed again, only the
  // blocks with pairs apart pay, with a second geometry (docs/measurements.md).
  static constexpr unsigned kAnyApart = 1u << 31;
  static_assert(kWidth < 31, "kAnyApart lies above every lane's bit");
  template <bool kKeep>
  static unsigned block(const BatchView<T>& v, std::size_t row, const BatchLimits<T>& lim) {
    V in[12];
    load(v, row, in);
    const Pair p = geometry(in);
    // Validation, bit for bit as Triangle<T>::make: every coordinate finite and within
    // max_coordinate, the longest edge not below min_size, then the flatness test.
    const V q_max_a = L::max_nonneg(L::max_nonneg(p.qa[0], p.qa[1]), p.qa[2]);
    const V q_max_b = L::max_nonneg(L::max_nonneg(p.qb[0], p.qb[1]), p.qb[2]);
    const M too_small = L::either(L::lt(q_max_a, L::splat(lim.min_size_sq)),
                                  L::lt(q_max_b, L::splat(lim.min_size_sq)));
    const M valid = L::but_not(
        L::both(L::within(in, 12, lim.max_coordinate),
                L::both(well_shaped(p.area_a, q_max_a, lim), well_shaped(p.area_b, q_max_b, lim))),
        too_small);
    // Rows whose squared edge lengths the lanes' reciprocal square root cannot take.
    unsigned redo = 0;
    if constexpr (L::kHasRangeLimit) {
      const V q_least = L::min_nonneg(
          L::min_nonneg(L::min_nonneg(p.qa[0], p.qa[1]), L::min_nonneg(p.qa[2], p.qb[0])),
          L::min_nonneg(p.qb[1], p.qb[2]));
      const M out_of_range =
          L::either(L::lt_nonneg(q_least, L::splat(kEstimateMin<T>)),
                    L::lt_nonneg(L::splat(kEstimateMax<T>), L::max_nonneg(q_max_a, q_max_b)));
      redo = L::bits(L::both(valid, out_of_range));
    }
    V r[6];
    inverse_lengths(p, r);

    const V r_least =  // 1 / the longest edge
        L::min_nonneg(L::min_nonneg(L::min_nonneg(r[0], r[1]), L::min_nonneg(r[2], r[3])),
                      L::min_nonneg(r[4], r[5]));

    // The six overlaps. A's edge i: its line against B's least vertex along ma[i]. B's edge j:
    // A's greatest vertex along mb[j] (a_0 = 0 among them) against the line.
    const V zero = L::splat(T(0));
    const V overlap[6] = {-min3(p.pb[0][0], p.pb[0][1], p.pb[0][2]) * r[0],
                          (p.ca1 - min3(p.pb[1][0], p.pb[1][1], p.pb[1][2])) * r[1],
                          -min3(p.pb[2][0], p.pb[2][1], p.pb[2][2]) * r[2],
                          (max3(zero, p.pa[0][0], p.pa[0][1]) - p.cb[0]) * r[3],
                          (max3(zero, p.pa[1][0], p.pa[1][1]) - p.cb[1]) * r[4],
                          (max3(zero, p.pa[2][0], p.pa[2][1]) - p.cb[2]) * r[5]};
    V least;
    const Order widest = order(overlap, least);
    Vec axis = {zero, zero};  // the widest-gap axis: the minimum-translation axis when not apart
    if constexpr (kDepth) {   // picked as it is, then made unit
      const V mx[6] = {p.ma[0].x, p.ma[1].x, p.ma[2].x, p.mb[0].x, p.mb[1].x, p.mb[2].x};
      const V my[6] = {p.ma[0].y, p.ma[1].y, p.ma[2].y, p.mb[0].y, p.mb[1].y, p.mb[2].y};
      const V scale = pick(widest, r);
      axis = {pick(widest, mx) * scale, pick(widest, my) * scale};
    }

    // The touching band, tolerance × the longest edge, as m·(1 / longest) against the tolerance.
    const V rel = least * r_least;
    const T tol = lim.touching_tolerance;
    const M penetrating = L::both(valid, L::gt(rel, L::splat(tol)));
    M separated = L::both(valid, L::lt(rel, L::splat(-tol)));
    // A least overlap inside the band proves only that the pair does not overlap by more than the
    // band: a gap along an edge normal can be far less than the distance (two slivers end to
    // end), and a gap far below the coordinates' rounding comes out as a small overlap of either
    // sign (slivers 1e148 long, 3e139 apart end to end: found by fuzz_batch and fuzz_sat), so the
    // distance decides.
    const M gap_in_band = L::but_not(valid, L::either(penetrating, separated));
    V s = -least;
    // At Level::Overlap the pairs well apart need no distance.
    const M apart = kDepth ? L::either(separated, gap_in_band) : gap_in_band;
    const bool any_apart = L::bits(apart) != 0;
    if (any_apart) {
      V distance = s;
      Vec closest = axis;
      if constexpr (kKeep) {
        settle_apart(p, widest, apart, r_least, tol, distance, closest);
      } else {
        settle_apart_again(v, row, widest, apart, r_least, tol, distance, closest);
      }
      separated =
          L::either(separated, L::both(gap_in_band, L::gt(distance * r_least, L::splat(tol))));
      s = L::select(separated, distance, s);
      if constexpr (kDepth) {
        axis = {L::select(separated, closest.x, axis.x), L::select(separated, closest.y, axis.y)};
      }
    }

    L::store_status(v.status + row, valid, penetrating, separated);

    if constexpr (kDepth) {
      L::store(v.separation + row, L::select(valid, s, zero));
      L::store(v.normal_x + row, L::select(valid, axis.x, zero));
      L::store(v.normal_y + row, L::select(valid, axis.y, zero));
    }
    return redo | (any_apart ? kAnyApart : 0u);
  }

  // Every row of `v`: whole blocks, then the tail through a padded copy of its rows. Each block
  // keeps its geometry when the block before it had pairs apart: blocks come in runs of the kind
  // (a broad phase's stream, a class of pairs), so that is the form the block most likely needs.
  // The one-pair lanes always keep it (why: docs/measurements.md, "The batch kernel's block in
  // machine code").
  static void run(const BatchView<T>& v, const BatchLimits<T>& lim) {
    constexpr bool kAlwaysKeep = kWidth == 1;
    std::size_t row = 0;
    bool apart = kAlwaysKeep;
    for (; row + kWidth <= v.count; row += kWidth) {
      const unsigned redo = apart ? block<true>(v, row, lim) : block<false>(v, row, lim);
      apart = kAlwaysKeep || (redo & kAnyApart) != 0;
      redo_rows(v, lim, row, redo & ~kAnyApart);
    }
    if (row == v.count) return;
    const std::size_t rest = v.count - row;
    T coords[12][kWidth];
    std::uint8_t status[kWidth];
    T out[3][kWidth];
    BatchView<T> tail{{}, {}, status, nullptr, nullptr, nullptr, static_cast<std::size_t>(kWidth)};
    for (int k = 0; k < 6; ++k) {
      for (int i = 0; i < kWidth; ++i) {
        // Padding lanes repeat the tail's first row: valid whenever it is, never read back.
        const std::size_t from = row + (static_cast<std::size_t>(i) < rest ? i : 0);
        coords[k][i] = v.a[k][from];
        coords[6 + k][i] = v.b[k][from];
      }
      tail.a[k] = coords[k];
      tail.b[k] = coords[6 + k];
    }
    if constexpr (kDepth) {
      tail.separation = out[0];
      tail.normal_x = out[1];
      tail.normal_y = out[2];
    }
    const unsigned redo = block<true>(tail, 0, lim) & ((1u << rest) - 1u);
    for (std::size_t i = 0; i < rest; ++i) {
      v.status[row + i] = status[i];
      if constexpr (kDepth) {
        v.separation[row + i] = out[0][i];
        v.normal_x[row + i] = out[1][i];
        v.normal_y[row + i] = out[2][i];
      }
    }
    redo_rows(v, lim, row, redo);
  }

  static void redo_rows(const BatchView<T>& v, const BatchLimits<T>& lim, std::size_t row,
                        unsigned lanes) {
    if constexpr (L::kHasRangeLimit) {
      for (int k = 0; lanes != 0; ++k, lanes >>= 1) {
        if (lanes & 1u) penetrate_row_portable(v, lim, kDepth, row + static_cast<std::size_t>(k));
      }
    }
  }
};

// Every row of `v` with the lanes `L`, at Level::Depth or (depth false) Level::Overlap.
template <class L>
void run_batch(const BatchView<typename L::T>& v, const BatchLimits<typename L::T>& lim,
               bool depth) {
  if (depth) {
    SatOverLanes<L, true>::run(v, lim);
  } else {
    SatOverLanes<L, false>::run(v, lim);
  }
}

}  // namespace dyop::detail
