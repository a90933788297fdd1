// SPDX-License-Identifier: MIT
// satviz (private): the tracer policies of the SAT templates. NullTracer is the fast path and records nothing;
// TraceRecorder fills a TraceT. The algorithm calls a tracer only inside `if constexpr (Tracer::kEnabled)`, so
// everything the trace needs beyond the result (world axes, full projection intervals) is computed only when
// recording, and the arithmetic that produces the result is the same in both instantiations.
#pragma once

#include <satviz/polygon.h>
#include <satviz/shape.h>
#include <satviz/trace.h>

#include <algorithm>
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

/// The null tracer of code compiled for AVX2 (RunWide): scans use 256-bit vectors.
struct WideNullTracer : NullTracer
{
    static constexpr bool kWide = true;
};

/// The null tracer of code compiled for AVX-512 (RunWide512): the face loops that take them use 512-bit vectors,
/// the rest 256-bit ones.
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
    lo = std::numeric_limits<S>::infinity();
    hi = -std::numeric_limits<S>::infinity();
    for (const Vec2T<S>& v : shape.polygon->Vertices())
    {
        const S d = Dot(direction, TransformPoint(xf, v));
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
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

} // namespace satviz::detail
