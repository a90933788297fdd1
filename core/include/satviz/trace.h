// SPDX-License-Identifier: MIT
// satviz: the step trace of a SAT query, recorded for teaching views and figures. Data only: nothing here draws.
#pragma once

#include <satviz/manifold.h>

#include <vector>

namespace satviz
{

/// One axis as the algorithm tested it. Geometry is in world space, oriented as `direction`.
template <typename S>
struct AxisTestT
{
    AxisRef axis{};       ///< where the axis comes from
    Vec2T<S> direction{}; ///< unit axis in world space (a face's outward normal, or vertex/centre to centre)
    S minA{}, maxA{};     ///< projection interval of shape A on `direction`
    S minB{}, maxB{};     ///< projection interval of shape B on `direction`
    /// The separation the algorithm computed on this axis, scaled to unit length: > 0 is a gap that separates,
    /// <= 0 an overlap of -separation. An axis of B (a face of B, or B's vertex towards circle A) points from B
    /// towards A and its separation is minA - maxB; every other axis points from A towards B, with minB - maxA.
    S separation{};
    int supportA = -1;       ///< A's vertex that realises the separation (-1 for a circle)
    int supportB = -1;       ///< B's vertex that realises the separation (-1 for a circle)
    bool separating = false; ///< this axis separates the shapes: the test stopped here (early exit)
    /// The axis repeats one already tested (a face of B anti-parallel to a face of A): no work was done for it.
    bool skipped = false;
    int duplicateOf = -1; ///< with skipped: index in TraceT::axes of the test it repeats
    /// The axis was pruned: one point of the other polygon lies no farther out than `bound` on it, which bounds
    /// the separation from above and showed that this face could neither separate the shapes nor beat the best
    /// face so far. The queries prune faces only against a polygon they walk (above 16 vertices), and the point is
    /// then that polygon's support point found earlier. `separation` and the intervals are computed for the view
    /// only.
    bool pruned = false;
    S bound{};     ///< with pruned: the point's separation, an upper bound of `separation`
    int best = -1; ///< index in TraceT::axes of the axis with the largest separation so far, this one included
};

/// Double-precision axis test.
using AxisTest = AxisTestT<double>;

/// How the contact points of an overlapping polygon pair were found (Sutherland-Hodgman clipping of the incident
/// edge against the side planes of the reference face). World space.
template <typename S>
struct ClipTraceT
{
    AxisRef reference{};        ///< the reference face (the deciding axis)
    Vec2T<S> referenceV1{};     ///< first vertex of the reference face
    Vec2T<S> referenceV2{};     ///< second vertex of the reference face
    Vec2T<S> referenceNormal{}; ///< outward normal of the reference face
    int incidentShape = -1;     ///< 0 (A) or 1 (B): the shape that owns the incident edge
    int incidentEdge = -1;      ///< index of the incident edge: the edge most anti-parallel to the reference face
    Vec2T<S> incidentV1{};      ///< first vertex of the incident edge
    Vec2T<S> incidentV2{};      ///< second vertex of the incident edge
    Vec2T<S> sideClip1[2]{};    ///< incident edge clipped by the side plane through referenceV1
    int sideClip1Count = 0;     ///< number of points in sideClip1
    Vec2T<S> sideClip2[2]{};    ///< then clipped by the side plane through referenceV2
    int sideClip2Count = 0;     ///< number of points in sideClip2
    S clippedSeparation[2]{};   ///< signed distance of each sideClip2 point to the reference face
    bool kept[2]{};             ///< whether each sideClip2 point was kept (below the reference face)
    bool usedFallback = false;  ///< no clipped point was kept, the deepest incident vertex was used instead
};

/// Double-precision clip trace.
using ClipTrace = ClipTraceT<double>;

/// Why the test ended.
enum class TraceExit
{
    None,           ///< nothing recorded yet
    SeparatingAxis, ///< an axis separated the shapes (the last entry of axes)
    AllAxesOverlap, ///< every axis overlapped: the shapes intersect
    /// Overlap only: a vertex of one polygon lies inside the other (containedShape, containedVertex), so the shapes
    /// intersect and the remaining axes were not tested.
    VertexInside,
};

/// The instructions a query's loops run on. Each path gives the same answers to the bit.
enum class InstructionPath
{
    Baseline, ///< the lanes every processor of the architecture has (SSE2 on x86-64); a traced query runs these
    Avx2,     ///< 256-bit vectors (AVX2)
    Avx512,   ///< 512-bit vectors (AVX-512F): the face loops of two polygons of up to 8 vertices each, in double
};

/// The complete record of one query: every axis in the order tested, the contact clipping, and the result.
/// Recorded in every build type. Filling it allocates; the untraced queries never do.
template <typename S>
struct TraceT
{
    std::vector<AxisTestT<S>> axes;   ///< axes in test order, skipped duplicates included
    bool hasClip = false;             ///< clip is filled (overlapping polygon pairs)
    ClipTraceT<S> clip{};             ///< contact clipping
    TraceExit exit = TraceExit::None; ///< why the test ended
    int containedShape = -1;          ///< with VertexInside: the polygon (0 = A, 1 = B) whose vertex lies inside
    int containedVertex = -1;         ///< with VertexInside: that vertex
    ManifoldT<S> result{};            ///< the query's result (for Overlap: only `overlap` is set)
    /// The instructions the same query runs on, untraced, on this processor. The trace shows the baseline loops,
    /// whose numbers are those of every path, to the bit (the property tests of tests/test_wide.cpp hold them so);
    /// the order in which wider loops take the faces is their own.
    InstructionPath untracedPath = InstructionPath::Baseline;
    /// Empties the trace for reuse.
    void Clear() { *this = TraceT<S>(); }
};

/// Double-precision trace.
using Trace = TraceT<double>;

} // namespace satviz
