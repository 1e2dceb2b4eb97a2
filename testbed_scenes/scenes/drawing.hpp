#pragma once
/// \file
/// A scene's state as a picture to draw: shapes in world coordinates (y up). The report draws it
/// (`report/svg.hpp`); scenes only say what is there.

#include <cstdint>
#include <string>
#include <vector>

#include "dyop/vec2.hpp"

namespace dyop::scenes {

/// One shape to draw, in world coordinates (metres, y up).
struct DrawShape {
  enum class Kind : std::uint8_t { Polygon, Circle, Segment };
  /// Colours: static grey, kinematic blue, dynamic orange.
  enum class Role : std::uint8_t { Static, Kinematic, Dynamic };
  Kind kind = Kind::Polygon;
  Role role = Role::Dynamic;
  /// Polygon: its vertices; circle: its centre, then a point on the rim (shows the rotation);
  /// segment: its two ends.
  std::vector<Vec2<double>> points;
  double radius = 0;  ///< circles only
  std::string label;  ///< drawn at the shape's first-points centroid when not empty
};

/// Everything to draw, with a caption.
struct Drawing {
  std::string title;
  std::vector<DrawShape> shapes;
};

}  // namespace dyop::scenes
