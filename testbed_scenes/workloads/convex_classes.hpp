#pragma once
/// \file
/// The input classes of the convex pairs beyond two triangles: polygon–polygon (3 to 8 vertices
/// each, `SetAsBox` boxes among them) and polygon–circle, made by the seeded generator of
/// `workloads/random.hpp` as `input_classes.hpp` makes triangle pairs, so that a seed gives the
/// same pairs with any compiler and library.
///
/// Polygons: a quarter are boxes as `b2PolygonShape::SetAsBox` makes them (4 vertices, its
/// counter-clockwise order, axis-aligned half the time), the rest 3 to 8 vertices on an ellipse, in
/// a random winding from a random first vertex.

#include <cstdint>
#include <vector>

#include "workloads/precision.hpp"
#include "workloads/raw_convex_pair.hpp"

namespace dyop::workloads {

enum class ConvexClass {
  Overlapping,  ///< B (size 0.3 to 1.5) within a unit of A (size 1), the pairs that penetrate
  Separated,    ///< the same draws apart with overlapping bounding boxes
  Scale,        ///< the same draws, either way, scaled by 1e-6 to 1e6; a quarter with B up to
                ///< 1e3 smaller
  Far,          ///< the same draws, either way, 1e-3 to 1 times `max_offset` from the origin
  Sliver,       ///< B thin (aspect 1e-6 to 1e-1; for a circle pair A), half the time A too
  Touching,     ///< exactly touching: B on a horizontal edge of A (vertex, edge or vertex on a
                ///< vertex; a circle on the edge or, tangent, on its end vertex), a quarter-turn
  Nested,       ///< one polygon inside the other (shrunk about an inner point, a vertex or a point
                ///< of an edge); the circle's centre inside the polygon (a quarter: on a vertex)
};

/// Every class, in the order the tests report them.
inline constexpr ConvexClass convex_classes[] = {
    ConvexClass::Overlapping, ConvexClass::Separated, ConvexClass::Scale, ConvexClass::Far,
    ConvexClass::Sliver,      ConvexClass::Touching,  ConvexClass::Nested};

/// The class's one spelling: "overlapping", "separated", "scale", "far", "sliver", "touching",
/// "nested".
const char* name(ConvexClass c);

/// `count` polygon pairs of class `c` made for `precision`, rounded to it and valid in it (the
/// invalid draws skipped), the same for the same seed.
std::vector<RawPolygonPair> make_polygon_pairs(ConvexClass c, int count, std::uint64_t seed,
                                               Precision precision);

/// `count` polygon–circle pairs of class `c`, as `make_polygon_pairs`.
std::vector<RawCirclePair> make_circle_pairs(ConvexClass c, int count, std::uint64_t seed,
                                             Precision precision);

/// `count` segment–polygon pairs of class `c` (A a segment of 2 vertices: a chord of the class's
/// polygon A, either way round; `Touching`: B on A's top edge, front or back; `Nested`: a chord of
/// a polygon shrunk inside B), as `make_polygon_pairs`.
std::vector<RawPolygonPair> make_segment_pairs(ConvexClass c, int count, std::uint64_t seed,
                                               Precision precision);

/// `count` segment–circle pairs of class `c`, as `make_segment_pairs` (`Nested`: the circle's
/// centre on the segment, a quarter of the time on an end).
std::vector<RawCirclePair> make_segment_circle_pairs(ConvexClass c, int count, std::uint64_t seed,
                                                     Precision precision);

}  // namespace dyop::workloads
