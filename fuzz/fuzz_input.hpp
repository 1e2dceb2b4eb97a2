#pragma once
// The byte format of the method fuzzers: one triangle pair in float or double.
//
// Byte 0: bit 0 set: float, else double; bit 1 set: grid encoding, else raw.
// - Raw: 12 IEEE values, little-endian (8 bytes each for double, 4 for float), in the order
//   ax,ay,bx,by,cx,cy,px,py,qx,qy,rx,ry: every bit pattern, NaN, infinities, subnormals included.
// - Grid: 12 little-endian int16 `g`, then int8 `e`, int8 `f`, int8 `ox`, int8 `oy`: coordinate
//   g·2^e plus the offset (ox, oy)·2^f. Exact collinearity, shared vertices and edges, touching,
//   huge and tiny scales and far offsets are a few bytes away.
// Missing bytes read as zero, so every input decodes. Bytes after the pair are the `rest`, for a
// fuzzer's own use (a Lin–Canny cache).

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "byte_reader.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::fuzz {

struct FuzzInput {
  bool is_float = false;
  std::array<double, 12> coords{};  // as the precision holds them (floats widened exactly)
  const std::uint8_t* rest = nullptr;
  std::size_t rest_size = 0;

  workloads::RawPair pair() const {
    workloads::RawPair p;
    for (int i = 0; i < 3; ++i) {
      p.a[i] = Vec2<double>(coords[2 * i], coords[2 * i + 1]);
      p.b[i] = Vec2<double>(coords[6 + 2 * i], coords[7 + 2 * i]);
    }
    return p;
  }
};

// `x` as a float program holds it: rounded, or an infinity beyond float's range (where the
// conversion itself would be undefined). Through a volatile: GCC 12 drops a vectorised
// double → float → double round trip.
inline double to_float(double x) {
  if (!(std::abs(x) <= double(std::numeric_limits<float>::max()))) {
    return std::isnan(x) ? x : std::copysign(double(std::numeric_limits<float>::infinity()), x);
  }
  const volatile float rounded = static_cast<float>(x);
  return rounded;
}

// Most numbers one input's grid encoding holds (two polygons of 8 vertices).
inline constexpr int kMaxFuzzCoordinates = 32;

// `count` (at most `kMaxFuzzCoordinates`) numbers x, y, x, y, ... into `out`, raw or on the grid
// (the format above), as the precision holds them. Odd positions take the grid's y offset.
inline void read_coordinates(ByteReader& in, bool is_float, bool grid, int count, double* out) {
  if (!grid) {
    for (int i = 0; i < count; ++i) out[i] = is_float ? double(in.get<float>()) : in.get<double>();
    return;
  }
  std::array<std::int16_t, kMaxFuzzCoordinates> g{};
  for (int i = 0; i < count; ++i) g[static_cast<std::size_t>(i)] = in.get<std::int16_t>();
  const int e = in.get<std::int8_t>();
  const int f = in.get<std::int8_t>();
  const double ox = std::ldexp(double(in.get<std::int8_t>()), f);
  const double oy = std::ldexp(double(in.get<std::int8_t>()), f);
  for (int i = 0; i < count; ++i) {
    const double c = std::ldexp(double(g[static_cast<std::size_t>(i)]), e) + (i % 2 == 0 ? ox : oy);
    out[i] = is_float ? to_float(c) : c;
  }
}

inline FuzzInput decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  FuzzInput out;
  const auto mode = in.get<std::uint8_t>();
  out.is_float = (mode & 1u) != 0;
  read_coordinates(in, out.is_float, (mode & 2u) != 0, 12, out.coords.data());
  out.rest = in.here();
  out.rest_size = in.left();
  return out;
}

}  // namespace dyop::fuzz
