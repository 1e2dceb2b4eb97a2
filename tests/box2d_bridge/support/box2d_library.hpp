#pragma once
// What the Box2D library under test does, for the tests whose expectations depend on it: its
// release (`dyop::box2d::box2d_release`, known at compile time) and whether its asserts are live
// (known at run time only: `b2Assert` is `assert`, so a Box2D built with NDEBUG, as CMake's
// Release builds are, has none; Debian's 2.4.1 has them).

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <type_traits>

#include "dyop/box2d_release.hpp"

// Box2D 2.4.2's hull (b2_collision.h); under 2.4.1 a name never defined nor used.
struct b2Hull;

namespace dyop::box2d::testing {

// Box2D's own `Set` of `n` points, and whether it left a polygon: always under 2.4.1 (whose `Set`
// returns nothing, and asserts or makes a 2×2 box where 2.4.2's refuses); under 2.4.2, false when
// its hull refuses the points and leaves the shape empty.
template <class Shape>
bool box2d_set(Shape& shape, const b2Vec2* points, int n) {
  if constexpr (std::is_same_v<decltype(shape.Set(points, n)), bool>) {
    return shape.Set(points, n);
  } else {
    shape.Set(points, n);
    return true;
  }
}

// The entry `make_triangle` builds its shapes through, on `n` points that are already a CCW hull
// in Box2D 2.4.1's order: 2.4.1's `Set` (which keeps that order), 2.4.2's `Set(const b2Hull&)`
// (which takes the points as they are, without its quickhull's welding and refusals).
template <class Shape, class Hull = b2Hull>
void box2d_set_hull(Shape& shape, const b2Vec2* points, int n) {
  if constexpr (box2d_release == Box2DRelease::V2_4_2) {
    Hull hull;
    for (int i = 0; i < n; ++i) hull.points[i] = points[i];
    hull.count = n;
    shape.Set(hull);
  } else {
    shape.Set(points, n);
  }
}

// True when the Box2D library aborts on its asserts. Asked once, in a child process: the mass of
// an empty polygon, which 2.4.1 and 2.4.2 both assert on (`m_count >= 3` in
// `b2PolygonShape::ComputeMass`); without asserts it returns a non-finite centre and the child
// exits normally.
inline bool box2d_asserts() {
  static const bool live = [] {
    const pid_t child = fork();
    if (child == 0) {
      const int null = open("/dev/null", O_WRONLY);  // the assertion's message is not news here
      if (null >= 0) dup2(null, STDERR_FILENO);
      b2PolygonShape empty;
      b2MassData mass;
      empty.ComputeMass(&mass, 1.0f);
      _exit(0);
    }
    int status = 0;
    if (child < 0 || waitpid(child, &status, 0) != child) {
      ADD_FAILURE() << "could not run the child process that probes Box2D's asserts";
      return false;
    }
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
  }();
  return live;
}

// The message of a test part skipped because the library has no asserts to die on.
inline constexpr const char* kNoAsserts =
    "this Box2D library was built without asserts (NDEBUG): it does not abort on these points";

}  // namespace dyop::box2d::testing
