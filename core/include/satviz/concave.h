// SPDX-License-Identifier: MIT
// satviz: concave shapes, as compounds of convex pieces, in the queries (Overlap, Collide, Sweep, RayCast).
#pragma once

#include <satviz/decompose.h>
#include <satviz/manifold.h>
#include <satviz/raycast.h>
#include <satviz/shape.h>
#include <satviz/sweep.h>

#include <vector>

namespace satviz
{

/// An axis-aligned box in a body frame.
template <typename S>
struct BoundsT
{
    Vec2T<S> min{}; ///< lower-left corner
    Vec2T<S> max{}; ///< upper-right corner
};

/// One convex piece of a concave shape.
template <typename S>
struct ConcavePartT
{
    ShapeT<S> shape;            ///< the piece, a convex polygon in the body frame
    std::vector<bool> internal; ///< for each edge of the piece: shared with another piece (a seam, not a surface)
    BoundsT<S> bounds;          ///< the piece's box in the body frame (the broadphase boxes each piece as placed)
};

/// Double-precision piece.
using ConcavePart = ConcavePartT<double>;

/// A concave shape: convex pieces in one body frame (from Decompose), which meet along their internal edges.
template <typename S>
struct ConcaveT
{
    std::vector<ConcavePartT<S>> parts; ///< the pieces, in the decomposition's order
};

/// Double-precision concave shape.
using Concave = ConcaveT<double>;

/// A concave shape from the pieces of a decomposition (DecompositionT::pieces).
template <typename S>
ConcaveT<S> MakeConcave(const std::vector<ConvexPieceT<S>>& pieces);

/// Collide for pairs with a concave shape: the merged manifold, and the pieces whose pair decided it.
template <typename S>
struct ConcaveManifoldT
{
    /// As for convex shapes: overlap, depth, normal from A to B, up to two contacts; axis.index names an edge or
    /// vertex of the deciding piece (pieceA or pieceB, whichever axis.shape names).
    ManifoldT<S> manifold;
    int pieceA = -1;      ///< A's deciding piece, or -1 when A is convex (or when no piece pair was near)
    int pieceB = -1;      ///< B's deciding piece, or -1
    int pairsTested = 0;  ///< piece pairs whose boxes overlapped and were collided
    int pairsOverlap = 0; ///< of these, the pairs that overlap
    int pairsSeam = 0;    ///< of these, the pairs whose own normal pointed along an internal edge (rule 2)
};

/// Double-precision concave manifold.
using ConcaveManifold = ConcaveManifoldT<double>;

/// True when the shapes intersect (touching counts): some piece of A overlaps B. Only the pieces whose boxes
/// overlap B's box are tested.
template <typename S>
bool Overlap(const ConcaveT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB);
/// Convex against concave; see above.
template <typename S>
bool Overlap(const ShapeT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b, const TransformT<S>& xfB);
/// Concave against concave: some pair of pieces overlaps.
template <typename S>
bool Overlap(const ConcaveT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b, const TransformT<S>& xfB);

/// One manifold for a pair with a concave shape. The rule:
/// 1. Every pair of pieces (a convex shape is one piece) whose boxes overlap is collided.
/// 2. A pair whose normal, taken outward from a concave piece, points along an internal edge of that piece (it is
///    that edge's normal, or, for a circle in a corner's region, it leans past a corner into the internal edge's
///    side) would push out through a seam, where the shape goes on: a ghost collision. Two polygons are tested
///    again on the surface axes alone (the face normals of both, less those along internal edges): the least
///    overlap there is the pair's depth, its contacts B's deepest points on that axis, halfway to A's surface.
///    A pair with a circle is dropped instead, unless every overlapping pair is dropped (then all are kept).
/// 3. Of the pairs left, the deepest decides the normal, depth and axis: moving B by depth * normal clears that
///    piece. Depths are never added: two pieces under a shape lying across their seam would push it twice.
/// 4. Contacts: those of the pairs left whose normal is the deciding one (a flat surface made of several pieces);
///    of these the two farthest apart across the normal, so a box across a seam keeps its two corners.
/// Separated: overlap false; gap and normal of the pair whose lower bound of the distance is least (a collided
/// pair's gap, or for pairs whose boxes are apart, the gap between the boxes on the axis that parts them).
template <typename S>
ConcaveManifoldT<S> Collide(const ConcaveT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                            const TransformT<S>& xfB);
/// Convex against concave; see above.
template <typename S>
ConcaveManifoldT<S> Collide(const ShapeT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                            const TransformT<S>& xfB);
/// Concave against concave; see above.
template <typename S>
ConcaveManifoldT<S> Collide(const ConcaveT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                            const TransformT<S>& xfB);

/// Speculative contacts (CollideWithin) for pairs with a concave shape, by pieces. Overlapping: the merged manifold
/// of Collide above. Apart by at most `margin` (>= 0): each pair of pieces whose boxes, grown by the margin, overlap
/// gets CollideWithin; a pair whose normal points along an internal edge is dropped (the seam rule of Collide: a
/// box hovering beside a seam must not be pushed sideways through it); of the pairs left, the least gap decides the
/// normal and the axis, and its contacts, with those of the pairs that share its normal, give the two farthest
/// apart across it (a box above a floor of pieces keeps a point on each side of a seam). Farther apart: overlap
/// false, no contacts, a lower bound of the gap (as Collide).
template <typename S>
ConcaveManifoldT<S> CollideWithin(const ConcaveT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                                  const TransformT<S>& xfB, S margin);
/// Convex against concave; see above.
template <typename S>
ConcaveManifoldT<S> CollideWithin(const ShapeT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                                  const TransformT<S>& xfB, S margin);
/// Concave against concave; see above.
template <typename S>
ConcaveManifoldT<S> CollideWithin(const ConcaveT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                                  const TransformT<S>& xfB, S margin);

/// Sweep for pairs with a concave shape, and the pieces that decided it.
template <typename S>
struct ConcaveSweepResultT
{
    SweepResultT<S> result; ///< as for convex shapes; `initial` is the merged manifold (Collide above)
    int pieceA = -1;        ///< A's piece hit first, or -1 when A is convex or nothing is hit
    int pieceB = -1;        ///< B's piece hit first, or -1
};

/// Double-precision concave sweep result.
using ConcaveSweepResult = ConcaveSweepResultT<double>;

/// The swept test (Sweep) against each pair of pieces whose boxes, swept over the step, overlap: the earliest hit
/// decides; at equal times a hit whose normal is not along an internal edge is preferred. Overlapping at t = 0 when
/// some pair overlaps then, with the merged manifold of Collide as `initial`.
template <typename S>
ConcaveSweepResultT<S> Sweep(const ConcaveT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                             const TransformT<S>& xfB, Vec2T<S> vB);
/// Convex against concave; see above.
template <typename S>
ConcaveSweepResultT<S> Sweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ConcaveT<S>& b,
                             const TransformT<S>& xfB, Vec2T<S> vB);
/// Concave against concave; see above.
template <typename S>
ConcaveSweepResultT<S> Sweep(const ConcaveT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ConcaveT<S>& b,
                             const TransformT<S>& xfB, Vec2T<S> vB);

/// A segment cast against a concave shape: the hit, and the piece hit.
template <typename S>
struct ConcaveRayHitT
{
    RayHitT<S> hit; ///< as for convex shapes; edge is an edge of `piece`
    int piece = -1; ///< the piece hit first (or the piece the segment starts in), -1 on a miss
};

/// Double-precision concave ray hit.
using ConcaveRayHit = ConcaveRayHitT<double>;

/// The first point where the segment from p1 to p2 meets the concave shape: the least fraction over the pieces
/// whose boxes the segment's box overlaps, a hit on an outline edge preferred over one on an internal edge at the
/// same fraction. startsInside when p1 is in some piece.
template <typename S>
ConcaveRayHitT<S> RayCast(const ConcaveT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2);

} // namespace satviz
