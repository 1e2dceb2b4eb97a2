#pragma once
/// \file
/// Which Box2D 2.4 release the plug-in is compiled against, told apart at compile time.
///
/// Box2D 2.4.2's CMake and `b2_version` still say 2.4.1; what changed is `b2PolygonShape::Set`:
/// 2.4.0 and 2.4.1 return `void` and wrap the hull of the points as a gift (welding points closer
/// than 0.5·b2_linearSlop); 2.4.2 returns `bool`, computes a quickhull (`b2ComputeHull`) that
/// welds points within 4·b2_linearSlop and drops those within 2·b2_linearSlop of their
/// neighbours' line, and leaves the shape empty (`m_count` 0) when fewer than three points remain.
/// `dyop::box2d::make_triangle` builds the same shape under both (`dyop/box2d.hpp`).

#include <box2d/b2_polygon_shape.h>

#include <cstdint>
#include <type_traits>
#include <utility>

namespace dyop::box2d {

/// The Box2D 2.4 releases whose `b2PolygonShape::Set` differ.
enum class Box2DRelease : std::uint8_t {
  V2_4_1,  ///< 2.4.0 or 2.4.1: `Set` returns void, gift wrapping from the rightmost point
  V2_4_2,  ///< 2.4.2: `Set` returns bool (quickhull, may leave the shape empty); `b2Hull` exists
};

/// The release compiled against: 2.4.2 when `Set(points, count)` returns `bool`.
inline constexpr Box2DRelease box2d_release =
    std::is_same_v<decltype(std::declval<b2PolygonShape&>().Set(nullptr, 0)), bool>
        ? Box2DRelease::V2_4_2
        : Box2DRelease::V2_4_1;

/// The release's spelling for messages: "2.4.1" (for 2.4.0 too) or "2.4.2".
constexpr const char* name(Box2DRelease r) { return r == Box2DRelease::V2_4_2 ? "2.4.2" : "2.4.1"; }

}  // namespace dyop::box2d
