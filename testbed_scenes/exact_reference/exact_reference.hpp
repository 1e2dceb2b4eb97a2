#pragma once
// The exact reference: penetration depth and distance of two convex polygons (two triangles,
// or 3 to 8 vertices each; A a segment where it has 2, a polygon of its two sides) and of a
// polygon (or segment) and a circle, computed exactly (GMP) on the given doubles, rounded once at
// the end.
//
// Every double of a pair is an integer times a power of two; with the least such power of the pair
// as the unit, every coordinate is an exact integer, and every product, sum and comparison below
// is exact integer arithmetic. Two polygons: depth = min over both polygons' edge normals (the
// Minkowski difference's axes) of the overlap N/sqrt(L), N and L exact integers, the least found
// by exact comparison and only it evaluated, as a 256-bit float (rounding far below double's).
// Distance when apart = the least of the exact vertex–segment distances, both ways. A polygon and
// a circle: the centre's signed distance from the polygon less the radius; inside, minus the least
// distance to an edge line, outside, the square root of the exact squared distance to the nearest
// edge, its sign decided exactly against the squared radius.

#include "workloads/raw_convex_pair.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::workloads {

struct ExactAnswer {
  double separation = 0;  // signed: -depth when penetrating, the distance when apart
  int sign = 0;           // exact sign of the separation: -1 penetrating, 0 touching, +1 apart
};

ExactAnswer exact_separation(const RawPair& p);
ExactAnswer exact_separation(const RawPolygonPair& p);
ExactAnswer exact_separation(const RawCirclePair& p);

/// The exact overlap of `p` along the outward normal of one edge (of A when `of_a`, else of B;
/// edge i runs from vertex i to vertex i + 1 in the caller's order): how far the other triangle
/// reaches past that edge's line, the translation along the normal that separates the pair
/// (metres; negative: apart along it). The depth along a set of allowed directions is the least
/// of these over the allowed edges.
double exact_edge_overlap(const RawPair& p, bool of_a, int edge);
/// The same for two polygons (edge i from vertex i to vertex (i + 1) % count).
double exact_edge_overlap(const RawPolygonPair& p, bool of_a, int edge);
/// The exact overlap of circle B past the line of A's edge `edge` (caller's order), along its
/// outward normal: the radius less the centre's signed distance from that line.
double exact_edge_overlap(const RawCirclePair& p, int edge);

}  // namespace dyop::workloads
