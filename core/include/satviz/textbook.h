// SPDX-License-Identifier: MIT
// satviz: the separating axis test as textbooks teach it: project both shapes on every distinct axis and compare
// the two intervals. Written for reading and for the teaching views; Overlap, Collide and Sweep give the same
// answers faster (their face tests are each one side of an axis of this test).
#pragma once

#include <satviz/manifold.h>
#include <satviz/shape.h>
#include <satviz/sweep.h>

#include <vector>

namespace satviz
{

/// Most faces one axis can stand for: a convex polygon has at most two faces on one line (a face and the one
/// opposite it), so two polygons give at most four.
constexpr int kMaxFacesPerAxis = 4;

/// One distinct axis of the textbook test, with both projection intervals. World space.
template <typename S>
struct TextbookAxisT
{
    /// Where the axis comes from: the face normals (or the vertex axis, or the line of centres) that lie on it.
    /// faces[0] names the axis and gives it its direction: in a trace, A's face turned towards B, else B's face
    /// turned towards A (the face a reader looks at), else the first listed. The others are parallel or
    /// anti-parallel to it and were merged.
    AxisRef faces[kMaxFacesPerAxis]{};
    int faceCount = 0;    ///< number of entries in faces
    Vec2T<S> direction{}; ///< unit axis, world space: the outward normal of faces[0] (or vertex to centre)
    S minA{}, maxA{};     ///< projection interval of shape A on `direction`
    S minB{}, maxB{};     ///< projection interval of shape B on `direction`
    /// The intervals are disjoint: this axis separates the shapes and the test stops here.
    bool separating = false;
    /// separating: the gap between the intervals, max(minB - maxA, minA - maxB) > 0. Else 0.
    S gap{};
    /// not separating: how far the intervals overlap, min(maxA - minB, maxB - minA) >= 0: the shortest push of
    /// B along this axis (one way or the other) that separates the intervals. Else 0.
    S overlap{};
    /// not separating: +1 when that push moves B along `direction` (maxA - minB is the smaller), -1 against it.
    int pushSign = 0;
    int best = -1; ///< index in the trace of the axis with the smallest overlap so far, this one included
};

/// Double-precision textbook axis.
using TextbookAxis = TextbookAxisT<double>;

/// The answer of the textbook test.
template <typename S>
struct TextbookResultT
{
    bool overlap = false; ///< every axis overlaps: the shapes intersect (touching counts)
    /// overlap: the smallest overlap over the axes, the length of the minimum translation vector (MTV).
    S depth{};
    /// separated: the gap on the separating axis found (a lower bound of the distance).
    S gap{};
    /// Unit, world space, from A to B: the MTV's direction (moving B by depth * normal separates the shapes), or
    /// the separating axis oriented from A's interval to B's.
    Vec2T<S> normal{};
    int axis = -1;      ///< index of the deciding axis in the test order (the trace's axes)
    int axesTested = 0; ///< axes tested before the test ended
    int axisCount = 0;  ///< distinct axes the test would test in all
};

/// Double-precision textbook result.
using TextbookResult = TextbookResultT<double>;

/// Step trace of the textbook test: the distinct axes in test order with their intervals, and the answer.
template <typename S>
struct TextbookTraceT
{
    std::vector<TextbookAxisT<S>> axes; ///< the axes tested, in order
    TextbookResultT<S> result{};        ///< the answer
    /// Empties the trace for reuse.
    void Clear() { *this = TextbookTraceT<S>(); }
};

/// Double-precision textbook trace.
using TextbookTrace = TextbookTraceT<double>;

/// The separating axis test as Ericson (Real-Time Collision Detection, 5.2.1 and 5.4) and the classic tutorials
/// teach it. The axes are the face normals of both polygons, a face parallel or anti-parallel to an axis already
/// listed merged into it; for a polygon and a circle also the axis from the polygon's vertex nearest the centre to
/// the centre; for two circles the line of centres. On each axis both shapes are projected; disjoint intervals
/// prove a separating axis and the test stops; otherwise the smaller of the two ways to push the intervals apart
/// is the axis's overlap, and the smallest overlap over all axes is the minimum translation vector.
/// Same verdict as Overlap, same depth and normal as Collide up to rounding (and, where two axes tie, the choice).
/// Works in A's frame, as the fast queries do. Cost O((n + m)^2): every vertex is projected on every axis.
/// With a non-null `trace`, every axis is recorded; the result is bit-identical either way.
template <typename S>
TextbookResultT<S> TextbookCollide(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                                   const TransformT<S>& xfB, TextbookTraceT<S>* trace = nullptr);

/// One axis of the textbook swept test: the intervals at t = 0 and when they overlap during the motion.
template <typename S>
struct TextbookSweepAxisT
{
    AxisRef faces[kMaxFacesPerAxis]{}; ///< as TextbookAxisT::faces
    int faceCount = 0;                 ///< number of entries in faces
    Vec2T<S> direction{};              ///< unit axis, world space, as TextbookAxisT::direction
    S minA{}, maxA{};                  ///< A's interval at t = 0
    S minB{}, maxB{};                  ///< B's interval at t = 0
    /// Speed of B's interval relative to A's along `direction`, per unit of t (0 within the rounding of the
    /// motion: a few machine epsilons of the speed).
    S rate{};
    /// The intervals overlap (with positive length) for t in (entry, exit); -infinity and +infinity when they
    /// always do. Both are NaN when they never do (rate 0 and disjoint or only touching).
    S entry{}, exit{};
    bool never = false;    ///< the intervals never overlap: the shapes cannot meet
    int latestEntry = -1;  ///< index of the axis with the latest entry so far, this one included
    int earliestExit = -1; ///< index of the axis with the earliest exit so far, this one included
    bool endsTest = false; ///< this axis proved a miss and ended the test
};

/// Double-precision textbook sweep axis.
using TextbookSweepAxis = TextbookSweepAxisT<double>;

/// The answer of the textbook swept test.
template <typename S>
struct TextbookSweepResultT
{
    SweepStatus status = SweepStatus::Miss; ///< miss, hit, or already interpenetrating at t = 0
    S toi{};                                ///< Hit: the time of impact in [0, 1], the latest entry
    Vec2T<S> normal{};                      ///< Hit: unit normal from A to B at first contact
    int axis = -1;    ///< Hit: index of the axis with the latest entry; a miss: the axis that proved it
    AxisRef corner{}; ///< circle pairs hit on a rounded corner: the vertex axis of the corner (else kind None)
};

/// Double-precision textbook sweep result.
using TextbookSweepResult = TextbookSweepResultT<double>;

/// Step trace of the textbook swept test.
template <typename S>
struct TextbookSweepTraceT
{
    std::vector<TextbookSweepAxisT<S>> axes; ///< the axes tested, in order
    SweepExit exit = SweepExit::None;        ///< why the test ended
    TextbookSweepResultT<S> result{};        ///< the answer
    /// Empties the trace for reuse.
    void Clear() { *this = TextbookSweepTraceT<S>(); }
};

/// Double-precision textbook sweep trace.
using TextbookSweepTrace = TextbookSweepTraceT<double>;

/// The swept test by intervals (Ericson 5.5.8, moving intervals on each axis): A moves by vA and B by vB over the
/// step, t from 0 to 1. On each distinct axis B's interval slides at a constant rate relative to A's, so the two
/// overlap during one span of time (entry, exit). The shapes interpenetrate when every axis overlaps at once: from
/// the latest entry to the earliest exit. A hit is a latest entry within the step and before the earliest exit;
/// an axis whose intervals never overlap, a latest entry after the step or not before the earliest exit is a miss.
/// Touching at one instant and sliding along a face at zero distance are misses, as in Sweep.
/// Polygon pairs: the same status and time as Sweep up to rounding. Circle pairs: a circle's own axis (vertex to
/// centre, or the line of centres) turns as it moves, so fixed axes cannot find the time of a corner hit; the
/// fixed axes (the polygon's faces) are tested by intervals, and when none proves a miss the centre's path is
/// cast against the rounded outline, exactly as Sweep does. No relative motion: the static test decides.
/// With a non-null `trace`, every axis is recorded; the result is bit-identical either way.
template <typename S>
TextbookSweepResultT<S> TextbookSweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                                      const TransformT<S>& xfB, Vec2T<S> vB, TextbookSweepTraceT<S>* trace = nullptr);

} // namespace satviz
