#pragma once
// Bytes read as values, for every fuzzer's decoding: missing bytes read as zero, so that every
// input decodes.

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace dyop::fuzz {

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  void read(void* out, std::size_t n) {
    std::memset(out, 0, n);
    const std::size_t k = n < size_ - at_ ? n : size_ - at_;
    if (k > 0) std::memcpy(out, data_ + at_, k);
    at_ += k;
  }
  template <class V>
  V get() {
    V v;
    read(&v, sizeof v);
    return v;
  }
  const std::uint8_t* here() const { return data_ + at_; }
  std::size_t left() const { return size_ - at_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

}  // namespace dyop::fuzz
