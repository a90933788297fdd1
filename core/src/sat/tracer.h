// SPDX-License-Identifier: MIT
// satviz (private): the tracer policies of the SAT templates. NullTracer is the fast path and records nothing;
// TraceRecorder fills a TraceT, SweepRecorder a SweepTraceT. The algorithm calls a tracer only inside
// `if constexpr (Tracer::kEnabled)`, so everything the trace needs beyond the result (world axes, full projection
// intervals) is computed only when recording, and the arithmetic that produces the result is the same in both
// instantiations. A face loop in lanes hands the recorder its lanes where it decides on them (FaceLanes, Block), so
// the trace holds the numbers the loop decided from.
#pragma once

#include "sweep_axis.h"

#include <satviz/polygon.h>
#include <satviz/shape.h>
#include <satviz/sweep.h>
#include <satviz/trace.h>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace satviz::detail
{

/// A non-owning view of a polygon or a circle.
template <typename S>
struct ShapeRef
{
    const PolygonT<S>* polygon = nullptr; ///< the polygon, or null
    const CircleT<S>* circle = nullptr;   ///< the circle, or null
};

/// The tracer that records nothing.
/// The algorithm's choices, fixed at compile time: a tracer type inherits them, and the benchmark's variants
/// override one to measure what it buys. Queries always use these defaults.
struct AlgorithmChoices
{
    /// Stop at the first separating axis; without it every face is tested and Collide's face queries report the
    /// largest separation (speculative contacts need it; the benchmark measures what stopping saves).
    static constexpr bool kEarlyExit = true;
    static constexpr bool kSkipParallel = true; ///< skip faces of B anti-parallel to a face of A
    /// Walked faces whose separation a single point of the other polygon (the witness) bounds too low to matter
    /// are not walked to: large polygons then walk only the faces near the contact.
    static constexpr bool kPruneWalked = true;
    static constexpr int kScanLimit = 16;   ///< polygons up to this many vertices are scanned, larger walked
    static constexpr bool kWide = false;    ///< scans with 256-bit vectors (AVX2; see HasWideVectors)
    static constexpr bool kWide512 = false; ///< and, where a query takes them, 512-bit ones (see HasWide512)
};

struct NullTracer : AlgorithmChoices
{
    static constexpr bool kEnabled = false;
};

/// The null tracer of code compiled for AVX2 (RunWide): scans and the sweep's face loops use 256-bit vectors.
struct WideNullTracer : NullTracer
{
    static constexpr bool kWide = true;
};

/// The null tracer of code compiled for AVX-512 (RunWide512): the face loops that take them (Collide's, and the
/// sweep's of small polygons) use 512-bit vectors, the rest 256-bit ones.
struct Wide512NullTracer : WideNullTracer
{
    static constexpr bool kWide512 = true;
};

/// Projection interval of a shape on a world direction.
template <typename S>
void ProjectShape(ShapeRef<S> shape, const TransformT<S>& xf, Vec2T<S> direction, S& lo, S& hi)
{
    if (shape.circle != nullptr)
    {
        const S center = Dot(direction, TransformPoint(xf, shape.circle->center));
        lo = center - shape.circle->radius;
        hi = center + shape.circle->radius;
        return;
    }
    // Locals, not the out-parameters: through references that may alias the transform, each vertex would store
    // and reload both ends and the transform.
    const TransformT<S> frame = xf;
    S low = std::numeric_limits<S>::infinity();
    S high = -std::numeric_limits<S>::infinity();
    for (const Vec2T<S>& v : shape.polygon->Vertices())
    {
        const S d = Dot(direction, TransformPoint(frame, v));
        low = std::min(low, d);
        high = std::max(high, d);
    }
    lo = low;
    hi = high;
}

/// The tracer that records every step into a TraceT.
template <typename S>
class TraceRecorder : public AlgorithmChoices
{
  public:
    static constexpr bool kEnabled = true;

    TraceRecorder(TraceT<S>& trace, ShapeRef<S> a, const TransformT<S>& xfA, ShapeRef<S> b, const TransformT<S>& xfB)
        : m_trace(trace), m_a(a), m_b(b), m_xfA(xfA), m_xfB(xfB)
    {
        m_trace.Clear();
    }

    /// The world transform of shape `side` (0 = A, 1 = B).
    const TransformT<S>& Frame(int side) const { return side == 0 ? m_xfA : m_xfB; }

    /// A face of polygon `side` was tested. `normal` is in that polygon's frame (unit or not); `separation` is
    /// the algorithm's value on that normal; `support` is the other shape's support vertex (-1 for a circle).
    void FaceAxis(int side, int face, Vec2T<S> normal, S separation, int support, bool separating)
    {
        AxisTestT<S> test;
        test.axis = {AxisKind::FaceNormal, side, face};
        test.direction = Normalize(Rotate(Frame(side).q, normal));
        test.separation = separation / Length(normal);
        test.supportA = side == 0 ? face : support;
        test.supportB = side == 0 ? support : face;
        test.separating = separating;
        Push(test);
    }

    /// Faces i0 .. i0 + count - 1 of polygon `side` as a face loop holds them in lanes, lane l face i0 + l: their
    /// normals (nx, ny; in that polygon's frame, unit or not) and separations, recorded as FaceAxis records one. The
    /// faces in the bits of `skipped` (bit l: lane l) were skipped (SkippedFace); `inc`, the other polygon mapped
    /// into this one's frame, gives the support point shown for each face.
    template <typename L, typename Inc>
    void FaceLanes(int side, int i0, int count, const L& nx, const L& ny, const L& separations, uint64_t skipped,
                   const Inc& inc)
    {
        // The lanes stored once, rather than a lane at a time.
        alignas(64) S x[L::kCount];
        alignas(64) S y[L::kCount];
        alignas(64) S values[L::kCount];
        nx.Store(x);
        ny.Store(y);
        separations.Store(values);
        for (int l = 0; l < count; ++l)
        {
            if ((skipped >> l) & 1u)
            {
                SkippedFace(i0 + l, -1);
                continue;
            }
            const Vec2T<S> normal{x[l], y[l]};
            FaceAxis(side, i0 + l, normal, values[l], inc.Support(normal), values[l] > S(0));
        }
    }

    /// A face was pruned: the separation `bound` of one point of the other polygon showed it could neither
    /// separate nor beat the best face so far. The separation shown is computed here, for the view only;
    /// `support` is the other polygon's support vertex for the face.
    void PrunedFace(int side, int face, Vec2T<S> normal, S bound, int support)
    {
        const TransformT<S>& own = Frame(side);
        const TransformT<S>& other = Frame(1 - side);
        const PolygonT<S>& ref = side == 0 ? *m_a.polygon : *m_b.polygon;
        const PolygonT<S>& inc = side == 0 ? *m_b.polygon : *m_a.polygon;
        const Vec2T<S> worldNormal = Rotate(own.q, normal);
        const S separation = Dot(worldNormal, TransformPoint(other, inc.Vertices()[support]) -
                                                  TransformPoint(own, ref.Vertices()[face]));
        FaceAxis(side, face, normal, separation, support, false);
        m_trace.axes.back().pruned = true;
        m_trace.axes.back().bound = bound / Length(normal);
    }

    /// A face of B was skipped: it is anti-parallel to face `duplicateFace` of A, already tested (-1: the face of
    /// A whose normal is most anti-parallel).
    void SkippedFace(int face, int duplicateFace)
    {
        AxisTestT<S> test;
        test.axis = {AxisKind::FaceNormal, 1, face};
        test.direction = Rotate(m_xfB.q, m_b.polygon->Normal(face));
        test.skipped = true;
        S lowest = std::numeric_limits<S>::infinity();
        for (size_t i = 0; i < m_trace.axes.size(); ++i)
        {
            const AxisTestT<S>& tested = m_trace.axes[i];
            if (tested.axis.kind != AxisKind::FaceNormal || tested.axis.shape != 0)
            {
                continue;
            }
            const S alignment = Dot(tested.direction, test.direction);
            if (tested.axis.index == duplicateFace || (duplicateFace < 0 && alignment < lowest))
            {
                lowest = alignment;
                test.duplicateOf = static_cast<int>(i);
                test.separation = tested.separation;
                test.supportA = tested.supportA;
                test.supportB = tested.supportB;
            }
        }
        Push(test);
    }

    /// The axis from vertex `vertex` of polygon `side` to the circle's centre, `direction` in world space.
    void VertexAxis(int side, int vertex, Vec2T<S> direction, S separation, bool separating)
    {
        AxisTestT<S> test;
        test.axis = {AxisKind::VertexToCenter, side, vertex};
        test.direction = direction;
        test.separation = separation;
        test.supportA = side == 0 ? vertex : -1;
        test.supportB = side == 0 ? -1 : vertex;
        test.separating = separating;
        Push(test);
    }

    /// The axis between two circles' centres, `direction` in world space from A to B.
    void CenterAxis(Vec2T<S> direction, S separation, bool separating)
    {
        AxisTestT<S> test;
        test.axis = {AxisKind::CenterToCenter, -1, -1};
        test.direction = direction;
        test.separation = separation;
        test.separating = separating;
        Push(test);
    }

    /// Vertex `vertex` of polygon `side` lies inside the other polygon (Overlap's shortcut).
    void ContainedVertex(int side, int vertex)
    {
        m_trace.containedShape = side;
        m_trace.containedVertex = vertex;
    }

    /// The contact clipping, already in world space.
    void Clip(const ClipTraceT<S>& clip)
    {
        m_trace.hasClip = true;
        m_trace.clip = clip;
    }

    /// The query ended.
    void Finish(TraceExit exit, const ManifoldT<S>& result)
    {
        m_trace.exit = exit;
        m_trace.result = result;
    }

  private:
    void Push(AxisTestT<S>& test)
    {
        ProjectShape(m_a, m_xfA, test.direction, test.minA, test.maxA);
        ProjectShape(m_b, m_xfB, test.direction, test.minB, test.maxB);
        const int index = static_cast<int>(m_trace.axes.size());
        test.best = index;
        if (index > 0)
        {
            const int previous = m_trace.axes.back().best;
            if (test.skipped || m_trace.axes[previous].separation >= test.separation)
            {
                test.best = previous;
            }
        }
        m_trace.axes.push_back(test);
    }

    TraceT<S>& m_trace;
    ShapeRef<S> m_a;
    ShapeRef<S> m_b;
    TransformT<S> m_xfA;
    TransformT<S> m_xfB;
};


// Records the axes of a sweep. Everything here is for the trace only.
template <typename S>
class SweepRecorder
{
  public:
    static constexpr bool kEnabled = true;
    static constexpr bool kWide = false;
    static constexpr bool kWide512 = false;

    SweepRecorder(SweepTraceT<S>& trace, ShapeRef<S> a, const TransformT<S>& xfA, ShapeRef<S> b,
                  const TransformT<S>& xfB, Vec2T<S> relativeVelocity)
        : m_trace(trace), m_a(a), m_b(b), m_xfA(xfA), m_xfB(xfB), m_velocity(relativeVelocity)
    {
        m_trace.Clear();
    }

    // A face axis of a polygon sweep, with the algorithm's own numbers.
    void Axis(int side, int face, S separation, S rate, S entry, S exit, bool endsTest)
    {
        const Vec2T<S> direction =
            side == 0 ? Rotate(m_xfA.q, m_a.polygon->Normal(face)) : -Rotate(m_xfB.q, m_b.polygon->Normal(face));
        AxisWorld({AxisKind::FaceNormal, side, face}, direction, separation, rate, entry, exit, endsTest);
    }

    // An axis given in world space, oriented from A towards B.
    void AxisWorld(AxisRef ref, Vec2T<S> direction, S separation, S rate, S entry, S exit, bool endsTest)
    {
        SweepAxisT<S> axis;
        axis.axis = ref;
        axis.direction = direction;
        ProjectShape(m_a, m_xfA, axis.direction, axis.minA, axis.maxA);
        ProjectShape(m_b, m_xfB, axis.direction, axis.minB, axis.maxB);
        const S shift = Dot(axis.direction, m_velocity);
        axis.sweptMinB = axis.minB + std::min(S(0), shift);
        axis.sweptMaxB = axis.maxB + std::max(S(0), shift);
        axis.separation = separation;
        axis.rate = rate;
        axis.entry = entry;
        axis.exit = exit;
        axis.endsTest = endsTest;
        m_trace.axes.push_back(axis);
    }

    // An axis computed here from the shapes at t = 0: the projection gap and how it changes.
    void AxisFromShapes(AxisRef ref, Vec2T<S> direction)
    {
        S minA, maxA, minB, maxB;
        ProjectShape(m_a, m_xfA, direction, minA, maxA);
        ProjectShape(m_b, m_xfB, direction, minB, maxB);
        const S separation = minB - maxA;
        const S rate = Dot(direction, m_velocity);
        S entry, exit;
        const bool closes = AxisTimes(separation, rate, entry, exit);
        AxisWorld(ref, direction, separation, rate, entry, exit, !closes);
    }

    // A face of a large polygon's face loop taken for its exact separation (WalkedEvaluation): its step now, its
    // rate, entry and exit when the lanes take it in (Flushed). `exitPass`: the second pass of a walked loop.
    void Taken(int side, int face, S separation, bool exitPass)
    {
        m_pending[m_pendingCount++] = static_cast<int>(m_trace.axes.size());
        Axis(side, face, separation, S(0), S(0), kInfinity<S>, false);
        m_trace.axes.back().exitPass = exitPass;
    }

    // The lanes took the pending faces in, in order: lane l holds the l-th face taken since the last call, with its
    // rate, entry (-infinity: none) and exit as the lanes computed them, and `ends` the lanes whose axis ended the
    // test. Returns the lane of the first such face (it ended the test), or -1.
    template <typename L, typename Axes, typename Mask>
    int Flushed(const L& rates, const Axes& axes, const Mask& ends)
    {
        int ended = -1;
        for (int l = 0; l < m_pendingCount; ++l)
        {
            SweepAxisT<S>& axis = m_trace.axes[static_cast<size_t>(m_pending[l])];
            axis.rate = rates.Get(l);
            Times(axes, l, axis.entry, axis.exit);
            axis.endsTest = ended < 0 && ends.Get(l);
            ended = axis.endsTest ? l : ended;
        }
        m_pendingCount = 0;
        return ended;
    }

    // Faces i0 .. i0 + count - 1 of polygon `side` as a face loop that scans the other polygon holds them in lanes
    // (lane l: face i0 + l), with their separations, rates, entries (-infinity: none) and exits, and `ends` the lanes
    // whose axis ends the test (SweepLanes::Add). Records the faces up to the first that ends the test, and returns
    // its lane, or -1.
    template <typename L, typename Axes, typename Mask>
    int Block(int side, int i0, int count, const L& separations, const L& rates, const Axes& axes, const Mask& ends)
    {
        for (int l = 0; l < count; ++l)
        {
            S entry;
            S exit;
            Times(axes, l, entry, exit);
            const bool endsTest = ends.Get(l);
            Axis(side, i0 + l, separations.Get(l), rates.Get(l), entry, exit, endsTest);
            if (endsTest)
            {
                return l;
            }
        }
        return -1;
    }

    // A face of a walked loop decided by the bound of a point of the other polygon, not walked to (see
    // SweepAxisT::bounded); its separation, rate, entry and exit are for the view only.
    void Bounded(int side, int face, S separation, S rate, S entry, S exit, S bound, S boundTime, S known,
                 bool exitPass)
    {
        Axis(side, face, separation, rate, entry, exit, false);
        SweepAxisT<S>& axis = m_trace.axes.back();
        axis.bounded = true;
        axis.bound = bound;
        axis.boundTime = boundTime;
        axis.knownEntry = known;
        axis.exitPass = exitPass;
    }

    // A face of a bisected loop that the bisection ruled out, never evaluated (see SweepAxisT::skipped); its
    // separation, rate, entry and exit are for the view only.
    void Skipped(int side, int face, S separation, S rate, S entry, S exit)
    {
        Axis(side, face, separation, rate, entry, exit, false);
        m_trace.axes.back().skipped = true;
    }

    // The test ended after a pass over a polygon's faces, on the latest entry against the earliest exit: the last
    // face evaluated shows it.
    void EndedAfterPass()
    {
        for (size_t k = m_trace.axes.size(); k-- > 0;)
        {
            SweepAxisT<S>& axis = m_trace.axes[k];
            if (!axis.bounded && !axis.skipped)
            {
                axis.endsTest = true;
                return;
            }
        }
    }

    // The test ended: why, and per step the axis of the latest entry and of the earliest exit so far, as the face
    // loops keep them (SweepLanes::Add): the first face of the latest entry, where only an axis apart at t = 0
    // (separation >= 0) has an entry and an overlapping one holds the latest entry only until an axis with an entry
    // comes. Flagged faces were not evaluated and change neither.
    void Finish(SweepExit exit)
    {
        m_trace.exit = exit;
        int latest = -1;
        int earliest = -1;
        for (size_t k = 0; k < m_trace.axes.size(); ++k)
        {
            SweepAxisT<S>& axis = m_trace.axes[k];
            if (!axis.bounded && !axis.skipped)
            {
                const int index = static_cast<int>(k);
                if (latest < 0)
                {
                    latest = index;
                    earliest = index;
                }
                else
                {
                    const SweepAxisT<S>& held = m_trace.axes[static_cast<size_t>(latest)];
                    const bool heldEnters = held.separation >= S(0);
                    if (!((heldEnters && held.entry >= axis.entry) || (!heldEnters && !(axis.separation >= S(0)))))
                    {
                        latest = index;
                    }
                    if (!(m_trace.axes[static_cast<size_t>(earliest)].exit <= axis.exit))
                    {
                        earliest = index;
                    }
                }
            }
            axis.latestEntry = latest;
            axis.earliestExit = earliest;
        }
    }

  private:
    // The entry and exit the trace shows for lane l of `axes`: an overlapping axis (no entry) enters at 0, as its
    // interval overlaps from t = 0; one that never closes has neither.
    template <typename Axes>
    static void Times(const Axes& axes, int l, S& entry, S& exit)
    {
        const bool never = axes.never.Get(l);
        entry = never ? S(0) : std::max(axes.entry.Get(l), S(0));
        exit = never ? kInfinity<S> : axes.leave.Get(l);
    }

    SweepTraceT<S>& m_trace;
    ShapeRef<S> m_a;
    ShapeRef<S> m_b;
    TransformT<S> m_xfA;
    TransformT<S> m_xfB;
    Vec2T<S> m_velocity;
    int m_pending[4] = {}; // the steps of the faces taken and not yet in the lanes
    int m_pendingCount = 0;
};

} // namespace satviz::detail
