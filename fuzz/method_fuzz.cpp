// libFuzzer target for one method of the registry (`dyop/method.hpp`), chosen at run time with
// `--method=NAME` (its one spelling; libFuzzer leaves flags that start with `--` to the target),
// on one triangle pair in float or double (format: fuzz_input.hpp). `--list-methods` prints the
// methods it takes, one per line, and exits: every row of the registry (the library's methods).
//
// What it asserts, besides "no crash, no sanitizer report":
// - `Triangle<T>::make` decides every input; a pair it accepts is answered at every level, never
//   `Invalid` (dyop-paper: only by design, with a reason), and every field the level promises is
//   finite;
// - sat: within the exact bound of the exact rational reference (double 1e-12, float 1e-5 of the
//   pair's size), with the exact status outside the touching band;
// - dyop: agrees with sat (status, and separation within the touching band);
// - batch: every row's verdict is `Triangle<T>::make`'s and every valid row is sat's answer, in 17
//   copies of the row (the AVX-512 kernel's 16 float lanes and a tail, the AVX2 kernel's 2 × 8),
//   and every kernel the CPU has gives the portable kernel's bits (status, separation, normal);
// - lin-canny: also warm-started from a cache made of the remaining bytes (any bytes).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include "dyop/batch.hpp"
#include "dyop/method.hpp"
#include "fuzz_input.hpp"
#include "workloads/batch_arrays.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/finite_fields.hpp"

namespace dyop::fuzz {
namespace {

// The method under test, set once by LLVMFuzzerInitialize.
Method g_method = Method::Dyop;

[[noreturn]] void fail(const char* what, const FuzzInput& in) {
  std::fprintf(stderr, "%s: %s (%s) on", name(g_method), what, in.is_float ? "float" : "double");
  for (double c : in.coords) std::fprintf(stderr, " %.17g", c);
  std::fprintf(stderr, "\n");
  std::abort();
}

void require(bool ok, const char* what, const FuzzInput& in) {
  if (!ok) fail(what, in);
}

using workloads::finite_at;

template <class T>
double exact_bound() {
  return std::is_same_v<T, float> ? 1e-5 : 1e-12;
}

// How far two exact methods' separations may differ: 4 touching bands, taken on the pair's size
// as the exactness bound takes it (the diagonal of both bounding boxes together). A distance
// carries rounding relative to itself, so for a pair far apart the gap counts, not only the
// triangles (found by fuzz_batch: two triangles of size 5 a million apart in float, where the
// distance's own ulp is 0.125).
template <class T>
double agreement(const FuzzInput& in) {
  return 4 * double(touching_tolerance<T>()) * workloads::pair_size(in.pair());
}

// Sat against the exact rational reference.
template <class T>
void check_exact(const Result<T>& r, const FuzzInput& in, T band) {
  const workloads::RawPair p = in.pair();
  const workloads::ExactAnswer exact = workloads::exact_separation(p);
  const double size = workloads::pair_size(p);
  require(std::abs(double(r.separation) - exact.separation) <= exact_bound<T>() * size,
          "sat is not within the exact bound", in);
  if (std::abs(exact.separation) > 2 * double(band)) {
    require(r.status == (exact.separation < 0 ? Status::Penetrating : Status::Separated),
            "sat's status is not the exact one", in);
  }
}

template <class T>
bool same_bits(T x, T y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

// Every kernel the CPU has against the portable one, bit for bit, on `batch` at Level::Depth.
template <class T>
void check_kernels_agree(const FuzzInput& in, const PairBatch<T>& batch,
                         const workloads::BatchArrays<T>& portable) {
  for (BatchKernel kernel : {BatchKernel::Avx2, BatchKernel::Avx512}) {
    if (!batch_kernel_available(kernel)) continue;
    workloads::BatchArrays<T> got(batch.count, [&](std::size_t, int, int) { return Vec2<T>(); });
    require(penetrate_batch(batch, Level::Depth, got.out(), kernel) == BatchError::None,
            "a batch kernel the CPU has refused a plain call", in);
    for (std::size_t k = 0; k < batch.count; ++k) {
      require(got.status[k] == portable.status[k] &&
                  same_bits(got.separation[k], portable.separation[k]) &&
                  same_bits(got.normal_x[k], portable.normal_x[k]) &&
                  same_bits(got.normal_y[k], portable.normal_y[k]),
              "batch kernels differ", in);
    }
  }
}

template <class T>
void check_batch(const FuzzInput& in, const TriangleOrError<T>& a, const TriangleOrError<T>& b) {
  constexpr std::size_t rows = 17;
  workloads::BatchArrays<T> arrays(rows, [&](std::size_t, int side, int i) {
    return Vec2<T>(T(in.coords[6 * side + 2 * i]), T(in.coords[6 * side + 2 * i + 1]));
  });
  const PairBatch<T> batch = arrays.pairs();
  require(
      penetrate_batch(batch, Level::Depth, arrays.out(), BatchKernel::Portable) == BatchError::None,
      "batch refused a plain call", in);
  check_kernels_agree(in, batch, arrays);
  const std::vector<Status>& status = arrays.status;
  const std::vector<T>& sep = arrays.separation;
  const std::vector<T>& nx = arrays.normal_x;
  const std::vector<T>& ny = arrays.normal_y;
  const BatchRowError e = batch_row_error(batch, 0);
  require(e.a == a.error && e.b == b.error, "batch's verdict differs from Triangle::make's", in);
  const bool valid = a.ok() && b.ok();
  const Result<T> s = valid ? sat(a.triangle, b.triangle) : Result<T>{};
  const double agree = valid ? agreement<T>(in) : 0;
  for (std::size_t k = 0; k < rows; ++k) {
    require((status[k] == Status::Invalid) == !valid, "batch lost or kept a row wrongly", in);
    if (!valid) continue;
    require(std::isfinite(sep[k]) && std::isfinite(nx[k]) && std::isfinite(ny[k]),
            "batch answered NaN or inf", in);
    require(std::abs(double(sep[k]) - double(s.separation)) <= agree, "batch differs from sat", in);
    require(sep[k] == sep[0] && status[k] == status[0], "batch lanes differ", in);
  }
}

// A pair's state from arbitrary bytes: out-of-range fields must start cold, not index past.
PairState state_from(const FuzzInput& in) {
  ByteReader bytes(in.rest, in.rest_size);
  PairState state;
  LinCannyCache& c = state.lin_canny;
  c.valid = (bytes.get<std::uint8_t>() & 1u) != 0;
  c.type_a = static_cast<Feature::Type>(bytes.get<std::uint8_t>() % 4);
  c.type_b = static_cast<Feature::Type>(bytes.get<std::uint8_t>() % 4);
  c.index_a = bytes.get<std::uint8_t>();
  c.index_b = bytes.get<std::uint8_t>();
  c.depth_axis = bytes.get<std::uint8_t>();
  return state;
}

template <class T>
void run(const FuzzInput& in) {
  auto at = [&](int k) { return Vec2<T>(T(in.coords[k]), T(in.coords[k + 1])); };
  const TriangleOrError<T> a = Triangle<T>::make(at(0), at(2), at(4));
  const TriangleOrError<T> b = Triangle<T>::make(at(6), at(8), at(10));
  if (info(g_method).entry == Entry::Batch) {
    check_batch(in, a, b);
    return;
  }
  if (!a.ok() || !b.ok()) return;
  const Method m = g_method;
  const T size = std::max(a.triangle.size(), b.triangle.size());
  const T band = touching_tolerance<T>() * size;
  PairState cache = state_from(in);
  Status depth_status = Status::Invalid;
  for (Level level : {Level::Overlap, Level::Depth, Level::Contact, Level::Manifold}) {
    Query<T> q{level};
    q.margin = T(0.01) * size;
    q.face_hysteresis = T(0.001) * size;
    const Result<T> r = penetrate(m, a.triangle, b.triangle, q, &cache);
    if (r.status == Status::Invalid) {
      require(m == Method::DyopPaper && r.reason != InvalidReason::None, "Invalid on a valid pair",
              in);
      continue;
    }
    require(finite_at(r, level), "NaN or inf in a field the level promises", in);
    if (level == Level::Depth) depth_status = r.status;
  }
  if (depth_status == Status::Invalid) return;
  const Result<T> r = penetrate(m, a.triangle, b.triangle, Query<T>{Level::Depth});
  if (m == Method::Sat) check_exact(r, in, band);
  if (m == Method::Dyop) {
    const Result<T> s = sat(a.triangle, b.triangle);
    require(std::abs(double(r.separation) - double(s.separation)) <= agreement<T>(in),
            "dyop and sat disagree on separation", in);
    if (std::abs(s.separation) > 2 * band)
      require(r.status == s.status, "dyop and sat disagree on status", in);
  }
  if (m == Method::Dyop || m == Method::Sat) {
    // Asking for the proof of separation instead of the distance changes no status, and the
    // gap it reports is a lower bound on the distance.
    Query<T> gap{Level::Depth};
    gap.apart = Apart::Gap;
    const Result<T> g = penetrate(m, a.triangle, b.triangle, gap);
    require(g.status == r.status, "Apart::Gap changes the status", in);
    require(finite_at(g, Level::Depth), "NaN or inf with Apart::Gap", in);
    if (g.status == Status::Separated) {
      require(double(g.separation) <= double(r.separation) + agreement<T>(in),
              "the gap of Apart::Gap exceeds the distance", in);
    }
  }
}

}  // namespace
}  // namespace dyop::fuzz

// Reads `--method=NAME` (required) or `--list-methods`; exits with a message on anything else.
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  using namespace dyop;
  std::optional<Method> chosen;
  for (int i = 1; i < *argc; ++i) {
    const std::string_view arg = (*argv)[i];
    if (arg == "--list-methods") {
      for (const MethodInfo& row : method_table) std::printf("%s\n", row.name);
      std::exit(0);
    }
    constexpr std::string_view flag = "--method=";
    if (arg.substr(0, flag.size()) == flag) {
      chosen = parse_method(arg.substr(flag.size()));
      if (!chosen) {
        std::fprintf(stderr, "fuzz_method: no method '%s' (--list-methods)\n",
                     (*argv)[i] + flag.size());
        std::exit(2);
      }
    }
  }
  if (!chosen) {
    std::fprintf(stderr, "fuzz_method: give --method=NAME (--list-methods lists them)\n");
    std::exit(2);
  }
  fuzz::g_method = *chosen;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const dyop::fuzz::FuzzInput in = dyop::fuzz::decode(data, size);
  if (in.is_float) {
    dyop::fuzz::run<float>(in);
  } else {
    dyop::fuzz::run<double>(in);
  }
  return 0;
}
