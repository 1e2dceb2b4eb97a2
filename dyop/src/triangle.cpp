#include "dyop/triangle.hpp"

#include <algorithm>
#include <cmath>

namespace dyop {

const char* describe(TriangleError e) {
  switch (e) {
    case TriangleError::None:
      return "valid triangle";
    case TriangleError::NonFinite:
      return "non-finite coordinate (NaN or infinity)";
    case TriangleError::TooLarge:
      return "coordinate too large (beyond max_coordinate: squared lengths would overflow)";
    case TriangleError::TooSmall:
      return "triangle too small (longest edge below min_size: squared lengths would underflow)";
    case TriangleError::RepeatedVertex:
      return "repeated vertex (two vertices are equal)";
    case TriangleError::Degenerate:
      return "degenerate triangle (vertices collinear within the flatness tolerance)";
  }
  return "unknown triangle error";
}

template <class T>
TriangleOrError<T> Triangle<T>::make(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& p2) {
  TriangleOrError<T> out;
  out.error = check(p0, p1, p2);
  if (out.error != TriangleError::None) return out;
  Triangle<T>& t = out.triangle;
  t.flipped_ = cross(Vec2<T>(p1 - p0), Vec2<T>(p2 - p0)) < 0;
  t.v_ = {p0, t.flipped_ ? p2 : p1, t.flipped_ ? p1 : p2};
  for (int i = 0; i < 3; ++i) {
    const Vec2<T> e = t.v_[(i + 1) % 3] - t.v_[i];
    t.len_[i] = e.norm();
    t.n_[i] = right_perp(e) / t.len_[i];
  }
  t.size_ = std::max({t.len_[0], t.len_[1], t.len_[2]});
  return out;
}

template <class T>
Triangle<T> Triangle<T>::moved(T c, T s, const Vec2<T>& translation) const {
  Triangle<T> t = *this;
  for (int i = 0; i < 3; ++i) {
    t.v_[i] = rotated(v_[i], c, s) + translation;
    t.n_[i] = rotated(n_[i], c, s);
  }
  return t;
}

template class Triangle<float>;
template class Triangle<double>;

}  // namespace dyop
