#pragma once
/// \file
/// `penetrate_batch`: `sat`'s exact answer for many triangle pairs at once, over
/// structure-of-arrays input, at the `Overlap` and `Depth` levels.
///
/// Algorithm: per pair, as `sat` (`dyop/sat.hpp`): the minimum over the six edge-normal axes of
/// the Minkowski difference of the overlap `max_A(u·a) − min_B(u·b)`, in a frame centred on A's
/// first vertex; a pair found apart gets the exact Euclidean distance. Every row is validated
/// exactly as `Triangle<T>::make` validates it (same arithmetic, same decision). Rows are done 16
/// (float) or 8 (double) at a time with AVX-512, 8 or 4 with AVX2 + FMA, or one at a time, as
/// `BatchKernel` chooses; every kernel gives every row the same bits.
/// For pairs apart the distance is certified without the 18 vertex–edge distances whenever
/// possible: the deepest vertex along the widest-gap axis projecting inside that axis's edge
/// (the gap is then the distance), or the nearest vertex pair supporting both triangles along its
/// direction; pairs with parallel edges may need the full search (slower, same answer).
///
/// Conventions (as every method, `dyop/result.hpp`):
/// - Triangles in world coordinates, any winding; the kernel finds each winding itself.
/// - `normal` is a unit vector from A to B: translating B by `depth * normal` (depth =
///   `-separation`) brings a penetrating pair to touching.
/// - `separation` is signed: `-depth` when penetrating, the Euclidean distance when apart.
///
/// Accuracy against `sat`: the same status except within rounding of the edge of the touching
/// band; separation within a few eps × the pair's size (measured over 25,000 seeded pairs of every
/// input class: ≤ 4e-16 in double, ≤ 2e-7 in float, relative to the pair's size); the same
/// normal except where two axes (or closest-feature pairs) tie. Reciprocal square roots are the
/// CPU's 12-bit estimate (`rsqrtps`, taken in float) refined to within 2 ulp (float: one Halley
/// step; double: one 4th-order step), or 1/`std::sqrt` for squares outside float's normal range:
/// the bits are the same from every kernel on one CPU, and may differ in the last 2 ulp between
/// CPU vendors (their estimates differ).

#include <cstddef>
#include <cstdint>

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// The pairs of a batch, one array per coordinate (structure of arrays). Row `k` is the pair
/// A = (ax0[k], ay0[k]), (ax1[k], ay1[k]), (ax2[k], ay2[k]) and B likewise: world coordinates,
/// any winding, every array `count` long. No alignment is required.
template <class T>
struct PairBatch {
  const T* ax0 = nullptr;  ///< x of A's vertex 0
  const T* ay0 = nullptr;  ///< y of A's vertex 0
  const T* ax1 = nullptr;  ///< x of A's vertex 1
  const T* ay1 = nullptr;  ///< y of A's vertex 1
  const T* ax2 = nullptr;  ///< x of A's vertex 2
  const T* ay2 = nullptr;  ///< y of A's vertex 2
  const T* bx0 = nullptr;  ///< x of B's vertex 0
  const T* by0 = nullptr;  ///< y of B's vertex 0
  const T* bx1 = nullptr;  ///< x of B's vertex 1
  const T* by1 = nullptr;  ///< y of B's vertex 1
  const T* bx2 = nullptr;  ///< x of B's vertex 2
  const T* by2 = nullptr;  ///< y of B's vertex 2
  std::size_t count = 0;   ///< number of pairs (rows)
};

/// Where `penetrate_batch` writes, one entry per row, owned by the caller (the kernel allocates
/// nothing). The arrays must not overlap the input arrays or each other.
template <class T>
struct BatchOutput {
  /// Always written. `Invalid`: a triangle of the row fails `Triangle<T>::make` (non-finite,
  /// too large, repeated vertex, degenerate); `batch_row_error` says which and why. The other
  /// rows are computed as usual.
  Status* status = nullptr;
  /// Level::Depth (not read nor written at Level::Overlap, may then be null): signed;
  /// `-depth` when Penetrating or Touching (|separation| within the touching band), the
  /// exact Euclidean distance when Separated; 0 when Invalid.
  T* separation = nullptr;
  /// Level::Depth: x of the unit normal from A to B. Penetrating or Touching: the
  /// minimum-translation axis; Separated: from A's closest point to B's; 0 when Invalid.
  T* normal_x = nullptr;
  T* normal_y = nullptr;  ///< Level::Depth: y of the unit normal; see `normal_x`
};

/// Which code runs a batch. All give the same answer, bit for bit (status, separation, normal).
enum class BatchKernel : std::uint8_t {
  Auto,      ///< the fastest available: Avx512, else Avx2, else Portable
  Portable,  ///< plain C++, one pair per step: any CPU
  Avx2,      ///< 8 float or 4 double pairs per step with AVX2 and FMA
  Avx512,    ///< 16 float or 8 double pairs per step with AVX-512 (F and DQ)
};

/// Every `BatchKernel`, in declaration order.
inline constexpr BatchKernel batch_kernels[] = {BatchKernel::Auto, BatchKernel::Portable,
                                                BatchKernel::Avx2, BatchKernel::Avx512};

/// True when `kernel` can run here: Auto and Portable always; Avx2 (Avx512) when the library was
/// built with `DYOP_BATCH_AVX2` (`DYOP_BATCH_AVX512`), on x86-64 with GCC or Clang, and the CPU
/// has AVX2 and FMA (AVX-512 F and DQ), asked once with `__builtin_cpu_supports`.
bool batch_kernel_available(BatchKernel kernel);

/// The kernel `penetrate_batch` runs when asked for `requested`: Auto resolves to the fastest
/// available here; any other is itself (available or not: see `batch_kernel_available`).
BatchKernel batch_kernel_used(BatchKernel requested = BatchKernel::Auto);

/// The kernel's one spelling: "auto", "portable", "avx2", "avx512".
const char* name(BatchKernel kernel);

/// What `penetrate_batch` could not do; on any error it writes nothing.
enum class BatchError : std::uint8_t {
  None,               ///< all rows written
  UnsupportedLevel,   ///< Level::Contact or Level::Manifold: use a per-pair method (`sat`)
  NullArray,          ///< count > 0 and an input array, `status`, or at Level::Depth a
                      ///< separation or normal array, is null
  KernelUnavailable,  ///< a kernel forced where it cannot run (`batch_kernel_available`)
};

/// A static, human-readable description of `e`.
const char* describe(BatchError e);

/// `sat`'s status (and at Level::Depth its separation and normal) for every row of `pairs`.
/// Only `Level::Overlap` and `Level::Depth` are supported. Thread-safe for distinct outputs.
template <class T>
BatchError penetrate_batch(const PairBatch<T>& pairs, Level level, const BatchOutput<T>& out,
                           BatchKernel kernel = BatchKernel::Auto);

/// Why row `row` of `pairs` is Invalid: each triangle's `Triangle<T>::make` error (None for a
/// valid one). `row` must be below `pairs.count`.
struct BatchRowError {
  TriangleError a = TriangleError::None;  ///< A's error
  TriangleError b = TriangleError::None;  ///< B's error
  /// True when both triangles are valid.
  bool ok() const { return a == TriangleError::None && b == TriangleError::None; }
};

/// Why row `row` of `pairs` is Invalid (`row` below `pairs.count`).
template <class T>
BatchRowError batch_row_error(const PairBatch<T>& pairs, std::size_t row);

/// \cond EXPLICIT_INSTANTIATIONS
extern template BatchError penetrate_batch(const PairBatch<float>&, Level,
                                           const BatchOutput<float>&, BatchKernel);
extern template BatchError penetrate_batch(const PairBatch<double>&, Level,
                                           const BatchOutput<double>&, BatchKernel);
extern template BatchRowError batch_row_error(const PairBatch<float>&, std::size_t);
extern template BatchRowError batch_row_error(const PairBatch<double>&, std::size_t);
/// \endcond

}  // namespace dyop
