// The AVX-512 lanes of the batch kernel. Compiled with -mavx512f -mavx512dq -ffp-contract=off
// (see dyop/CMakeLists.txt) and entered only after batch.cpp has checked the CPU. As in
// batch_avx2.cpp, nothing but the two entry points has external linkage and no header with inline
// library code is included: no AVX-512 instruction can leak into code any CPU runs.
//
// Masks live in mask registers; each operation is the AVX2 lanes' one lane for lane (the same
// compare predicates, x86's min and max, the same integer tricks on non-negative floats), and the
// reciprocal square root starts from the same 12-bit estimate (`vrsqrtps` on each 256-bit half,
// not AVX-512's own 14-bit one), so every pair gets the same bits as from the other kernels.

#include <immintrin.h>

// GCC 12's AVX-512 intrinsics read a deliberately uninitialised `_mm512_undefined_*` value and
// warn about it once inlined (GCC bug 105593, fixed in GCC 13).
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "detail/batch_kernel.hpp"

namespace dyop::detail {
namespace {

// Sixteen floats per register.
struct Float16 {
  using T = float;
  using V = __m512;
  using M = __mmask16;
  static constexpr int kWidth = 16;
  static constexpr bool kHasRangeLimit = true;  // the estimate flushes subnormals to zero
  static V load(const T* p) { return _mm512_loadu_ps(p); }
  static void store(T* p, V x) { _mm512_storeu_ps(p, x); }
  static V splat(T x) { return _mm512_set1_ps(x); }
  static V infinity() { return _mm512_set1_ps(__builtin_huge_valf()); }
  static V fma(V a, V b, V c) { return _mm512_fmadd_ps(a, b, c); }
  static V min(V a, V b) { return _mm512_min_ps(a, b); }
  static V max(V a, V b) { return _mm512_max_ps(a, b); }
  static V abs(V a) { return _mm512_andnot_ps(_mm512_set1_ps(-0.0f), a); }
  static V flip(V x, V s) { return _mm512_xor_ps(x, _mm512_and_ps(s, _mm512_set1_ps(-0.0f))); }
  static M lt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
  static M gt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
  static __m512i as_int(V a) { return _mm512_castps_si512(a); }
  static V as_float(__m512i a) { return _mm512_castsi512_ps(a); }
  static M lt_nonneg(V a, V b) { return _mm512_cmpgt_epi32_mask(as_int(b), as_int(a)); }
  static V min_nonneg(V a, V b) { return as_float(_mm512_min_epi32(as_int(a), as_int(b))); }
  static V max_nonneg(V a, V b) { return as_float(_mm512_max_epi32(as_int(a), as_int(b))); }
  static V min_where(V least, V x, M m) { return _mm512_mask_min_ps(least, m, x, least); }
  // |x| as bit patterns: NaN and infinity are above any finite limit.
  static M within(const V* x, int n, T limit) {
    const __m512i magnitude = _mm512_set1_epi32(0x7FFFFFFF);
    __m512i most = _mm512_and_si512(as_int(x[0]), magnitude);
    for (int k = 1; k < n; ++k)
      most = _mm512_max_epu32(most, _mm512_and_si512(as_int(x[k]), magnitude));
    int bound;
    __builtin_memcpy(&bound, &limit, sizeof bound);
    return _mm512_cmpgt_epi32_mask(_mm512_set1_epi32(bound + 1), most);
  }
  static M both(M a, M b) { return static_cast<M>(a & b); }
  static M either(M a, M b) { return static_cast<M>(a | b); }
  static M but_not(M a, M b) { return static_cast<M>(a & ~b); }
  static V select(M m, V a, V b) { return _mm512_mask_blend_ps(m, b, a); }
  static M select(M m, M a, M b) { return static_cast<M>((m & a) | (~m & b)); }
  static unsigned bits(M m) { return m; }
  static V sqrt(V a) { return _mm512_sqrt_ps(a); }
  static V rsqrt_estimate(V q) {
    const __m256 low = _mm256_rsqrt_ps(_mm512_castps512_ps256(q));
    const __m256 high = _mm256_rsqrt_ps(_mm512_extractf32x8_ps(q, 1));
    return _mm512_insertf32x8(_mm512_castps256_ps512(low), high, 1);
  }
  static V inv_sqrt(V q) { return refine_inv_sqrt<Float16>(q, rsqrt_estimate(q)); }

  static void store_status(std::uint8_t* out, M valid, M penetrating, M separated) {
    __m512i code = _mm512_mask_blend_epi32(separated, _mm512_set1_epi32(kStatusTouching),
                                           _mm512_set1_epi32(kStatusSeparated));
    code = _mm512_mask_blend_epi32(penetrating, code, _mm512_set1_epi32(kStatusPenetrating));
    code = _mm512_mask_blend_epi32(valid, _mm512_set1_epi32(kStatusInvalid), code);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm512_cvtepi32_epi8(code));
  }
};

// Eight doubles per register.
struct Double8 {
  using T = double;
  using V = __m512d;
  using M = __mmask8;
  static constexpr int kWidth = 8;
  static constexpr bool kHasRangeLimit = true;  // the estimate is taken in float
  static V load(const T* p) { return _mm512_loadu_pd(p); }
  static void store(T* p, V x) { _mm512_storeu_pd(p, x); }
  static V splat(T x) { return _mm512_set1_pd(x); }
  static V infinity() { return _mm512_set1_pd(__builtin_huge_val()); }
  static V fma(V a, V b, V c) { return _mm512_fmadd_pd(a, b, c); }
  static V min(V a, V b) { return _mm512_min_pd(a, b); }
  static V max(V a, V b) { return _mm512_max_pd(a, b); }
  static V abs(V a) { return _mm512_andnot_pd(_mm512_set1_pd(-0.0), a); }
  static V flip(V x, V s) { return _mm512_xor_pd(x, _mm512_and_pd(s, _mm512_set1_pd(-0.0))); }
  static M lt(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
  static M gt(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
  static __m512i as_int(V a) { return _mm512_castpd_si512(a); }
  static M lt_nonneg(V a, V b) { return _mm512_cmpgt_epi64_mask(as_int(b), as_int(a)); }
  static V min_nonneg(V a, V b) { return _mm512_min_pd(a, b); }  // as the AVX2 lanes
  static V max_nonneg(V a, V b) { return _mm512_max_pd(a, b); }
  static V min_where(V least, V x, M m) { return _mm512_mask_min_pd(least, m, x, least); }
  // As the AVX2 lanes: vmaxpd may drop a NaN, which the flatness test then rejects.
  static M within(const V* x, int n, T limit) {
    V most = abs(x[0]);
    for (int k = 1; k < n; ++k) most = _mm512_max_pd(most, abs(x[k]));
    return _mm512_cmp_pd_mask(most, _mm512_set1_pd(limit), _CMP_LE_OQ);
  }
  static M both(M a, M b) { return static_cast<M>(a & b); }
  static M either(M a, M b) { return static_cast<M>(a | b); }
  static M but_not(M a, M b) { return static_cast<M>(a & ~b); }
  static V select(M m, V a, V b) { return _mm512_mask_blend_pd(m, b, a); }
  static M select(M m, M a, M b) { return static_cast<M>((m & a) | (~m & b)); }
  static unsigned bits(M m) { return m; }
  static V sqrt(V a) { return _mm512_sqrt_pd(a); }
  static V rsqrt_estimate(V q) { return _mm512_cvtps_pd(_mm256_rsqrt_ps(_mm512_cvtpd_ps(q))); }
  static V inv_sqrt(V q) { return refine_inv_sqrt<Double8>(q, rsqrt_estimate(q)); }

  static void store_status(std::uint8_t* out, M valid, M penetrating, M separated) {
    __m512i code = _mm512_mask_blend_epi64(separated, _mm512_set1_epi64(kStatusTouching),
                                           _mm512_set1_epi64(kStatusSeparated));
    code = _mm512_mask_blend_epi64(penetrating, code, _mm512_set1_epi64(kStatusPenetrating));
    code = _mm512_mask_blend_epi64(valid, _mm512_set1_epi64(kStatusInvalid), code);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out), _mm512_cvtepi64_epi8(code));
  }
};

}  // namespace

void penetrate_batch_avx512(const BatchView<float>& v, const BatchLimits<float>& lim, bool depth) {
  run_batch<Float16>(v, lim, depth);
}

void penetrate_batch_avx512(const BatchView<double>& v, const BatchLimits<double>& lim,
                            bool depth) {
  run_batch<Double8>(v, lim, depth);
}

}  // namespace dyop::detail
