// SPDX-License-Identifier: MIT
// satviz: convex decomposition of simple polygons, so that a concave outline can take part in the SAT queries.
#pragma once

#include <satviz/polygon.h>

#include <string>
#include <vector>

namespace satviz
{

/// How to cut a simple polygon into convex pieces.
enum class DecomposeMethod
{
    /// Ear clipping into triangles, then Hertel-Mehlhorn: drop every diagonal whose removal leaves both of its
    /// ends convex. O(n^2) for n vertices; at most four times the fewest pieces possible.
    Fast,
    /// The fewest convex pieces whose corners are vertices of the outline (no new points): an exact dynamic
    /// programme over the diagonals, O(n^5) with a small constant, for outlines of at most kFewestMaxVertices
    /// vertices (after dropping repeated and collinear ones); larger outlines get the Fast result. Never more
    /// pieces than Fast.
    Fewest,
};

/// Outlines above this many vertices are decomposed by Fewest as by Fast (the exact programme's O(n^5) stops
/// being interactive beyond it).
constexpr int kFewestMaxVertices = 100;

/// One convex piece of a decomposition.
template <typename S>
struct ConvexPieceT
{
    PolygonT<S> polygon;        ///< the piece, counter-clockwise, strictly convex
    std::vector<int> source;    ///< for each vertex of the piece, the index of the input vertex it is
    std::vector<bool> internal; ///< for each edge i (vertex i to i + 1) of the piece: a diagonal shared with
                                ///< another piece (true) or a part of the outline (false)
};

/// Double-precision piece.
using ConvexPiece = ConvexPieceT<double>;

/// Why an outline could not be decomposed.
enum class DecomposeError
{
    None,             ///< decomposed
    TooFewVertices,   ///< fewer than 3 distinct vertices
    NotFinite,        ///< a coordinate is NaN or infinite (vertex `edgeA`)
    TooLarge,         ///< a coordinate exceeds kMaxCoordinate in magnitude (vertex `edgeA`)
    ZeroArea,         ///< the outline encloses no area (every vertex on one line)
    SelfIntersecting, ///< edges `edgeA` and `edgeB` cross or touch: the outline is not simple
};

/// The outcome of a decomposition: the pieces, or an error.
template <typename S>
struct DecompositionT
{
    std::vector<ConvexPieceT<S>> pieces;         ///< the convex pieces; empty when error != None
    DecomposeError error = DecomposeError::None; ///< what is wrong, if anything
    /// SelfIntersecting: the two input edges that meet (edge i runs from input vertex i to the next input vertex
    /// that differs from it), edgeA < edgeB. NotFinite, TooLarge: edgeA is the offending vertex. Else -1.
    int edgeA = -1;
    int edgeB = -1; ///< see edgeA
    /// True when the outline was decomposed.
    bool Ok() const { return error == DecomposeError::None; }
};

/// Double-precision decomposition.
using Decomposition = DecompositionT<double>;

/// Cuts a simple polygon (no holes) into convex pieces. Either orientation is accepted; repeated consecutive
/// vertices and vertices on the line through their neighbours ("straight" vertices) are dropped first: each lies
/// on an outline edge of a piece but is a corner of none, since a piece is strictly convex (MakePolygon's rule: a
/// corner turns) and no seam ends there. So the pieces are those of the outline without them, and they cost
/// pieces where a seam would have served best by ending at one: a bump on a flat floor, written with the floor's
/// top running on through the bump's feet, is not the bump and the floor below it (whose top would have straight
/// corners at the bump's feet) but more pieces, cut from the floor's lower corners. Every other input vertex is a
/// corner of at least one piece, the pieces cover the outline exactly (their areas sum to its area) and meet only
/// along their internal edges.
/// An outline that is not simple (two edges cross or touch, or an edge folds back along the one before it) gets
/// SelfIntersecting with the two edges; the check costs O(n^2) at worst, so the call ends on any input.
template <typename S>
DecompositionT<S> Decompose(const std::vector<Vec2T<S>>& points, DecomposeMethod method);

/// A one-line English description of the error, e.g. "polygon is not simple: edge 1 (vertex 1 to 2) crosses edge
/// 3 (vertex 3 to 0)". `points` is the decomposed input, for the edges' end vertices.
template <typename S>
std::string DescribeDecomposeError(const DecompositionT<S>& decomposition, const std::vector<Vec2T<S>>& points);

} // namespace satviz
