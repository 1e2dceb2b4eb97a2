// `penetrate_batch`: `sat`'s answer (Overlap or Depth) for many pairs at once over
// structure-of-arrays input. The algorithm is written once in detail/batch_kernel.hpp over a
// "lanes" type: per pair, validation as Triangle<T>::make decides it, the six overlaps in a frame
// at A's first vertex, and for pairs found apart the exact distance. This file checks the CPU
// once and sends whole blocks to the AVX-512 lanes (batch_avx512.cpp), the AVX2 + FMA lanes
// (batch_avx2.cpp) or the portable lanes (one pair per step), as `BatchKernel` asks. Invariant:
// every kernel gives every pair the same bits (tests/dyop/batch_kernels_test.cpp), and to rounding
// `sat`'s figures (tests/dyop/batch_test.cpp).
#include "dyop/batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#define DYOP_BATCH_RSQRT_ESTIMATE 1
#endif

#include "detail/batch_kernel.hpp"

namespace dyop {
namespace detail {

static_assert(static_cast<std::uint8_t>(Status::Separated) == kStatusSeparated &&
                  static_cast<std::uint8_t>(Status::Touching) == kStatusTouching &&
                  static_cast<std::uint8_t>(Status::Penetrating) == kStatusPenetrating &&
                  static_cast<std::uint8_t>(Status::Invalid) == kStatusInvalid,
              "the batch kernel writes Status values as these numbers");

#if DYOP_HAVE_BATCH_AVX2
// batch_avx2.cpp, compiled with -mavx2 -mfma: called only when the CPU has both.
void penetrate_batch_avx2(const BatchView<float>& v, const BatchLimits<float>& lim, bool depth);
void penetrate_batch_avx2(const BatchView<double>& v, const BatchLimits<double>& lim, bool depth);
#endif
#if DYOP_HAVE_BATCH_AVX512
// batch_avx512.cpp, compiled with -mavx512f -mavx512dq: called only when the CPU has both.
void penetrate_batch_avx512(const BatchView<float>& v, const BatchLimits<float>& lim, bool depth);
void penetrate_batch_avx512(const BatchView<double>& v, const BatchLimits<double>& lim, bool depth);
#endif

namespace {

// One pair per step, with the vector lanes' arithmetic: x86's min and max, fused `fma`, and the
// same refined estimate for the reciprocal square root where it applies (exact division by the
// square root elsewhere, where the vector lanes hand their rows to these).
template <class Scalar>
struct PortableLanes {
  using T = Scalar;
  using V = Scalar;
  using M = bool;
  static constexpr int kWidth = 1;
  static constexpr bool kHasRangeLimit = false;
  static V load(const T* p) { return *p; }
  static void store(T* p, V x) { *p = x; }
  static V splat(T x) { return x; }
  static V infinity() { return std::numeric_limits<T>::infinity(); }
  static V fma(V a, V b, V c) { return std::fma(a, b, c); }
  static V min(V a, V b) { return a < b ? a : b; }
  static V max(V a, V b) { return a > b ? a : b; }
  static V abs(V a) { return std::abs(a); }
  static V flip(V x, V s) { return std::signbit(s) ? -x : x; }
  static M lt(V a, V b) { return a < b; }
  static M gt(V a, V b) { return a > b; }
  static M lt_nonneg(V a, V b) { return a < b; }
  static V min_nonneg(V a, V b) { return min(a, b); }
  static V max_nonneg(V a, V b) { return max(a, b); }
  static V min_where(V least, V x, M m) { return m && x < least ? x : least; }
  static M within(const V* x, int n, T limit) {
    return std::all_of(x, x + n, [limit](V c) { return std::abs(c) <= limit; });
  }
  static M both(M a, M b) { return a && b; }
  static M either(M a, M b) { return a || b; }
  static M but_not(M a, M b) { return a && !b; }
  static V select(M m, V a, V b) { return m ? a : b; }
  static M select(M m, M a, M b) { return m ? a : b; }
  static unsigned bits(M m) { return m ? 1u : 0u; }
  static V sqrt(V a) { return std::sqrt(a); }
#if DYOP_BATCH_RSQRT_ESTIMATE
  static V rsqrt_estimate(V q) {
    return static_cast<T>(_mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(static_cast<float>(q)))));
  }
  static V inv_sqrt(V q) {
    if (q >= kEstimateMin<T> && q <= kEstimateMax<T>) {
      return refine_inv_sqrt<PortableLanes>(q, rsqrt_estimate(q));
    }
    return T(1) / std::sqrt(q);
  }
#else
  static V inv_sqrt(V q) { return T(1) / std::sqrt(q); }  // no vector kernel to agree with
#endif
  static void store_status(std::uint8_t* out, M valid, M penetrating, M separated) {
    *out = !valid        ? kStatusInvalid
           : penetrating ? kStatusPenetrating
           : separated   ? kStatusSeparated
                         : kStatusTouching;
  }
};

template <class T>
BatchLimits<T> limits() {
  return {max_coordinate<T>(), min_size<T>() * min_size<T>(), degenerate_tolerance<T>(),
          touching_tolerance<T>()};
}

bool cpu_has_avx2_fma() {
#if DYOP_HAVE_BATCH_AVX2
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return yes;
#else
  return false;
#endif
}

bool cpu_has_avx512() {
#if DYOP_HAVE_BATCH_AVX512
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  }();
  return yes;
#else
  return false;
#endif
}

template <class T>
void run(BatchKernel kernel, const BatchView<T>& v, const BatchLimits<T>& lim, bool depth) {
  switch (kernel) {
#if DYOP_HAVE_BATCH_AVX512
    case BatchKernel::Avx512:
      penetrate_batch_avx512(v, lim, depth);
      return;
#endif
#if DYOP_HAVE_BATCH_AVX2
    case BatchKernel::Avx2:
      penetrate_batch_avx2(v, lim, depth);
      return;
#endif
    default:
      run_batch<PortableLanes<T>>(v, lim, depth);
      return;
  }
}

}  // namespace

template <class T>
void penetrate_row_portable(const BatchView<T>& v, const BatchLimits<T>& lim, bool depth,
                            std::size_t row) {
  if (depth) {
    SatOverLanes<PortableLanes<T>, true>::template block<true>(v, row, lim);
  } else {
    SatOverLanes<PortableLanes<T>, false>::template block<true>(v, row, lim);
  }
}

template void penetrate_row_portable(const BatchView<float>&, const BatchLimits<float>&, bool,
                                     std::size_t);
template void penetrate_row_portable(const BatchView<double>&, const BatchLimits<double>&, bool,
                                     std::size_t);

}  // namespace detail

bool batch_kernel_available(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::Auto:
    case BatchKernel::Portable:
      return true;
    case BatchKernel::Avx2:
      return detail::cpu_has_avx2_fma();
    case BatchKernel::Avx512:
      return detail::cpu_has_avx512();
  }
  return false;
}

BatchKernel batch_kernel_used(BatchKernel requested) {
  if (requested != BatchKernel::Auto) return requested;
  if (detail::cpu_has_avx512()) return BatchKernel::Avx512;
  if (detail::cpu_has_avx2_fma()) return BatchKernel::Avx2;
  return BatchKernel::Portable;
}

const char* name(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::Auto:
      return "auto";
    case BatchKernel::Portable:
      return "portable";
    case BatchKernel::Avx2:
      return "avx2";
    case BatchKernel::Avx512:
      return "avx512";
  }
  return "unknown";
}

const char* describe(BatchError e) {
  switch (e) {
    case BatchError::None:
      return "no error";
    case BatchError::UnsupportedLevel:
      return "unsupported level: the batch kernel computes Overlap and Depth only (use sat for "
             "Contact or Manifold)";
    case BatchError::NullArray:
      return "null array: every input array and status, and at Depth separation and both normal "
             "arrays, are needed when count > 0";
    case BatchError::KernelUnavailable:
      return "batch kernel unavailable: not built (DYOP_BATCH_AVX2, DYOP_BATCH_AVX512) or the CPU "
             "lacks its instructions (AVX2 and FMA; AVX-512 F and DQ)";
  }
  return "unknown batch error";
}

template <class T>
BatchError penetrate_batch(const PairBatch<T>& pairs, Level level, const BatchOutput<T>& out,
                           BatchKernel kernel) {
  if (level != Level::Overlap && level != Level::Depth) return BatchError::UnsupportedLevel;
  if (!batch_kernel_available(kernel)) return BatchError::KernelUnavailable;
  if (pairs.count == 0) return BatchError::None;
  const bool depth = level == Level::Depth;
  const detail::BatchView<T> v{{pairs.ax0, pairs.ay0, pairs.ax1, pairs.ay1, pairs.ax2, pairs.ay2},
                               {pairs.bx0, pairs.by0, pairs.bx1, pairs.by1, pairs.bx2, pairs.by2},
                               reinterpret_cast<std::uint8_t*>(out.status),
                               depth ? out.separation : nullptr,
                               depth ? out.normal_x : nullptr,
                               depth ? out.normal_y : nullptr,
                               pairs.count};
  const bool inputs = std::all_of(std::begin(v.a), std::end(v.a), [](const T* p) { return p; }) &&
                      std::all_of(std::begin(v.b), std::end(v.b), [](const T* p) { return p; });
  if (!inputs || !v.status || (depth && (!v.separation || !v.normal_x || !v.normal_y))) {
    return BatchError::NullArray;
  }
  detail::run(batch_kernel_used(kernel), v, detail::limits<T>(), depth);
  return BatchError::None;
}

template <class T>
BatchRowError batch_row_error(const PairBatch<T>& p, std::size_t k) {
  return {
      Triangle<T>::make({p.ax0[k], p.ay0[k]}, {p.ax1[k], p.ay1[k]}, {p.ax2[k], p.ay2[k]}).error,
      Triangle<T>::make({p.bx0[k], p.by0[k]}, {p.bx1[k], p.by1[k]}, {p.bx2[k], p.by2[k]}).error};
}

template BatchError penetrate_batch(const PairBatch<float>&, Level, const BatchOutput<float>&,
                                    BatchKernel);
template BatchError penetrate_batch(const PairBatch<double>&, Level, const BatchOutput<double>&,
                                    BatchKernel);
template BatchRowError batch_row_error(const PairBatch<float>&, std::size_t);
template BatchRowError batch_row_error(const PairBatch<double>&, std::size_t);

}  // namespace dyop
