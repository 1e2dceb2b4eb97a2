#pragma once
// The exact reference: penetration depth and distance of two triangles computed with exact
// rational arithmetic (GMP) on the given doubles, rounded once at the end.
//
// Depth = min over the six Minkowski-difference axes of overlap; each overlap is N/sqrt(L) with N
// and L exact rationals, evaluated as a 256-bit float (rounding far below double's). Distance when
// apart = the least of the 18 exact vertex–segment distances.

#include "workloads/raw_pair.hpp"

namespace dyop::workloads {

struct ExactAnswer {
  double separation = 0;  // signed: -depth when penetrating, the distance when apart
  int sign = 0;           // exact sign of the separation: -1 penetrating, 0 touching, +1 apart
};

ExactAnswer exact_separation(const RawPair& p);

/// The exact overlap of `p` along the outward normal of one edge (of A when `of_a`, else of B;
/// edge i runs from vertex i to vertex i + 1 in the caller's order): how far the other triangle
/// reaches past that edge's line, the translation along the normal that separates the pair
/// (metres; negative: apart along it). The depth along a set of allowed directions is the least
/// of these over the allowed edges.
double exact_edge_overlap(const RawPair& p, bool of_a, int edge);

}  // namespace dyop::workloads
