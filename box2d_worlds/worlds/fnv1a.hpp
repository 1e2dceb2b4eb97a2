#pragma once
/// \file
/// The hash of world states (`state_hash`) and of the scenes' runs.

#include <cstddef>
#include <cstdint>

namespace dyop::worlds {

/// FNV-1a (64-bit), fed value by value with the bit patterns of floats.
class Fnv1a {
 public:
  void add(float v);
  void add(double v);
  std::uint64_t value() const { return h_; }

 private:
  void bytes(const unsigned char* p, std::size_t n);
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace dyop::worlds
