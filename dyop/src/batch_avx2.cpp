// The AVX2 + FMA lanes of the batch kernel. Compiled with -mavx2 -mfma -ffp-contract=off (see
// dyop/CMakeLists.txt) and entered only after batch.cpp has checked the CPU. Nothing but the two
// entry points has external linkage here, and no library or standard header with inline code is
// included (see detail/batch_kernel.hpp): no AVX2 instruction can leak into code any CPU runs.
// -ffp-contract=off: validation must round as Triangle<T>::make does; fusing is asked for by name.

#include <immintrin.h>

#include "detail/batch_kernel.hpp"

namespace dyop::detail {
namespace {

// Status codes from all-ones/zero lanes: 1 − penetrating + separated is 2, 0 or 1 (Penetrating,
// Separated, Touching), and invalid lanes take 3: dyop::Status's numbering (kStatus* above).
static_assert(kStatusSeparated == 0 && kStatusTouching == 1 && kStatusPenetrating == 2 &&
              kStatusInvalid == 3);

// Eight floats per register.
struct Float8 {
  using T = float;
  using V = __m256;
  using M = __m256;
  static constexpr int kWidth = 8;
  static constexpr bool kHasRangeLimit = true;  // the estimate flushes subnormals to zero
  static V load(const T* p) { return _mm256_loadu_ps(p); }
  static void store(T* p, V x) { _mm256_storeu_ps(p, x); }
  static V splat(T x) { return _mm256_set1_ps(x); }
  static V infinity() { return _mm256_set1_ps(__builtin_huge_valf()); }
  static V fma(V a, V b, V c) { return _mm256_fmadd_ps(a, b, c); }
  static V min(V a, V b) { return _mm256_min_ps(a, b); }
  static V max(V a, V b) { return _mm256_max_ps(a, b); }
  static V abs(V a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }
  static V flip(V x, V s) { return _mm256_xor_ps(x, _mm256_and_ps(s, _mm256_set1_ps(-0.0f))); }
  static M lt(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
  static M gt(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
  static __m256i as_int(V a) { return _mm256_castps_si256(a); }
  static V as_float(__m256i a) { return _mm256_castsi256_ps(a); }
  static M lt_nonneg(V a, V b) { return as_float(_mm256_cmpgt_epi32(as_int(b), as_int(a))); }
  static V min_nonneg(V a, V b) { return as_float(_mm256_min_epi32(as_int(a), as_int(b))); }
  static V max_nonneg(V a, V b) { return as_float(_mm256_max_epi32(as_int(a), as_int(b))); }
  // Masked-out lanes become NaN (all ones), and vminps returns its second operand on a NaN.
  static V min_where(V least, V x, M m) {
    return _mm256_min_ps(_mm256_or_ps(x, _mm256_andnot_ps(m, as_float(_mm256_set1_epi32(-1)))),
                         least);
  }
  // |x| as bit patterns: NaN and infinity are above any finite limit.
  static M within(const V* x, int n, T limit) {
    const __m256i magnitude = _mm256_set1_epi32(0x7FFFFFFF);
    __m256i most = _mm256_and_si256(as_int(x[0]), magnitude);
    for (int k = 1; k < n; ++k)
      most = _mm256_max_epu32(most, _mm256_and_si256(as_int(x[k]), magnitude));
    int bound;
    __builtin_memcpy(&bound, &limit, sizeof bound);
    return as_float(_mm256_cmpgt_epi32(_mm256_set1_epi32(bound + 1), most));
  }
  static M both(M a, M b) { return _mm256_and_ps(a, b); }
  static M either(M a, M b) { return _mm256_or_ps(a, b); }
  static M but_not(M a, M b) { return _mm256_andnot_ps(b, a); }
  static V select(M m, V a, V b) { return _mm256_blendv_ps(b, a, m); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_ps(m)); }
  static V sqrt(V a) { return _mm256_sqrt_ps(a); }
  static V rsqrt_estimate(V q) { return _mm256_rsqrt_ps(q); }
  static V inv_sqrt(V q) { return refine_inv_sqrt<Float8>(q, rsqrt_estimate(q)); }

  static void store_status(std::uint8_t* out, M valid, M penetrating, M separated) {
    __m256i code =
        _mm256_add_epi32(_mm256_sub_epi32(_mm256_set1_epi32(1), _mm256_castps_si256(penetrating)),
                         _mm256_castps_si256(separated));
    code = _mm256_blendv_epi8(_mm256_set1_epi32(3), code, _mm256_castps_si256(valid));
    const __m256i words = _mm256_packs_epi32(code, code);  // per 128-bit half: 4 codes, twice
    const __m256i bytes = _mm256_packus_epi16(words, words);
    _mm_storel_epi64(
        reinterpret_cast<__m128i*>(out),
        _mm_unpacklo_epi32(_mm256_castsi256_si128(bytes), _mm256_extracti128_si256(bytes, 1)));
  }
};

// Four doubles per register.
struct Double4 {
  using T = double;
  using V = __m256d;
  using M = __m256d;
  static constexpr int kWidth = 4;
  static constexpr bool kHasRangeLimit = true;  // the estimate is taken in float
  static V load(const T* p) { return _mm256_loadu_pd(p); }
  static void store(T* p, V x) { _mm256_storeu_pd(p, x); }
  static V splat(T x) { return _mm256_set1_pd(x); }
  static V infinity() { return _mm256_set1_pd(__builtin_huge_val()); }
  static V fma(V a, V b, V c) { return _mm256_fmadd_pd(a, b, c); }
  static V min(V a, V b) { return _mm256_min_pd(a, b); }
  static V max(V a, V b) { return _mm256_max_pd(a, b); }
  static V abs(V a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a); }
  static V flip(V x, V s) { return _mm256_xor_pd(x, _mm256_and_pd(s, _mm256_set1_pd(-0.0))); }
  static M lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
  static M gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
  static __m256i as_int(V a) { return _mm256_castpd_si256(a); }
  static V as_double(__m256i a) { return _mm256_castsi256_pd(a); }
  static M lt_nonneg(V a, V b) { return as_double(_mm256_cmpgt_epi64(as_int(b), as_int(a))); }
  static V min_nonneg(V a, V b) { return _mm256_min_pd(a, b); }  // no 64-bit integer min in AVX2
  static V max_nonneg(V a, V b) { return _mm256_max_pd(a, b); }
  // Masked-out lanes become NaN (all ones), and vminpd returns its second operand on a NaN.
  static V min_where(V least, V x, M m) {
    return _mm256_min_pd(_mm256_or_pd(x, _mm256_andnot_pd(m, as_double(_mm256_set1_epi64x(-1)))),
                         least);
  }
  // vmaxpd may drop a NaN, but a NaN coordinate makes its triangle's area NaN, which fails the
  // flatness test; infinity and finite excess are caught here. (No 64-bit integer max in AVX2.)
  static M within(const V* x, int n, T limit) {
    V most = abs(x[0]);
    for (int k = 1; k < n; ++k) most = _mm256_max_pd(most, abs(x[k]));
    return _mm256_cmp_pd(most, _mm256_set1_pd(limit), _CMP_LE_OQ);
  }
  static M both(M a, M b) { return _mm256_and_pd(a, b); }
  static M either(M a, M b) { return _mm256_or_pd(a, b); }
  static M but_not(M a, M b) { return _mm256_andnot_pd(b, a); }
  static V select(M m, V a, V b) { return _mm256_blendv_pd(b, a, m); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_pd(m)); }
  static V sqrt(V a) { return _mm256_sqrt_pd(a); }

  static V rsqrt_estimate(V q) { return _mm256_cvtps_pd(_mm_rsqrt_ps(_mm256_cvtpd_ps(q))); }
  static V inv_sqrt(V q) { return refine_inv_sqrt<Double4>(q, rsqrt_estimate(q)); }

  static void store_status(std::uint8_t* out, M valid, M penetrating, M separated) {
    __m256i code =
        _mm256_add_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(1), _mm256_castpd_si256(penetrating)),
                         _mm256_castpd_si256(separated));
    code = _mm256_blendv_epi8(_mm256_set1_epi64x(3), code, _mm256_castpd_si256(valid));
    const __m128i dwords = _mm256_castsi256_si128(
        _mm256_permutevar8x32_epi32(code, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
    const __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(dwords, dwords), dwords);
    const int four = _mm_cvtsi128_si32(bytes);
    __builtin_memcpy(out, &four, 4);
  }
};

}  // namespace

void penetrate_batch_avx2(const BatchView<float>& v, const BatchLimits<float>& lim, bool depth) {
  run_batch<Float8>(v, lim, depth);
}

void penetrate_batch_avx2(const BatchView<double>& v, const BatchLimits<double>& lim, bool depth) {
  run_batch<Double4>(v, lim, depth);
}

}  // namespace dyop::detail
