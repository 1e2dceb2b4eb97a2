#pragma once
/// \file
/// A ground from a polygon outline with holes — the vertices a Box2D user would give
/// `b2ChainShape`, from a level editor or an SVG — triangulated and added to a body with its edge
/// data fixed, so that the plug-in's internal-edge rule glides bodies across it. The triangulation
/// is GEOS's constrained Delaunay triangulation (LGPL-2.1, linked as a shared library): this
/// target, `dyop::box2d_outlines`, is optional and apart from the plug-in (docs/box2d-plugin.md,
/// "Grounds from outlines").
///
///     const std::vector<std::vector<b2Vec2>> rings = {
///         {{0, 0}, {20, 0}, {20, 4}, {0, 4}},    // the outline
///         {{5, 1}, {7, 1}, {7, 2}, {5, 2}}};     // a cave in it
///     dyop::box2d::OutlineResult r = dyop::box2d::add_outline(*ground, rings);
///     if (!r.ok()) std::cerr << "ring " << r.ring << ": " << r.message << '\n';

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_math.h>

#include <cstdint>
#include <vector>

#include "dyop/box2d_mesh.hpp"

namespace dyop::box2d {

/// Why `add_outline` refused an outline; it then created nothing.
enum class OutlineError : std::uint8_t {
  None,              ///< the outline was added
  NoRings,           ///< no ring was given
  NotFinite,         ///< a coordinate is NaN or infinite: see `OutlineResult::ring`
  TooFewPoints,      ///< a ring has fewer than 3 distinct points: see `OutlineResult::ring`
  ZeroArea,          ///< a ring encloses no area (all its points on one line)
  SelfIntersection,  ///< a ring crosses itself or another ring, or two rings share an edge
  HoleOutside,       ///< a hole lies (partly) outside the outline
  NestedHoles,       ///< a hole lies inside another hole
  SplitInterior,     ///< holes touching each other or the outline cut the ground in pieces
  Invalid,           ///< another reason GEOS gives for an invalid polygon
  Triangles,         ///< `add_triangles` refused the triangulation: see `OutlineResult::mesh`
};

/// A static, human-readable description of `e`.
const char* describe(OutlineError e);

/// How `add_outline` builds the ground.
struct OutlineOptions {
  /// Vertices of the outline within this distance of the line through their neighbours are
  /// dropped before triangulating (metres; default `b2_linearSlop`, 0.005 m: Box2D welds vertices
  /// closer than that, and a straight run needs no vertex). 0 keeps every vertex.
  float simplify = b2_linearSlop;
  /// The triangles are made within square cells of this side (metres; default 2; the cells'
  /// sides at multiples of it in the body frame): each triangle's box stays within a cell, so a
  /// body meets few triangles in the broad phase. 0: one triangulation of the whole outline, whose
  /// triangles span its straight runs and depth.
  float cell = 2;
  /// The fixtures are made like this (density, friction, filter...; `shape` is ignored).
  b2FixtureDef fixture;
};

/// The outcome of `add_outline`, returned by value.
struct OutlineResult {
  OutlineError error = OutlineError::None;  ///< always valid
  /// The ring at fault (0: the outline, 1..: the holes in the order given); -1 when none or when
  /// the reason concerns several rings.
  int ring = -1;
  /// `error == Triangles`: what `add_triangles` found; otherwise its `fixtures` are those made.
  MeshResult mesh;
  const char* message = "";  ///< static, human-readable: what is wrong, or "outline added"
  int vertices = 0;          ///< vertices triangulated (after `OutlineOptions::simplify`)
  bool ok() const { return error == OutlineError::None; }  ///< true when `error == None`
};

/// Triangulates the polygon `rings` (body frame, metres: `rings[0]` the outline, the others its
/// holes; either winding; a ring's last point may repeat its first) and adds its triangles to
/// `body` with `add_triangles`: the edge data of every triangle fixed, so the edges inside the
/// ground are internal and a hole's and the outline's edges are not. A self-intersecting ring,
/// a hole outside the outline, holes that cut the ground in pieces and degenerate rings are
/// refused with a reason (holes touching the outline or each other at a single point are
/// accepted); nothing is created on refusal. Thread-safe (one GEOS context per call).
OutlineResult add_outline(b2Body& body, const std::vector<std::vector<b2Vec2>>& rings,
                          const OutlineOptions& options = OutlineOptions());

}  // namespace dyop::box2d
