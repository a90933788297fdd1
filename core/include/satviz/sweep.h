// SPDX-License-Identifier: MIT
// satviz: the swept test: when two translating shapes first touch during a step, at any speed.
#pragma once

#include <satviz/manifold.h>
#include <satviz/shape.h>
#include <satviz/trace.h>

#include <vector>

namespace satviz
{

/// The outcome of a sweep.
enum class SweepStatus
{
    Miss,        ///< the shapes do not interpenetrate during the step (grazing and sliding contact included)
    Hit,         ///< the shapes first touch at time toi in [0, 1] and interpenetrate right after
    Overlapping, ///< the shapes already interpenetrate at t = 0 (depth > 0): see `initial` for the MTV
};

/// One axis of a swept polygon test, as recorded in a SweepTraceT. World space; times in units of the step.
template <typename S>
struct SweepAxisT
{
    AxisRef axis{};        ///< where the axis comes from: a face normal, a vertex axis or the line of centres
    Vec2T<S> direction{};  ///< unit axis, world space, oriented from A towards B (an axis of B: B's normal negated)
    S minA{}, maxA{};      ///< A's projection interval on the axis at t = 0
    S minB{}, maxB{};      ///< B's projection interval at t = 0
    S sweptMinB{};         ///< B's interval swept over the step, relative to A: [sweptMinB, sweptMaxB]
    S sweptMaxB{};         ///< (the union of B's interval at t = 0 and at t = 1, moved by the relative velocity)
    S separation{};        ///< the gap (> 0) or minus the overlap on this axis at t = 0
    S rate{};              ///< change of the separation per unit of t (< 0: closing)
    S entry{};             ///< time the intervals start to overlap (0 if they already do)
    S exit{};              ///< time they stop overlapping (infinity if never)
    int latestEntry = -1;  ///< index of the axis with the latest entry so far, this one included (-1: none yet)
    int earliestExit = -1; ///< index of the axis with the earliest exit so far (-1: none yet)
    bool endsTest = false; ///< this axis ended the test: it never closes, or it proved a miss
    /// Against a polygon above 16 vertices the sweep decides some faces without evaluating them: such a face is a
    /// step of its own, flagged `bounded` or `skipped`, and its separation, rate, entry, exit and intervals are
    /// computed for the view only. A flagged face changes neither latestEntry nor earliestExit, and never ends
    /// the test.
    /// The face was not walked to: a point of the other polygon (its support point for a face walked to before)
    /// lies `bound` beyond the face (behind it when negative), so the separation is at most `bound`. In the first
    /// pass this showed that the intervals overlap at t = 0 (bound < 0: no entry; the exit waits for the second
    /// pass), or that the face approaches and its entry is at most `boundTime`, before `knownEntry`: it cannot be
    /// the latest entry. In the second pass (`exitPass`) it showed that the face recedes and its exit is at least
    /// `boundTime`, after the latest entry `knownEntry`: it cannot part the intervals before they all overlap.
    bool bounded = false;
    S bound{};      ///< with bounded: the bound of the separation, the point's distance beyond the face
    S boundTime{};  ///< with bounded: the entry bound bound / -rate (0 when bound < 0) or the exit bound -bound / rate
    S knownEntry{}; ///< with bounded: the latest entry known then (a lower bound of it; second pass: the latest)
    /// Recorded by the second pass over the faces of a polygon against one above 16 vertices, which takes in the
    /// exits that can come before the latest entry, once that entry is known.
    bool exitPass = false;
    /// The face was not evaluated (a polygon above 256 faces): bisection found the faces beside the places where
    /// the line of the motion enters and leaves the Minkowski difference; the entries of the faces facing the
    /// motion rise up to the first place and fall after it, the exits of those facing away fall to the second and
    /// rise after it, so no other face holds the latest entry or the earliest exit.
    bool skipped = false;
};

/// Why a sweep ended.
enum class SweepExit
{
    None,           ///< nothing recorded
    NotMoving,      ///< no relative motion: the static test decided
    NeverCloses,    ///< an axis separates (or only touches) and does not close: no hit at any time
    EntryAfterStep, ///< the latest entry is after t = 1
    EntryAfterExit, ///< the latest entry is not before the earliest exit: the intervals never overlap together
    AllAxesOverlap, ///< every axis overlaps in a common time span: a hit (or overlapping at t = 0)
    /// Circle pairs: decided by casting the centre's path against the rounded outline of the other shape (its
    /// faces pushed out by the radius, and arcs around its vertices). The face axes recorded show the intervals;
    /// their entry can be earlier than the hit, which a rounded corner delays.
    RoundedOutline,
};

/// Step trace of a sweep: the axes in test order with their intervals and times, and why it ended.
template <typename S>
struct SweepTraceT
{
    std::vector<SweepAxisT<S>> axes;  ///< axes in test order
    SweepExit exit = SweepExit::None; ///< why the test ended
    /// The instructions the same sweep runs on, untraced, on this processor (see TraceT::untracedPath): the trace
    /// shows the baseline loops, whose numbers are those of every path, to the bit.
    InstructionPath untracedPath = InstructionPath::Baseline;
    /// Empties the trace for reuse.
    void Clear() { *this = SweepTraceT<S>(); }
};

/// Double-precision sweep trace.
using SweepTrace = SweepTraceT<double>;
/// Double-precision sweep axis.
using SweepAxis = SweepAxisT<double>;

/// The result of Sweep.
template <typename S>
struct SweepResultT
{
    SweepStatus status = SweepStatus::Miss; ///< miss, hit, or overlapping at the start
    S toi{};                                ///< time of impact in [0, 1] (Hit), 0 (Overlapping)
    /// Hit: unit contact normal from A to B at the time of impact. Overlapping: the MTV direction.
    Vec2T<S> normal{};
    /// Hit: the contact points at the time of impact (world, shapes moved; separation 0): where the incident
    /// polygon touches the reference face, a vertex or the part of an edge along the face over the face's extent.
    ContactPointT<S> contacts[2]{};
    int contactCount = 0; ///< number of contact points
    AxisRef axis{};       ///< the deciding axis: for a hit, the axis with the latest entry
    /// Overlapping: the static manifold at t = 0 (depth and MTV; from Sweep also its contact points, from SweepTime
    /// none: contactCount 0 and incidentEdge -1)
    ManifoldT<S> initial{};
};

/// Double-precision sweep result.
using SweepResult = SweepResultT<double>;

/// Swept test for shapes translating over one step: A moves by vA and B by vB (displacements per step, world
/// space); t runs from 0 to 1. Exact for translation, at any speed: there is no sampling and no tolerance, so a
/// shape 1e6 times faster than its size still hits a thin wall. Rotation during the step is not modelled: the
/// shapes keep their orientation from xfA and xfB (a rotating shape can be swept with its bounding circle).
///
/// A hit means the shapes interpenetrate right after first contact: touching at one instant (grazing a corner) or
/// sliding along a face at zero distance is a miss. Shapes that interpenetrate at t = 0 are reported as
/// Overlapping, with the static manifold. Without relative motion, the static test decides.
/// Cost: polygons of up to 16 vertices are scanned whole; against a larger one each face's separation is bounded by
/// one point of it and only the faces that can decide are walked to; the faces of a polygon above 256 faces are not
/// visited one by one: only those beside the places where the line of the motion enters and leaves the Minkowski
/// difference (found by bisection) are evaluated, O(log n log m) for n faces against m vertices
/// (plus one step per face parallel to the motion).
/// With a non-null `trace`, every axis is recorded in the order the test takes it (circle pairs: the polygon's faces
/// or the line of centres, then the vertex axis of a hit on a rounded corner); against a polygon above 16 vertices
/// the faces decided without evaluation are recorded too, flagged (SweepAxisT::bounded, SweepAxisT::skipped). The
/// result is bit-identical either way.
template <typename S>
SweepResultT<S> Sweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                      const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace = nullptr);

/// Sweep without the contact points: the same status, time of impact, normal and axis, bit for bit, and a hit
/// with no contacts (contactCount 0). For callers that need when and along which normal, not where: continuous
/// collision that runs Collide at the time of impact anyway, and MoveAndSlide. Skips the contact points at the
/// time of impact, a clipping of the incident edge at the moved pose. Shapes overlapping at t = 0 carry the static
/// manifold's depth, normal and axis, the same bits as Sweep's, but not its contact points (Sweep has them), which
/// saves clipping the incident edge.
/// With a non-null `trace`, the same trace as Sweep's.
template <typename S>
SweepResultT<S> SweepTime(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                          const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace = nullptr);

} // namespace satviz
