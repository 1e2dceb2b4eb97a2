#include "worlds/fnv1a.hpp"

#include <cstring>

namespace dyop::worlds {

void Fnv1a::bytes(const unsigned char* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    h_ ^= p[i];
    h_ *= 0x100000001b3ull;
  }
}

void Fnv1a::add(float v) {
  unsigned char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  bytes(b, sizeof b);
}

void Fnv1a::add(double v) {
  unsigned char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  bytes(b, sizeof b);
}

}  // namespace dyop::worlds
