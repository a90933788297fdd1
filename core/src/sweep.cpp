// SPDX-License-Identifier: MIT
// satviz: the swept test for translating shapes (Ericson, Real-Time Collision Detection, 5.5.2 for polygons;
// 5.3.2 and 5.5.7 for the ray against a sphere and the rounded shapes of circles).

#include "sat/clip.h"
#include "sat/collide512.h"
#include "sat/cpu_dispatch.h"
#include "sat/face_blocks.h"
#include "sat/incident_polygon.h"
#include "sat/lanes.h"
#include "sat/select.h"
#include "sat/support.h"
#include "sat/tracer.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace satviz
{
namespace detail
{
namespace
{

template <typename S>
constexpr S kInfinity = std::numeric_limits<S>::infinity();

struct NullSweepTracer
{
    static constexpr bool kEnabled = false;
    static constexpr bool kWide = false;
    static constexpr bool kWide512 = false; // the face loops of small polygons on 512-bit vectors (SmallSweep512)
};

// The null tracer of the sweep compiled for AVX2.
struct WideNullSweepTracer : NullSweepTracer
{
    static constexpr bool kWide = true;
};

// The null tracer of the sweep compiled for AVX-512.
struct Wide512NullSweepTracer : WideNullSweepTracer
{
    static constexpr bool kWide512 = true;
};

// Entry and exit times of one axis whose separation is `separation` at t = 0 and changes by `rate` per unit of
// t; false when the axis never closes (it separates or only touches, and does not approach).
template <typename S>
bool AxisTimes(S separation, S rate, S& entry, S& exit)
{
    entry = S(0);
    exit = kInfinity<S>;
    if (separation >= S(0))
    {
        if (rate >= S(0))
        {
            return false;
        }
        entry = separation / -rate;
    }
    else if (rate > S(0))
    {
        exit = -separation / rate;
    }
    return true;
}

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
            const bool never = axes.never.Get(l);
            // As Replay: an overlapping axis (no entry) enters at 0, as its interval overlaps from t = 0.
            axis.rate = rates.Get(l);
            axis.entry = never ? S(0) : std::max(axes.entry.Get(l), S(0));
            axis.exit = never ? kInfinity<S> : axes.leave.Get(l);
            axis.endsTest = ended < 0 && ends.Get(l);
            ended = axis.endsTest ? l : ended;
        }
        m_pendingCount = 0;
        return ended;
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
    SweepTraceT<S>& m_trace;
    ShapeRef<S> m_a;
    ShapeRef<S> m_b;
    TransformT<S> m_xfA;
    TransformT<S> m_xfB;
    Vec2T<S> m_velocity;
    int m_pending[4] = {}; // the steps of the faces taken and not yet in the lanes
    int m_pendingCount = 0;
};

template <typename S>
TransformT<S> Moved(const TransformT<S>& xf, Vec2T<S> velocity, S t)
{
    return {xf.p + t * velocity, xf.q};
}

// The static verdict when nothing moves, or the shapes interpenetrate at t = 0, written into a fresh `result`.
// Without kContacts (SweepTime) the static manifold carries no contact points and no incident edge.
template <bool kContacts, typename S>
void SetInitial(const ManifoldT<S>& manifold, SweepResultT<S>& result)
{
    if (manifold.overlap && manifold.depth > S(0))
    {
        result.status = SweepStatus::Overlapping;
        result.normal = manifold.normal;
        result.axis = manifold.axis;
        result.initial = manifold;
        if constexpr (!kContacts)
        {
            result.initial.contacts[0] = {};
            result.initial.contacts[1] = {};
            result.initial.contactCount = 0;
            result.initial.incidentEdge = -1;
        }
    }
}

// SetInitial into a result of its own.
template <bool kContacts, typename S>
SweepResultT<S> Initial(const ManifoldT<S>& manifold)
{
    SweepResultT<S> result;
    SetInitial<kContacts>(manifold, result);
    return result;
}

// What the face loops of a polygon sweep carry from axis to axis.
template <typename S>
struct SweepState
{
    S first = -kInfinity<S>; // latest entry so far (none yet)
    S last = kInfinity<S>;   // earliest exit so far
    int firstSide = 0;       // the axis of the latest entry: its polygon
    int firstFace = 0;       // and its face
    bool inside = true;      // every separation so far is < 0
    SweepExit exit = SweepExit::AllAxesOverlap;
};

// A face's place in the order A's faces, then B's, as a lane value (exact in float up to 2^24).
constexpr int kSideShift = 16;
constexpr int kSideStride = 1 << kSideShift;

// The rate below which the motion counts as parallel to a face: a few roundings of Dot(n, v) with |n| = 1.
template <typename S>
S StillRate(Vec2T<S> velocity)
{
    return S(8) * std::numeric_limits<S>::epsilon() * std::max(std::abs(velocity.x), std::abs(velocity.y));
}

// The rates, with those within `still` of 0 set to 0 (StillRate).
template <typename L, typename S>
L Moving(const L& rate, S still)
{
    return Select(Max(rate, -rate) > L::Fill(still), rate, L::Fill(S(0)));
}

// Entry, exit and whether the axis never closes, for four axes at once (the per-axis rule of AxisTimes, without
// branches). A rate within `still` of 0 is 0: the motion runs along the face as far as its rounding can tell, so
// touching and sliding along a face is no hit. With q = s / -r: s >= 0 enters at q (r < 0) or never (r >= 0);
// s < 0 is overlapping from t = 0 (no entry: -infinity, so that a face touching at t = 0, whose entry is 0, is the
// latest entry rather than any overlapping face) and, when r > 0, exits at q.
template <typename L>
struct AxisLanes
{
    using S = std::decay_t<decltype(std::declval<L>().Get(0))>;
    L entry;
    L leave;
    typename L::Mask apart;
    typename L::Mask never;

    AxisLanes(const L& separation, const L& rawRate, S still)
    {
        const L zero = L::Fill(0);
        const L rate = Moving(rawRate, still);
        apart = separation >= zero;
        const L q = separation / -rate;
        const L infinity = L::Fill(std::numeric_limits<S>::infinity());
        entry = Select(apart, q, -infinity);
        leave = Select(~apart & (rate > zero), q, infinity);
        never = apart & (rate >= zero);
    }
};

// What the face loops carry from A's faces to B's, per lane: the latest entry (and its face) and the earliest exit
// each lane saw, and whether every separation was < 0. The lanes are combined once, after both polygons (Combine),
// so B's faces need not wait for A's to be combined.
template <typename L, typename S>
struct SweepLanes
{
    L first = L::Fill(-kInfinity<S>);              // latest entry so far (none yet)
    L firstIndex = L::Fill(S(0));                  // its face: side * kSideStride + face
    L last = L::Fill(kInfinity<S>);                // earliest exit so far
    typename L::Mask inside = L::Mask::Fill(true); // every separation so far is < 0

    // Takes in a block of four faces (face indices as lane values, side * kSideStride + face), in face order:
    // each lane keeps the latest entry it saw and the first face that has it, and the earliest exit. Returns the
    // lanes whose axis ends the test: it never closes, or the latest entry is after t = 1.
    typename L::Mask Add(const AxisLanes<L>& axes, const L& faces)
    {
        // A NaN separation does not count as apart, and a NaN entry does not replace the latest one.
        inside = inside & ~axes.apart;
        const typename L::Mask later = axes.entry > first;
        first = Select(later, axes.entry, first);
        firstIndex = Select(later, faces, firstIndex);
        last = Min(axes.leave, last);
        return axes.never | (first > L::Fill(S(1)));
    }

    // The latest entry, at the first face that has it, and the earliest exit.
    void Combine(SweepState<S>& state) const
    {
        state.first = first.MaxLane();
        const L candidates = Select(first == L::Fill(state.first), firstIndex, L::Fill(S(1 << 30)));
        const int index = static_cast<int>(candidates.MinLane());
        // The index is not negative: a shift and a mask, not a signed division.
        state.firstSide = index >> kSideShift;
        state.firstFace = index & (kSideStride - 1);
        state.last = last.MinLane();
        state.inside = inside.All();
    }
};

// The separations at t = 0 of the faces of a polygon of at most 8 faces, as its face loop computed them (the blocks
// of SmallRefSeparations), kept for a start where the shapes interpenetrate: the static manifold's reference face is
// the face of largest separation, as Collide finds it from the same numbers, so no face is tested twice.
template <typename L>
struct KeptSeparations
{
    L block0 = L::Fill(0); // faces 0 to 3
    L block1 = L::Fill(0); // faces 4 to 7, or 0 to 3 again
    bool kept = false;     // the face loop was that of a small polygon (else nothing is kept)
    bool twoBlocks = false;
};

// The recorder's face-by-face view of a block of faces i0 .. i0 + 3 (those below n), with the block's own numbers:
// the latest entry and earliest exit so far, and the first face that ends the test (then `viewEnded`).
template <typename L, typename S, typename Tracer>
void Replay(Tracer& tracer, SweepState<S>& view, bool& viewEnded, int side, int i0, int n, const L& separations,
            const L& rates, const AxisLanes<L>& axes)
{
    for (int l = 0; l < 4 && i0 + l < n && !viewEnded; ++l)
    {
        const S entry = axes.entry.Get(l);
        const S leave = axes.leave.Get(l);
        const bool never = axes.never.Get(l);
        if (entry > view.first)
        {
            view.first = entry;
            view.firstSide = side;
            view.firstFace = i0 + l;
        }
        view.last = std::min(view.last, leave);
        viewEnded = never || view.first > S(1) || view.first >= view.last;
        // The trace shows an overlapping axis (no entry) as entering at 0, as its interval overlaps from t = 0.
        tracer.Axis(side, i0 + l, separations.Get(l), rates.Get(l), never ? S(0) : std::max(entry, S(0)),
                    never ? kInfinity<S> : leave, viewEnded);
        if (viewEnded)
        {
            view.exit = never               ? SweepExit::NeverCloses
                        : view.first > S(1) ? SweepExit::EntryAfterStep
                                            : SweepExit::EntryAfterExit;
        }
    }
}

// The faces of `ref` (side 0 = A, 1 = B) against `inc` mapped into ref's frame; `velocity` is B's motion relative
// to A in ref's frame, times -1 when ref is B (it is then A that moves towards ref). False when an axis ends the
// test with a miss. N is inc's padded vertex count (inc scanned; a walked inc goes to SweepBoundedFaces, a ref above
// kBisectFaces faces to SweepBisectedFaces).
//   Per face: separation s at t = 0 (as in the static face query, but with unit normals) and its rate
//   r = Dot(n, velocity), then its entry and exit (AxisLanes). The faces are decided four at a time, in lanes:
//   each lane keeps the latest entry it saw (and its face) and the earliest exit, so there is no branch per face,
//   whose outcome follows the geometry and would be mispredicted. The last block repeats the last face, which
//   changes no bound. A block that holds an axis that never closes, or an entry after t = 1, ends the test; the
//   latest entry against the earliest exit is compared once per polygon. Both bounds only tighten from face to
//   face, so this ends with the same verdict as stopping at the first face that fails, and the lanes combine to
//   the first face of the latest entry, as a face-by-face loop finds it. The recorder has the faces in order up to
//   that first failing face, with the lanes' numbers.
template <int N, int kBlocks, typename L, typename S, typename Tracer>
bool SweepFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                SweepLanes<L, S>& lanes, SweepState<S>& view, Tracer& tracer, KeptSeparations<L>& kept)
{
    static_assert(N > 0, "a scanned inc");
    constexpr bool kSmall = kBlocks > 0;
    // A small ref has the separations of all its faces, and its blocks, from one pass over inc's vertices.
    const auto small = [&]() {
        if constexpr (kSmall)
        {
            return SmallRefSeparations<N, kBlocks, L, S>(ref, inc);
        }
        else
        {
            return 0;
        }
    }();
    if constexpr (kSmall)
    {
        kept = {small.block0, small.block1, true, kBlocks == 2};
    }
    const int n = ref.Count();
    // A small ref has exactly kBlocks blocks, so its loop unrolls.
    const int blocksEnd = kSmall ? 4 * kBlocks : n;
    typename L::Mask ends = L::Mask::Fill(false);
    bool viewEnded = view.exit != SweepExit::AllAxesOverlap;
    for (int i0 = 0; i0 < blocksEnd && !ends.Any(); i0 += 4)
    {
        // The block's normals and separations; the last block repeats the last face.
        L nx;
        L ny;
        L separations;
        if constexpr (kSmall)
        {
            const FaceBlock<L, S>& block = i0 == 0 ? small.faces0 : small.faces1;
            nx = block.nx;
            ny = block.ny;
            separations = i0 == 0 ? small.block0 : small.block1;
        }
        else
        {
            const FaceBlock<L, S> block(ref, ref.Vertices().data, i0);
            nx = block.nx;
            ny = block.ny;
            // The four faces side by side: each vertex of inc is projected on all four normals at once and the
            // minimum kept per lane, so no minimum is taken across lanes. The same products, sums and minimum as
            // FaceSeparation, so the same bits.
            const L offset = block.Offset();
            const L low = ProjectionMinimum<N>(inc, nx, ny);
            separations = (low - offset) + L::Fill(S(0));
        }
        const L rates = nx * L::Fill(velocity.x) + ny * L::Fill(velocity.y);
        const AxisLanes<L> axes(separations, rates, StillRate(velocity));
        // Lane l holds face i0 + l, past the last face too: a lane that repeats the last face ties with that face's
        // own lane, whose smaller index Combine takes.
        ends = lanes.Add(axes, L::Fill(S(side * kSideStride + i0)) + L::Set(S(0), S(1), S(2), S(3)));
        if constexpr (Tracer::kEnabled)
        {
            Replay(tracer, view, viewEnded, side, i0, n, separations, rates, axes);
        }
    }
    // A latest entry after t = 1 ended its own block (`ends`), so what is left to compare is the latest entry
    // against the earliest exit. Why the test ended is for the trace only, which the view has.
    return !ends.Any() && !(lanes.first.MaxLane() >= lanes.last.MinLane());
}

// For the trace only: face i of `ref` as the face loops would evaluate it, for a face they decided without
// evaluating it: its exact separation (inc's support point searched for alone), its rate, and its entry and exit as
// the lanes compute them (AxisLanes; the trace shows an overlapping axis as entering at 0, as Replay does).
template <typename S>
struct ViewedFace
{
    S separation;
    S rate;
    S entry;
    S exit;
};

template <typename L, typename S>
ViewedFace<S> ViewFace(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int i, Vec2T<S> velocity)
{
    const Vec2T<S> normal = ref.Normal(i);
    const S separation = inc.Separation(normal, ref.Vertices()[i], inc.Support(normal));
    const S rate = normal.x * velocity.x + normal.y * velocity.y;
    const AxisLanes<L> axes(L::Fill(separation), L::Fill(rate), StillRate(velocity));
    const bool never = axes.never.Get(0);
    return {separation, rate, never ? S(0) : std::max(axes.entry.Get(0), S(0)),
            never ? kInfinity<S> : axes.leave.Get(0)};
}

// The end of a pass over the faces of a polygon in a large polygon's face loop (walked or bisected): `going` is
// whether the test goes on. For the trace, the face-by-face view of a scanned polygon after it (Replay) goes on from
// the lanes' latest entry and earliest exit, and a pass that ended the test on the latest entry against the
// earliest exit (a face that ends it on its own said so as the lanes took it in) shows it on its last face
// evaluated.
template <typename L, typename S, typename Tracer>
bool EndPass(Tracer& tracer, SweepState<S>& view, const SweepLanes<L, S>& lanes, bool going)
{
    if constexpr (Tracer::kEnabled)
    {
        SweepState<S> state;
        lanes.Combine(state);
        view.first = state.first;
        view.firstSide = state.firstSide;
        view.firstFace = state.firstFace;
        view.last = state.last;
        if (!going && view.exit == SweepExit::AllAxesOverlap)
        {
            view.exit = SweepExit::EntryAfterExit;
            tracer.EndedAfterPass();
        }
    }
    return going;
}

// The faces (or vertices) of a polygon along a counter-clockwise chain from `from`, by their offset k from it.
struct Chain
{
    int from;
    int n;
    int At(int k) const { return from + k < n ? from + k : from + k - n; }
};

// The first offset in [0, count) at which `past` holds, or `count`: `past` fails up to some offset and holds from
// there on, so bisection finds it.
template <typename Past>
int FirstPast(int count, Past&& past)
{
    int lo = 0;
    int left = count; // offsets from lo still in question
    while (left > 0)
    {
        const int half = left / 2;
        const bool beyond = past(lo + half);
        lo = beyond ? lo : lo + half + 1;
        left = beyond ? half : left - half - 1;
    }
    return lo;
}

// The support vertex of `polygon` in direction `d` (its frame), known to lie on the chain from vertex `lo` to vertex
// `hi` (counter-clockwise, less than half a turn): the first vertex there whose edge no longer climbs along d, by
// bisection, settled by ClimbFrom as in BisectSupport. O(log) of the chain's length.
template <typename S>
int BracketedSupport(const PolygonT<S>& polygon, Vec2T<S> d, int lo, int hi)
{
    const int n = polygon.Count();
    const Chain chain{lo, n};
    const int k =
        FirstPast(hi >= lo ? hi - lo : hi - lo + n, [&](int j) { return !(Dot(d, polygon.Edge(chain.At(j))) > S(0)); });
    return ClimbFrom(polygon, d, chain.At(k));
}

// What the bounded face loop of one polygon (SweepBoundedFaces) leaves for its second pass (SweepBoundedExits).
template <typename S>
struct WalkedSweep
{
    bool walked = false; // inc was walked: its exit-only faces wait for the second pass
    Vec2T<S> witness{};  // the point of inc that bounds the separations of ref's faces
};

// What the evaluation of a walked face loop (below) holds for the recorder: the recorder, its view and the pass. An
// empty base for an untraced query, which then holds nothing more than it needs.
template <typename S, typename Tracer, bool = Tracer::kEnabled>
class EvaluationTrace
{
  protected:
    EvaluationTrace(Tracer&, SweepState<S>&, bool) {}
};

template <typename S, typename Tracer>
class EvaluationTrace<S, Tracer, true>
{
  protected:
    EvaluationTrace(Tracer& tracer, SweepState<S>& view, bool exitPass)
        : m_tracer(tracer), m_view(view), m_exitPass(exitPass)
    {
    }
    Tracer& m_tracer;
    SweepState<S>& m_view;
    bool m_exitPass;
};

// The faces of a walked face loop that need their exact separation, evaluated in increasing face order four at a
// time into the lanes (SweepLanes::Add): inc's support point for each (climbed from the one before, found by
// bisection after a gap, or searched for between two that bracket it), its separation, and the axis times. `known`
// rises to the latest entry seen. The recorder records each face as it is taken, with the lanes' numbers once they
// take it in, and the faces decided without evaluation as the loop decides them (Bounded, Skipped); `view` learns
// why an axis ended the test. `exitPass`: the second pass of a walked loop (SweepBoundedExits).
template <typename L, typename S, typename Tracer>
class WalkedEvaluation : EvaluationTrace<S, Tracer>
{
  public:
    WalkedEvaluation(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                     SweepLanes<L, S>& lanes, S& known, Tracer& tracer, SweepState<S>& view, bool exitPass = false)
        : EvaluationTrace<S, Tracer>(tracer, view, exitPass), m_ref(ref), m_inc(inc), m_side(side),
          m_velocity(velocity), m_lanes(lanes), m_known(known)
    {
    }

    // The lower bound of the latest entry so far.
    S Known() const { return m_known; }

    // For the trace: face i, not walked to, whose separation the witness bounds by `bound`; `rate` is its rate and
    // `known` the lower bound of the latest entry that the loop compared with. The second pass records only the
    // faces that recede (the others have no exit to bound).
    void Bounded(int i, S bound, S rate, S known)
    {
        S boundTime;
        if (this->m_exitPass)
        {
            if (!(rate > StillRate(m_velocity)))
            {
                return;
            }
            boundTime = -bound / rate;
        }
        else
        {
            boundTime = bound < S(0) ? S(0) : bound / -rate;
        }
        const ViewedFace<S> shown = ViewFace<L>(m_ref, m_inc, i, m_velocity);
        this->m_tracer.Bounded(m_side, i, shown.separation, shown.rate, shown.entry, shown.exit, bound, boundTime,
                               known, this->m_exitPass);
    }

    // For the trace: face i, never evaluated: the bisection showed it cannot decide.
    void Skipped(int i)
    {
        const ViewedFace<S> shown = ViewFace<L>(m_ref, m_inc, i, m_velocity);
        this->m_tracer.Skipped(m_side, i, shown.separation, shown.rate, shown.entry, shown.exit);
    }

    // Evaluates face i (after the faces added before it); true when an axis ends the test.
    bool Add(int i)
    {
        const Vec2T<S> normal = m_ref.Normal(i);
        const Vec2T<S> d = InvRotate(m_inc.xf.q, -normal);
        return Take(i, normal,
                    m_last < 0 || i - m_last > kClimbLimit ? BisectSupport(m_inc.polygon, d)
                                                           : ClimbFrom(m_inc.polygon, d, m_support));
    }

    // Evaluates face i, whose support point lies on inc's chain from `lo` to `hi` (BracketedSupport; or near
    // them), after the faces added before it; true when an axis ends the test.
    bool Add(int i, int lo, int hi)
    {
        const Vec2T<S> normal = m_ref.Normal(i);
        return Take(i, normal, BracketedSupport(m_inc.polygon, InvRotate(m_inc.xf.q, -normal), lo, hi));
    }

    // The support point of the last face evaluated (ref's frame), or `otherwise` before the first.
    Vec2T<S> Witness(Vec2T<S> otherwise) const
    {
        return m_last < 0 ? otherwise : TransformPoint(m_inc.xf, m_inc.polygon.Vertices()[m_support]);
    }

    // Takes the pending faces into the lanes (the last one repeated in the lanes left); true when an axis ends the
    // test.
    bool Flush()
    {
        if (m_count == 0)
        {
            return false;
        }
        const auto at = [this](int l) { return std::min(l, m_count - 1); };
        const Vec2T<S> n0 = m_ref.Normal(m_faces[at(0)]);
        const Vec2T<S> n1 = m_ref.Normal(m_faces[at(1)]);
        const Vec2T<S> n2 = m_ref.Normal(m_faces[at(2)]);
        const Vec2T<S> n3 = m_ref.Normal(m_faces[at(3)]);
        const L nx = L::Set(n0.x, n1.x, n2.x, n3.x);
        const L ny = L::Set(n0.y, n1.y, n2.y, n3.y);
        const L separations =
            L::Set(m_separations[at(0)], m_separations[at(1)], m_separations[at(2)], m_separations[at(3)]);
        const L rates = nx * L::Fill(m_velocity.x) + ny * L::Fill(m_velocity.y);
        const S base = S(m_side * kSideStride);
        const L faces = L::Set(base + S(m_faces[at(0)]), base + S(m_faces[at(1)]), base + S(m_faces[at(2)]),
                               base + S(m_faces[at(3)]));
        m_count = 0;
        const bool ends = m_lanes.Add(AxisLanes<L>(separations, rates, StillRate(m_velocity)), faces).Any();
        m_known = std::max(m_known, m_lanes.first.MaxLane());
        if constexpr (Tracer::kEnabled)
        {
            // The lanes' numbers again, and the lanes whose axis ended the test (SweepLanes::Add): it never closes,
            // or its entry is after t = 1 (a lane's latest entry was at most 1 before, or an earlier block would
            // have ended the test).
            const AxisLanes<L> axes(separations, rates, StillRate(m_velocity));
            const int ended = this->m_tracer.Flushed(rates, axes, axes.never | (m_lanes.first > L::Fill(S(1))));
            if (ended >= 0)
            {
                this->m_view.exit = axes.never.Get(ended) ? SweepExit::NeverCloses : SweepExit::EntryAfterStep;
            }
        }
        return ends;
    }

  private:
    // Face i, its unit normal and inc's support point for it, into the pending faces; true when an axis ends the
    // test.
    bool Take(int i, Vec2T<S> normal, int support)
    {
        m_support = support;
        m_last = i;
        m_faces[m_count] = i;
        m_separations[m_count] = m_inc.Separation(normal, m_ref.Vertices()[i], support);
        if constexpr (Tracer::kEnabled)
        {
            this->m_tracer.Taken(m_side, i, m_separations[m_count], this->m_exitPass);
        }
        ++m_count;
        return m_count == 4 && Flush();
    }

    // Faces skipped beyond which the support point is found by bisection rather than climbed to.
    static constexpr int kClimbLimit = 16;
    const PolygonT<S>& m_ref;
    const IncidentPolygon<S>& m_inc;
    int m_side;
    Vec2T<S> m_velocity;
    SweepLanes<L, S>& m_lanes;
    S& m_known;
    int m_support = 0;
    int m_last = -1;
    int m_count = 0;
    int m_faces[4] = {};
    S m_separations[4] = {};
};

// Visits the faces of ref in blocks of four with the bounds a witness w (a point of inc) gives: per face, its
// distance d = Dot(n, w - v_i) bounds the separation s from above (s <= d), and r = Dot(n, velocity) is the rate.
// `select(d, r)` returns the lanes to evaluate exactly (face `always` is evaluated in any case), which `evaluation`
// takes in face order; the witness of each block is the support point of the last face evaluated (it turns with the
// faces, so it bounds the next ones tightly), or `witness` before the first. True when an axis ends the test. The
// recorder has the faces not selected in face order among those evaluated, with their bounds.
template <typename L, typename S, typename Tracer, typename Select>
bool VisitBounds(const PolygonT<S>& ref, Vec2T<S> witness, Vec2T<S> velocity, Select&& select,
                 WalkedEvaluation<L, S, Tracer>& evaluation, int always = -1)
{
    const int n = ref.Count();
    const L vx = L::Fill(velocity.x);
    const L vy = L::Fill(velocity.y);
    for (int i0 = 0; i0 < n; i0 += 4)
    {
        const Vec2T<S> w = evaluation.Witness(witness);
        const FaceBlock<L, S> block(ref, ref.Vertices().data, i0);
        const L distance = block.nx * (L::Fill(w.x) - block.vx) + block.ny * (L::Fill(w.y) - block.vy);
        const L rate = block.nx * vx + block.ny * vy;
        [[maybe_unused]] const S known = evaluation.Known(); // what `select` compares with
        int lanes = select(distance, rate).Bits() & (n - i0 >= 4 ? 0xF : (1 << (n - i0)) - 1);
        lanes |= always >= i0 && always < i0 + 4 ? 1 << (always - i0) : 0;
        // For the trace: the faces of the block not selected, recorded up to the lane `end` (in face order).
        [[maybe_unused]] int bounded = ~lanes & (n - i0 >= 4 ? 0xF : (1 << (n - i0)) - 1);
        [[maybe_unused]] const auto record = [&](int end) {
            if constexpr (Tracer::kEnabled)
            {
                for (; bounded != 0 && __builtin_ctz(static_cast<unsigned>(bounded)) < end; bounded &= bounded - 1)
                {
                    const int l = __builtin_ctz(static_cast<unsigned>(bounded));
                    evaluation.Bounded(i0 + l, distance.Get(l), rate.Get(l), known);
                }
            }
        };
        while (lanes != 0)
        {
            const int l = __builtin_ctz(static_cast<unsigned>(lanes));
            lanes &= lanes - 1;
            if constexpr (Tracer::kEnabled)
            {
                record(l);
            }
            if (evaluation.Add(i0 + l))
            {
                return true;
            }
        }
        if constexpr (Tracer::kEnabled)
        {
            record(4);
        }
    }
    return false;
}

// The faces of `ref` against a walked `inc` (more than kScanLimit vertices): as SweepFaces, but only the faces that
// can decide are walked to. A point w of inc bounds each face's separation from above (s <= d, VisitBounds): first
// inc's support point for the face of ref that meets the motion most head-on (at ref's support point against the
// velocity), whose entry, if it has one, starts `known`, a lower bound of the latest entry (that face is always
// walked to, so the lanes hold its entry too); then the support point of the last face walked to. A face with d < 0
// overlaps from t = 0 on (entry 0, and it keeps `inside`): its exit alone can matter, and only if it comes before
// the latest entry, which is known after both polygons' faces: the second pass (SweepBoundedExits) takes the exits
// in. A face that approaches (r < 0) with entry bound d / -r below `known` cannot hold the latest entry, nor tie
// with it. Every other face (d >= 0 and r >= 0: it may never close; or its entry may be the latest) is walked to,
// in face order. So the latest entry, its first face and the verdict are those of the full loop, up to rounding
// where a bound and a separation tie (two support points on an edge parallel to the face). The recorder has the faces
// walked to, with the lanes' numbers, and those not walked to, with their bounds, in face order.
template <typename L, typename S, typename Tracer>
bool SweepBoundedFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                       SweepLanes<L, S>& lanes, SweepState<S>& view, Tracer& tracer, S& known, WalkedSweep<S>& walk)
{
    const int n = ref.Count();
    const int top = BisectSupport(ref, -velocity);
    const int before = Prev(top, n);
    const int seed = Dot(ref.Normal(top), velocity) <= Dot(ref.Normal(before), velocity) ? top : before;
    const Vec2T<S> seedNormal = ref.Normal(seed);
    const int seedSupport = BisectSupport(inc.polygon, InvRotate(inc.xf.q, -seedNormal));
    walk.walked = true;
    walk.witness = TransformPoint(inc.xf, inc.polygon.Vertices()[seedSupport]);
    const S seedSeparation = inc.Separation(seedNormal, ref.Vertices()[seed], seedSupport);
    const S rawSeedRate = seedNormal.x * velocity.x + seedNormal.y * velocity.y;
    const S seedRate = std::abs(rawSeedRate) > StillRate(velocity) ? rawSeedRate : S(0);
    if (seedSeparation >= S(0) && seedRate < S(0))
    {
        known = std::max(known, seedSeparation / -seedRate);
    }
    WalkedEvaluation<L, S, Tracer> evaluation(ref, inc, side, velocity, lanes, known, tracer, view);
    // Entry bound d / -r below known, without a division: d < known (1 - 4 eps) (-r) implies it despite the
    // rounding of the product and the quotient (not that of d itself). A face whose rate is within StillRate of 0
    // counts as parallel to the motion (AxisLanes): it is walked to, as it may never close.
    const S shrink = S(1) - S(4) * std::numeric_limits<S>::epsilon();
    const S still = StillRate(velocity);
    const auto select = [&known, shrink, still](const L& distance, const L& rate) {
        const L zero = L::Fill(S(0));
        return ~((zero > distance) | ((L::Fill(-still) > rate) & (L::Fill(known * shrink) * -rate > distance)));
    };
    const bool ends = VisitBounds<L>(ref, walk.witness, velocity, select, evaluation, seed) || evaluation.Flush();
    return EndPass(tracer, view, lanes, !ends && !(lanes.first.MaxLane() >= lanes.last.MinLane()));
}

// The second pass of a walked face loop, once the latest entry is known: every face that recedes (r > 0) and
// whose exit bound -d / r does not clear the latest entry is walked to, so every exit that could come before the
// latest entry is taken in. False when one exits no later than the latest entry (or an axis never closes): a miss.
// The recorder has the faces walked to and the receding faces not walked to, in face order.
template <typename L, typename S, typename Tracer>
bool SweepBoundedExits(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                       SweepLanes<L, S>& lanes, const WalkedSweep<S>& walk, SweepState<S>& view, Tracer& tracer)
{
    const S first = lanes.first.MaxLane();
    S known = first;
    WalkedEvaluation<L, S, Tracer> evaluation(ref, inc, side, velocity, lanes, known, tracer, view, true);
    // Exit bound -d / r after the latest entry, without a division: -d > first (1 + 4 eps) r implies it despite
    // the rounding of the product and the quotient (not that of d itself).
    const S grow = S(1) + S(4) * std::numeric_limits<S>::epsilon();
    // Every receding face whose exit bound does not clear the latest entry: its witness may differ from the one
    // that sent the face here in the first pass, so the selection does not rest on that pass's choice.
    // A rate within StillRate of 0 counts as 0 (AxisLanes): that face never exits.
    const S still = StillRate(velocity);
    const auto select = [first, grow, still](const L& distance, const L& rate) {
        return (rate > L::Fill(still)) & ~(-distance > L::Fill(first * grow) * rate);
    };
    if (VisitBounds<L>(ref, walk.witness, velocity, select, evaluation) || evaluation.Flush())
    {
        return EndPass(tracer, view, lanes, false);
    }
    return EndPass(tracer, view, lanes, !(first >= lanes.last.MinLane()));
}

// A run of `count` faces of ref (counter-clockwise from run.from) that all face against the motion (`facing`) or
// all along it, and where the line of the motion crosses the faces the run builds on the Minkowski difference
// M = ref - inc (ref's frame, inc moving by `velocity`): the offset of the first face whose end on M lies past the
// line, or `count`. Face i of ref builds the face of M from v_i - w to v_(i+1) - w, with w inc's support point
// against its normal. Along a run facing the motion these ends cross the line t velocity once, from its left to
// its right, looking along the motion (Cross(end, velocity) rises); along a run facing away, from right to left. The
// run's faces are bisected on that side, each support point searched for between `supportLo` and `supportHi`, inc's
// support points for the run's first and last faces on entry, then for the faces bisected on either side (a run's
// support points turn with its normals, less than half a turn in all). On return they bracket the support points of the
// faces beside the crossing. O(log n log m) for a run of n faces and an inc of m vertices.
template <typename S>
int CrossingFace(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, Vec2T<S> velocity, Chain run, int count,
                 bool facing, int& supportLo, int& supportHi)
{
    const int n = ref.Count();
    const auto past = [&](int k) {
        const int face = run.At(k);
        const int support = BracketedSupport(inc.polygon, InvRotate(inc.xf.q, -ref.Normal(face)), supportLo, supportHi);
        const Vec2T<S> end = ref.Vertices()[Next(face, n)] - TransformPoint(inc.xf, inc.polygon.Vertices()[support]);
        const S side = Cross(end, velocity);
        const bool beyond = facing ? side >= S(0) : side <= S(0);
        (beyond ? supportHi : supportLo) = support;
        return beyond;
    };
    return FirstPast(count, past);
}

// The faces of a `ref` of more than kBisectFaces faces against `inc` (walked or scanned): as SweepFaces, but only the
// faces that can decide are evaluated, found by bisection, never every face: O(log n log m) steps for ref's n faces
// and inc's m vertices, plus one per face of either polygon parallel to the motion (Ericson 5.5.2 on the Minkowski
// difference M, as a ray cast in Cyrus-Beck form, with the bisection of a ray against a convex outline).
//   1. The rate r = Dot(n, velocity) changes sign at ref's support points across the motion: from there, face by
//      face, a run of faces facing the motion (r < -still) and a run facing away (r > still), with the faces
//      between them (|r| <= still, as AxisLanes rounds r; usually none).
//   2. The faces that face the motion are faces of M's outline on the side the motion enters: a face's entry time
//      s / -r is where the line of the motion crosses its line, and along the run those times rise up to the face
//      of M the line crosses and fall after it (a convex outline). So the latest entry among ref's faces is at one
//      of the two faces of ref beside that crossing (CrossingFace). Likewise the run facing away: its exit times
//      -s / r fall to the face of M the line leaves through, then rise, and a face that never closes (s >= 0,
//      r > 0) has the earliest exit time of all (<= 0), so it is one of the two faces there.
//   3. Those faces, the face after them (two faces whose times tie where the line passes through their common end
//      on M), the first and last face of each run and the faces between the runs (an axis along the motion that
//      never closes) are evaluated exactly, in face order (WalkedEvaluation): the lanes take their entries, exits
//      and ends as the full loop does, so the latest entry, its first face and the verdict are those of every face,
//      up to rounding where two faces' times tie, and up to a face that rounding alone takes for parallel to the
//      motion inside a run (nearly collinear faces). A NaN velocity leaves no face in either run: the faces
//      evaluated then decide alone, a miss unless the shapes interpenetrate, as with every face.
//   The recorder has the faces evaluated, with the lanes' numbers, and the others as skipped, in face order up to
//   the last candidate, then the faces between the runs.
template <typename L, typename S, typename Tracer>
bool SweepBisectedFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                        SweepLanes<L, S>& lanes, SweepState<S>& view, Tracer& tracer, S& known)
{
    const int n = ref.Count();
    const S still = StillRate(velocity);
    const auto facing = [&](int i) { return Dot(ref.Normal(i), velocity) < -still; };
    const auto away = [&](int i) { return Dot(ref.Normal(i), velocity) > still; };
    const auto direction = [&](int i) { return InvRotate(inc.xf.q, -ref.Normal(i)); };
    // A run's first face: the first in the run from `vertex` on, then back while the face before is in the run too.
    const auto first = [n](int vertex, const auto& inRun) {
        int f = vertex;
        for (int k = 0; k < n && !inRun(f); ++k)
        {
            f = Next(f, n);
        }
        for (int k = 0; k < n && inRun(Prev(f, n)); ++k)
        {
            f = Prev(f, n);
        }
        return f;
    };
    // A run's last face: the last in the run before `next`, the first face of the other run.
    const auto last = [n](int next, const auto& inRun) {
        int f = Prev(next, n);
        for (int k = 0; k < n && !inRun(f); ++k)
        {
            f = Prev(f, n);
        }
        return f;
    };
    // Looking along the motion, the faces turn to face it at ref's leftmost point, and away at its rightmost.
    const Vec2T<S> left = LeftPerp(velocity);
    const int frontFirst = first(BisectSupport(ref, left), facing);
    const int backFirst = first(BisectSupport(ref, -left), away);
    const int frontLast = last(backFirst, facing);
    const int backLast = last(frontFirst, away);
    // inc's support points for the runs' ends: two bisections, then climbs to the faces beside them.
    const int frontFirstSupport = BisectSupport(inc.polygon, direction(frontFirst));
    const int backFirstSupport = BisectSupport(inc.polygon, direction(backFirst));
    const int frontLastSupport = ClimbFrom(inc.polygon, direction(frontLast), backFirstSupport);
    const int backLastSupport = ClimbFrom(inc.polygon, direction(backLast), frontFirstSupport);
    // The faces to evaluate, with the support points that bracket theirs: three beside each crossing, and the runs'
    // ends.
    struct Candidate
    {
        int face;
        int lo;
        int hi;
    };
    Candidate candidates[10];
    int count = 0;
    // On return from CrossingFace, lo and hi bracket the support points of faces k - 1 and k; that of face k + 1
    // lies between hi and the run's last.
    const auto around = [&](int runFirst, int runLast, int lo, int hi, bool towards) {
        const Chain run{runFirst, n};
        const int runCount = (runLast >= runFirst ? runLast - runFirst : runLast - runFirst + n) + 1;
        const int runLastSupport = hi;
        const int k = CrossingFace(ref, inc, velocity, run, runCount, towards, lo, hi);
        for (int j = std::max(0, k - 1); j <= std::min(runCount - 1, k); ++j)
        {
            candidates[count++] = {run.At(j), lo, hi};
        }
        if (k + 1 < runCount)
        {
            candidates[count++] = {run.At(k + 1), hi, runLastSupport};
        }
    };
    around(frontFirst, frontLast, frontFirstSupport, frontLastSupport, true);
    around(backFirst, backLast, backFirstSupport, backLastSupport, false);
    candidates[count++] = {frontFirst, frontFirstSupport, frontFirstSupport};
    candidates[count++] = {frontLast, frontLastSupport, frontLastSupport};
    candidates[count++] = {backFirst, backFirstSupport, backFirstSupport};
    candidates[count++] = {backLast, backLastSupport, backLastSupport};
    // In face order, once each: equal entries then keep the first face, as in the full loop.
    for (int c = 1; c < count; ++c)
    {
        for (int j = c; j > 0 && candidates[j - 1].face > candidates[j].face; --j)
        {
            std::swap(candidates[j - 1], candidates[j]);
        }
    }
    WalkedEvaluation<L, S, Tracer> evaluation(ref, inc, side, velocity, lanes, known, tracer, view);
    // For the trace: the faces to be evaluated (the candidates and the faces between the runs), and the next face in
    // face order not yet recorded; `skipTo` records those before `end` that are not evaluated as skipped.
    [[maybe_unused]] std::conditional_t<Tracer::kEnabled, std::vector<bool>, bool> evaluated{};
    [[maybe_unused]] int unrecorded = 0;
    [[maybe_unused]] const auto skipTo = [&](int end) {
        if constexpr (Tracer::kEnabled)
        {
            for (; unrecorded < end; ++unrecorded)
            {
                if (!evaluated[static_cast<size_t>(unrecorded)])
                {
                    evaluation.Skipped(unrecorded);
                }
            }
        }
    };
    if constexpr (Tracer::kEnabled)
    {
        evaluated.assign(static_cast<size_t>(n), false);
        for (int c = 0; c < count; ++c)
        {
            evaluated[static_cast<size_t>(candidates[c].face)] = true;
        }
        for (int f = Next(frontLast, n), k = 0; f != backFirst && k < n; f = Next(f, n), ++k)
        {
            evaluated[static_cast<size_t>(f)] = true;
        }
        for (int f = Next(backLast, n), k = 0; f != frontFirst && k < n; f = Next(f, n), ++k)
        {
            evaluated[static_cast<size_t>(f)] = true;
        }
    }
    for (int c = 0; c < count; ++c)
    {
        const Candidate& candidate = candidates[c];
        if constexpr (Tracer::kEnabled)
        {
            skipTo(candidate.face);
        }
        if ((c == 0 || candidate.face != candidates[c - 1].face) &&
            evaluation.Add(candidate.face, candidate.lo, candidate.hi))
        {
            return EndPass(tracer, view, lanes, false);
        }
    }
    if constexpr (Tracer::kEnabled)
    {
        skipTo(n);
    }
    // The faces between the runs: their rate counts as 0, so they have no entry and no exit (in any order), and end
    // the test when they never close.
    for (int f = Next(frontLast, n), k = 0; f != backFirst && k < n; f = Next(f, n), ++k)
    {
        if (evaluation.Add(f, frontLastSupport, frontLastSupport))
        {
            return EndPass(tracer, view, lanes, false);
        }
    }
    for (int f = Next(backLast, n), k = 0; f != frontFirst && k < n; f = Next(f, n), ++k)
    {
        if (evaluation.Add(f, backLastSupport, backLastSupport))
        {
            return EndPass(tracer, view, lanes, false);
        }
    }
    return EndPass(tracer, view, lanes, !evaluation.Flush() && !(lanes.first.MaxLane() >= lanes.last.MinLane()));
}

// SweepFaces with inc's scan unrolled for its padded vertex count, and a ref of up to 8 faces in one pass.
template <int N, typename L, typename S, typename Tracer>
bool SweepFacesN(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                 SweepLanes<L, S>& lanes, SweepState<S>& view, Tracer& tracer, KeptSeparations<L>& kept)
{
    switch ((ref.Count() + 3) / 4)
    {
    case 1:
        return SweepFaces<N, 1>(ref, inc, side, velocity, lanes, view, tracer, kept);
    case 2:
        return SweepFaces<N, 2>(ref, inc, side, velocity, lanes, view, tracer, kept);
    default:
        return SweepFaces<N, 0>(ref, inc, side, velocity, lanes, view, tracer, kept);
    }
}

// Polygons with more faces than this have them bisected (SweepBisectedFaces) rather than bounded face by face
// (SweepBoundedFaces) or scanned. A bisection's reads and branches depend on each other, so each waits for the one
// before, while a pass over the faces reads ahead: on polygons in the cache the bisection is the faster above about
// 128 faces, on polygons that come from memory above about 512 (SweepTime of same-sized pairs).
constexpr int kBisectFaces = 256;

template <typename L, typename S, typename Tracer>
bool SweepFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                SweepLanes<L, S>& lanes, SweepState<S>& view, Tracer& tracer, S& known, WalkedSweep<S>& walk,
                KeptSeparations<L>& kept)
{
    if (ref.Count() > kBisectFaces) [[unlikely]]
    {
        return SweepBisectedFaces(ref, inc, side, velocity, lanes, view, tracer, known);
    }
    switch (inc.scan ? inc.padded : 0)
    {
    case 4:
        return SweepFacesN<4>(ref, inc, side, velocity, lanes, view, tracer, kept);
    case 8:
        return SweepFacesN<8>(ref, inc, side, velocity, lanes, view, tracer, kept);
    case 12:
        return SweepFacesN<12>(ref, inc, side, velocity, lanes, view, tracer, kept);
    case 16:
        return SweepFacesN<16>(ref, inc, side, velocity, lanes, view, tracer, kept);
    default:
        return SweepBoundedFaces(ref, inc, side, velocity, lanes, view, tracer, known, walk);
    }
}

// The contact points of a swept hit against a scanned incident polygon, in world space (Catto's clipping, reduced to
// what a time of impact leaves). At the time of impact the polygons touch on the line of the reference face and
// nowhere else, so the incident vertices within `slop` of that line are the contact: one vertex (its support point
// against the face), or two, the ends of an edge that lies along the face, which is then cut to the face's extent.
//   1. Every vertex, four at a time: whether its separation from the face at the time of impact is within `slop`,
//      its place along the face, and its place in the world at t = 0. The lanes of the vertices within `slop`
//      give the span along the face (least and greatest) and, when there is one such vertex, its place in the
//      world: no support point is searched for, no vertex is read back by index, and nothing branches on where the
//      polygons touch. Rounding can leave no vertex within `slop` (a shape far from the frame's origin, moving
//      fast): then the support vertex alone.
//   2. One vertex P: P in the world at t = 0, moved by its own velocity up to the time of impact.
//   3. More (an edge along the face): their span along the face, cut to the face's ends, as points of the face
//      (which moves with the reference polygon's velocity). They are within `slop` of the face, so these points are
//      on both outlines.
//   `face` is the reference face of `ref`; `inc` holds the incident polygon's vertices in ref's frame at t = 0;
//   `shift` is inc's motion relative to ref up to `toi` (ref's frame); `xfRef` is ref's transform at t = 0, `vRef`
//   and `vInc` the world velocities. At the time of impact the separation is zero: the contacts carry 0.
template <bool kWide, typename S>
int SweptContacts(const PolygonT<S>& ref, int face, const IncidentPolygon<S>& inc, Vec2T<S> shift, S slop,
                  const TransformT<S>& xfRef, Vec2T<S> vRef, Vec2T<S> vInc, S toi, ContactPointT<S> (&contacts)[2])
{
    using L = Lanes<S, kWide && std::is_same_v<S, double>>;
    const Vec2T<S> normal = ref.Normal(face);
    const Vec2T<S> tangent = LeftPerp(normal); // along the face, from v1 towards v2
    const Vec2T<S> v1 = ref.Vertices()[face];
    const S length = Dot(tangent, ref.Vertices()[Next(face, ref.Count())] - v1);
    // Separation at toi: Dot(n, p + shift - v1) <= slop, as Dot(n, p) <= slop + Dot(n, v1 - shift). Along the face
    // at toi: Dot(t, p) + Dot(t, shift - v1). The padding repeats vertex 0, which moves no least or greatest.
    const L nx = L::Fill(normal.x);
    const L ny = L::Fill(normal.y);
    const L tx = L::Fill(tangent.x);
    const L ty = L::Fill(tangent.y);
    const L limit = L::Fill(slop + Dot(normal, v1 - shift));
    const L alongShift = L::Fill(Dot(tangent, shift - v1));
    const L c = L::Fill(xfRef.q.c);
    const L s = L::Fill(xfRef.q.s);
    const L px = L::Fill(xfRef.p.x);
    const L py = L::Fill(xfRef.p.y);
    const L infinity = L::Fill(std::numeric_limits<S>::infinity());
    L least = infinity;
    L greatest = -infinity;
    L worldX = -infinity;
    L worldY = -infinity;
    uint32_t near = 0;
    for (int j = 0; j < inc.padded; j += 4)
    {
        const L x = L::Load(inc.x + j);
        const L y = L::Load(inc.y + j);
        const typename L::Mask onLine = limit >= nx * x + ny * y;
        near |= static_cast<uint32_t>(onLine.Bits()) << j;
        const L along = (tx * x + ty * y) + alongShift;
        least = Min(least, Select(onLine, along, infinity));
        greatest = Max(greatest, Select(onLine, along, -infinity));
        worldX = Max(worldX, Select(onLine, (c * x - s * y) + px, -infinity));
        worldY = Max(worldY, Select(onLine, (s * x + c * y) + py, -infinity));
    }
    near &= (uint32_t(1) << inc.polygon.Count()) - 1;
    const S low = std::max(S(0), least.MinLane());
    const S high = std::min(length, greatest.MaxLane());
    // Two vertices or more, spanning part of the face: an edge along it. (Bitwise: && became a branch on the
    // geometry.) An edge past the face's end (rounding at a corner) leaves the vertex alone.
    const bool edge = ((near & (near - 1)) != 0) & (low < high);
    Vec2T<S> vertex{worldX.MaxLane(), worldY.MaxLane()};
    if (near == 0) [[unlikely]]
    {
        // No vertex within `slop`: no edge either, and the support vertex alone.
        const int support = inc.template Support<kWide>(normal);
        vertex = TransformPoint(xfRef, Vec2T<S>{inc.x[support], inc.y[support]});
    }
    // The face in the world at t = 0 from its first vertex along its direction, and moved by ref's velocity.
    const Vec2T<S> faceStart = TransformPoint(xfRef, v1) + toi * vRef;
    const Vec2T<S> faceDirection = Rotate(xfRef.q, tangent);
    contacts[0] = {Select(edge, faceStart + low * faceDirection, vertex + toi * vInc), S(0)};
    contacts[1] = {Select(edge, faceStart + high * faceDirection, Vec2T<S>{}), S(0)};
    return edge ? 2 : 1;
}

#if SATVIZ_WIDE
// What the face loops of two polygons of at most 8 faces decide, found from every face of both at once on 512-bit
// vectors (SmallSweep512): whether the test goes on, the latest entry and its face, whether every separation is < 0,
// and the separations themselves, for the static manifold of an interpenetrating start.
struct SmallSweepVerdict
{
    bool going = false;
    SweepState<double> state;
    Lanes8 sepA;
    Lanes8 sepB;
    MappedPair512 mapped; // both polygons, each mapped into the other's frame
};

// The entry and exit times of the faces of `ref` (at most 8, one per lane) whose separations are `separations`
// (FaceSeparations512; -infinity past the last face), moving at `velocity` (ref's frame, as SweepFaces takes it):
// AxisLanes' rule lane by lane, with the same operations, so the same bits. A lane past the last face enters never
// (-infinity) and exits never (+infinity): it takes no part. NaN entries and exits become -infinity and +infinity,
// which the lanes of SweepLanes never take either. Returns the lanes of the faces that are apart (separation >= 0)
// and, in `never`, those that never close.
[[gnu::target("avx2,avx512f")]] inline int FaceTimes512(const PolygonT<double>& ref, const Lanes8& separations,
                                                        Vec2T<double> velocity, Lanes8& entry, Lanes8& leave,
                                                        int& never)
{
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const int n = ref.Count();
    Lanes8 nx;
    Lanes8 ny;
    Lanes8::LoadPoints(&ref.InlineBlock()[n + 1].x, nx, ny);
    const Lanes8 raw = nx * Lanes8::Fill(velocity.x) + ny * Lanes8::Fill(velocity.y);
    const Lanes8 zero = Lanes8::Fill(0.0);
    // Moving: a rate within StillRate of 0 is 0.
    const Lanes8 rate = zero.Blend(Max(raw, -raw).GreaterBits(Lanes8::Fill(StillRate(velocity))), raw);
    const int apart = separations.GreaterEqualBits(zero);
    const Lanes8 q = separations / -rate;
    const int numbers = q.GreaterEqualBits(Lanes8::Fill(-kInf));
    entry = Lanes8::Fill(-kInf).Blend(apart & numbers, q);
    leave = Lanes8::Fill(kInf).Blend(~apart & rate.GreaterBits(zero) & numbers & 0xFF, q);
    never = apart & rate.GreaterEqualBits(zero);
    return apart;
}

// The face loops of a sweep of two polygons of at most 8 faces (SweepFaces of A, then of B) on 512-bit vectors:
// every face of both polygons at once, then one decision, where the face loops decide after each polygon. The same
// verdict, latest entry and face: each bound only tightens from face to face, so a test that ends after A's faces
// also ends after both; the latest entry is the largest entry of all, its face the first face that has it (A's
// faces first), as SweepLanes::Combine finds them. `bInA`, `aInB`: each polygon's frame in the other's.
[[gnu::target("avx2,avx512f")]] inline SmallSweepVerdict
SmallSweep512(const PolygonT<double>& a, const PolygonT<double>& b, const TransformT<double>& bInA,
              const TransformT<double>& aInB, Vec2T<double> velocityInA, Vec2T<double> velocityInB)
{
    SmallSweepVerdict out;
    out.mapped = MapPair512(a, b, bInA, aInB);
    PairSeparations512(a, b, out.mapped, 0, out.sepA, out.sepB);
    Lanes8 entryA;
    Lanes8 leaveA;
    Lanes8 entryB;
    Lanes8 leaveB;
    int neverA = 0;
    int neverB = 0;
    const int apartA = FaceTimes512(a, out.sepA, velocityInA, entryA, leaveA, neverA);
    const int apartB = FaceTimes512(b, out.sepB, -velocityInB, entryB, leaveB, neverB);
    const double first = std::max(entryA.MaxLane(), entryB.MaxLane());
    const double last = std::min(leaveA.MinLane(), leaveB.MinLane());
    const int hitsA = entryA.EqualBits(Lanes8::Fill(first)) & ((1 << a.Count()) - 1);
    const int hitsB = entryB.EqualBits(Lanes8::Fill(first)) & ((1 << b.Count()) - 1);
    out.state.first = first;
    out.state.last = last;
    out.state.firstSide = hitsA == 0 && hitsB != 0 ? 1 : 0;
    out.state.firstFace = hitsA != 0   ? __builtin_ctz(static_cast<unsigned>(hitsA))
                          : hitsB != 0 ? __builtin_ctz(static_cast<unsigned>(hitsB))
                                       : 0;
    out.state.inside = (apartA | apartB) == 0;
    out.going = (neverA | neverB) == 0 && !(first > 1.0) && !(first >= last);
    return out;
}
#endif

// The static manifold of two polygons of at most 8 faces that interpenetrate at t = 0, from the separations their
// face loops kept (KeptSeparations) and the incident polygons mapped for them: as CollidePolygons with the same
// numbers, so the same manifold to the bit. Every separation is < 0 (the caller knows), so no face separates: the
// reference face is the face of largest separation, A's on a tie, B's faces anti-parallel to one of A's skipped as
// the second pass of Collide's face query skips them; its contacts are clipped as Collide clips them (kContacts; else
// the depth, normal and reference face alone).
template <bool kWide, bool kContacts, typename L, typename S>
ManifoldT<S> InterpenetratingManifold(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                                      const TransformT<S>& xfB, const IncidentPolygon<S>& incA,
                                      const IncidentPolygon<S>& incB, const KeptSeparations<L>& keptA,
                                      const KeptSeparations<L>& keptB)
{
    const auto largest = [](const KeptSeparations<L>& kept, uint64_t skip, int n, int& face) {
        L block0 = kept.block0;
        L block1 = kept.block1;
        if (kept.twoBlocks)
        {
            HideFaces<2>(skip, n, block0, block1);
        }
        else
        {
            HideFaces<1>(skip, n, block0, block1);
        }
        return LargestSeparation(block0, block1, n, face);
    };
    const uint64_t skip = SecondPassSkips<AlgorithmChoices::kSkipParallel>(b, incA, true);
    int faceA = 0;
    int faceB = 0;
    const S largestA = largest(keptA, 0, a.Count(), faceA);
    const S largestB = largest(keptB, skip, b.Count(), faceB);
    const bool flip = largestB > largestA;
    const PolygonT<S>& ref = SelectRef(flip, b, a);
    const IncidentPolygon<S>& inc = SelectRef(flip, incA, incB);
    const TransformT<S>& xfRef = SelectRef(flip, xfB, xfA);
    const int face = Select(flip, faceB, faceA);
    const S separation = Select(flip, largestB, largestA);
    if constexpr (!kContacts)
    {
        return ReferenceFaceManifold(ref, xfRef, face, flip, separation);
    }
    const ClipResult<S> clip = ClipIncidentEdge<kWide>(ref, face, inc, -1, S(0));
    return ReferenceFaceManifold(ref, xfRef, face, flip, separation, clip);
}

// The result of a hit (SweepPolygons, step 5), written into `result`: the time of impact, the axis of the latest
// entry (`state`) as the reference face, the normal and (kContacts) the contact points, with both polygons as the
// face loops mapped them (`incA`: A in B's frame, `incB`: B in A's) and their velocities in each frame.
template <bool kContacts, bool kWide, typename S>
void HitResult(const PolygonT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const PolygonT<S>& b,
               const TransformT<S>& xfB, Vec2T<S> vB, const IncidentPolygon<S>& incA, const IncidentPolygon<S>& incB,
               Vec2T<S> velocityInA, Vec2T<S> velocityInB, const SweepState<S>& state, SweepResultT<S>& result)
{
    // The incident polygon at the time of impact is its mapping at t = 0 moved by its motion relative to the
    // reference polygon over [0, first], in the reference frame: no polygon is mapped again.
    const S first = state.first + S(0); // a touching start enters at 0 or -0: +0
    const AxisRef firstAxis{AxisKind::FaceNormal, state.firstSide, state.firstFace};
    const bool flip = firstAxis.shape == 1;
    // Which polygon holds the reference face follows the geometry: every choice on it is a mask, not a branch.
    const PolygonT<S>& ref = SelectRef(flip, b, a);
    result.status = SweepStatus::Hit;
    result.toi = first;
    result.axis = firstAxis;
    if constexpr (!kContacts)
    {
        // The same normal as below: translation leaves the reference polygon's rotation as it was.
        const Vec2T<S> worldNormal = Rotate(Select(flip, xfB.q, xfA.q), ref.Normal(firstAxis.index));
        result.normal = Select(flip, -worldNormal, worldNormal);
        return;
    }
    const IncidentPolygon<S>& inc = SelectRef(flip, incA, incB);
    const TransformT<S>& xfRef0 = SelectRef(flip, xfB, xfA);
    const Vec2T<S> worldNormal = Rotate(xfRef0.q, ref.Normal(firstAxis.index));
    // At the time of impact the touching points are at zero distance up to rounding of either sign, which scales
    // with the coordinates in the reference frame: the incident polygon's offset at t = 0, its motion over the step
    // (together they bound its offset at any time in the step, and a fast shape is placed at the time of impact
    // only to within the rounding of its motion), and the face's own size (its largest coordinate extent, within
    // a factor sqrt(2) of its length and without a square root). None of these waits for the time of impact.
    const Vec2T<S> motion = Select(flip, -velocityInB, velocityInA);
    const Vec2T<S> face = ref.Vertices()[firstAxis.index];
    const Vec2T<S> edge = ref.Edge(firstAxis.index);
    const S scale = std::max({std::abs(inc.xf.p.x), std::abs(inc.xf.p.y), std::abs(motion.x), std::abs(motion.y),
                              std::abs(face.x), std::abs(face.y), std::abs(edge.x), std::abs(edge.y)});
    const S slop = S(64) * std::numeric_limits<S>::epsilon() * scale;
    const Vec2T<S> shift = first * motion;
    const Vec2T<S> vRef = Select(flip, vB, vA);
    result.normal = Select(flip, -worldNormal, worldNormal);
    if (inc.scan)
    {
        result.contactCount = SweptContacts<kWide>(ref, firstAxis.index, inc, shift, slop, xfRef0, vRef,
                                                   Select(flip, vA, vB), first, result.contacts);
        return;
    }
    const TransformT<S> xfRef = Moved(xfRef0, vRef, first);
    const ClipResult<S> clip = ClipIncidentEdge<kWide>(ref, firstAxis.index, inc, -1, slop, &shift);
    // At the time of impact the surfaces touch: the separation is 0, as SweptContacts gives it.
    result.contacts[0] = {WorldContact(clip, 0, xfRef).point, S(0)};
    result.contacts[1] = {WorldContact(clip, 1, xfRef).point, S(0)};
    result.contactCount = clip.contactCount;
    return;
}

/// Swept SAT for two translating polygons (Ericson 5.5.2).
/// Outline (steps 1 to 4 run, untraced, for polygons of up to 8 vertices on a processor with AVX-512, with every
/// face of each polygon in one register and one decision after both polygons: SmallSweep512, the same verdict, time
/// and face to the bit):
///   1. B's motion relative to A is v = vB - vA. On the unit normal n of a face of A, the face's separation (as in
///      the static face query) changes linearly: s(t) = s0 + t Dot(n, v); on a face of B, s(t) = s0 - t Dot(n, v).
///      These are the face normals of the Minkowski difference, so they are all the axes translation needs.
///   2. Per axis: if s0 >= 0 and the rate is >= 0 the axis never closes: no hit at any time (early exit). Else the
///      intervals overlap from entry = max(0, s0 / -rate) to exit = -s0 / rate (rate > 0) or forever.
///   3. First contact is the latest entry, valid while it is before the earliest exit (strictly: touching at one
///      instant is not a hit) and not after t = 1. Each bound only tightens, so the test ends as soon as it fails.
///      Against a walked polygon (above kScanLimit vertices) a point of it bounds every face's separation, so only
///      the faces that can hold the latest entry, never close, or exit before the latest entry are walked to
///      (SweepBoundedFaces, then SweepBoundedExits once the latest entry is known). A polygon above kBisectFaces
///      faces is not passed over: only its faces beside the two places where the line of the motion crosses the
///      Minkowski difference, and those along the motion, can decide; they are found by bisection and evaluated
///      alone (SweepBisectedFaces). Either way the same verdict and time.
///   4. Every s0 < 0: the shapes interpenetrate at t = 0: the static manifold gives the MTV.
///   5. A hit: the contact points at the time of impact (kContacts; else none: the time, normal and axis alone),
///      the axis of the latest entry as reference face and the other polygon, as mapped for the face loops, moved
///      by its relative motion up to that time: its vertices on the face's line, an edge among them cut to the
///      face's extent (SweptContacts); a walked polygon's incident edge clipped as in Collide (Catto).
template <bool kContacts, typename S, typename Tracer>
SweepResultT<S> SweepPolygons(const PolygonT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const PolygonT<S>& b,
                              const TransformT<S>& xfB, Vec2T<S> vB, Tracer& tracer)
{
    const Vec2T<S> velocity = vB - vA;
    const Vec2T<S> velocityInA = InvRotate(xfA.q, velocity);
    const Vec2T<S> velocityInB = InvRotate(xfB.q, velocity);

    // The one object every return statement returns, so that it is built where the caller wants it (named return
    // value): built here and copied out, its 16-byte copies straddled the stores that had just filled it, which
    // stalled store forwarding as often as the frame's layout made them straddle (Sweep of triangles took 0.95 of
    // the time without the copy).
    SweepResultT<S> result;
#if SATVIZ_WIDE
    if constexpr (Tracer::kWide512 && std::is_same_v<S, double>)
    {
        if (a.Count() <= 8 && b.Count() <= 8)
        {
            // The verdict maps both polygons into registers; the incident polygons are built from them only for a hit.
            const TransformT<S> bInA = InvMulTransforms(xfA, xfB);
            const TransformT<S> aInB = InvMulTransforms(xfB, xfA);
            const SmallSweepVerdict verdict = SmallSweep512(a, b, bInA, aInB, velocityInA, velocityInB);
            if (!verdict.going)
            {
                return result;
            }
            if (verdict.state.inside)
            {
                // Collide's second pass skips B's faces anti-parallel to one of A's.
                const uint64_t skip = AlgorithmChoices::kSkipParallel
                                          ? AntiParallelFaces(a, b, InvMulRot(aInB.q, RotT<S>{}))
                                          : uint64_t(0);
                const Lanes8 sepB = verdict.sepB.Replace(static_cast<int>(skip & 0xFF), -kInfinity<S>);
                SetInitial<kContacts>(ManifoldFromSeparations512<kContacts>(a, xfA, b, xfB, bInA, aInB, verdict.mapped,
                                                                            verdict.sepA, sepB),
                                      result);
                return result;
            }
            const IncidentPolygon<S> incB = MappedIncidentPolygon(b, bInA, verdict.mapped.bx, verdict.mapped.by);
            const IncidentPolygon<S> incA = MappedIncidentPolygon(a, aInB, verdict.mapped.ax, verdict.mapped.ay);
            HitResult<kContacts, Tracer::kWide>(a, xfA, vA, b, xfB, vB, incA, incB, velocityInA, velocityInB,
                                                verdict.state, result);
            return result;
        }
    }
#endif
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, std::bool_constant<Tracer::kWide>{});
    SweepLanes<Lanes<S, Tracer::kWide && std::is_same_v<S, double>>, S> lanes;
    SweepState<S> view; // the recorder's view: the latest entry and earliest exit so far, and why the test ended
    const auto finish = [&]() {
        if constexpr (Tracer::kEnabled)
        {
            tracer.Finish(view.exit);
        }
    };
    // A hit: the time of impact, the axis and normal, and (kContacts) the contact points.
    const auto hit = [&](const IncidentPolygon<S>& incA, const SweepState<S>& state) {
        HitResult<kContacts, Tracer::kWide>(a, xfA, vA, b, xfB, vB, incA, incB, velocityInA, velocityInB, state,
                                            result);
    };
    // A lower bound of the latest entry, and what the bounded face loops leave for their second pass.
    S known = S(0);
    WalkedSweep<S> walkA;
    WalkedSweep<S> walkB;
    KeptSeparations<decltype(lanes.first)> keptA;
    KeptSeparations<decltype(lanes.first)> keptB;
    if (!SweepFaces(a, incB, 0, velocityInA, lanes, view, tracer, known, walkA, keptA))
    {
        finish();
        return result;
    }
    // A's faces did not rule a hit out: now B's, with A mapped into B's frame.
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, std::bool_constant<Tracer::kWide>{});
    bool going = SweepFaces(b, incA, 1, -velocityInB, lanes, view, tracer, known, walkB, keptB);
    // Bounded face loops: the exits their first pass left, now that the latest entry is known.
    going = going && !(walkA.walked && !SweepBoundedExits(a, incB, 0, velocityInA, lanes, walkA, view, tracer));
    going = going && !(walkB.walked && !SweepBoundedExits(b, incA, 1, -velocityInB, lanes, walkB, view, tracer));
    finish();
    if (!going)
    {
        return result;
    }
    SweepState<S> state;
    lanes.Combine(state);
    if (state.inside)
    {
        SetInitial<kContacts>(keptA.kept && keptB.kept ? InterpenetratingManifold<Tracer::kWide, kContacts>(
                                                             a, xfA, b, xfB, incA, incB, keptA, keptB)
                                                       : Collide(a, xfA, b, xfB),
                              result);
        return result;
    }

    hit(incA, state);
    return result;
}

// First time the point p0 + t v enters the disc of radius r around c, if it crosses the circle (a tangent path
// only touches it): the stable root of |p0 + t v - c|^2 = r^2 (Ericson 5.3.2). A point on the circle, or inside it
// by rounding (the caller has ruled out a real overlap), that heads inwards enters at 0; heading along the circle
// as far as the rounding of b = Dot(p0 - c, v) can tell (StillRate), or on a path tangent to it as far as the
// rounding of the discriminant can tell (a circle sliding along a face passes over the vertex at its end so), it
// does not enter.
template <typename S>
S EnterDisc(Vec2T<S> p0, Vec2T<S> v, Vec2T<S> c, S r)
{
    const Vec2T<S> f = p0 - c;
    const S b = Dot(f, v);
    const S outside = Dot(f, f) - r * r;
    const S scale = std::max({std::abs(f.x), std::abs(f.y), r});
    if (b >= -scale * StillRate(v))
    {
        return kInfinity<S>;
    }
    if (outside <= S(0))
    {
        return S(0);
    }
    // A path tangent to the circle, as far as the rounding of the discriminant can tell, only touches it.
    const S speed2 = Dot(v, v);
    const S discriminant = b * b - speed2 * outside;
    if (discriminant <= S(16) * std::numeric_limits<S>::epsilon() * (Dot(f, f) + r * r) * speed2)
    {
        return kInfinity<S>;
    }
    return outside / (-b + std::sqrt(discriminant));
}

/// A circle of radius r, centre p0 moving by v, against a polygon (both in the polygon's frame): the first time
/// the centre enters the polygon rounded by r (the Minkowski sum of the polygon and the disc). Its boundary is
/// the faces pushed out by r and arcs of radius r around the vertices, so the first entry is the earliest of: a
/// crossing of a pushed-out face within the face's extent, or an entry into a vertex's disc. Returns the time
/// (infinity for none) and the unit normal out of the polygon at the contact.
template <typename S>
S CastRounded(const PolygonT<S>& polygon, Vec2T<S> p0, Vec2T<S> v, S r, Vec2T<S>& normal, AxisRef& axis, int side)
{
    S best = kInfinity<S>;
    const S still = StillRate(v);
    for (int i = 0; i < polygon.Count(); ++i)
    {
        const Vec2T<S> n = polygon.Normal(i);
        const S separation = Dot(n, p0 - polygon.Vertices()[i]) - r;
        const S rate = Dot(n, v);
        // A centre behind the pushed-out face by no more than rounding (touching) that heads in crosses it at 0,
        // if within the face's extent; one moving along the face (StillRate) never crosses it.
        const S rounding = S(16) * std::numeric_limits<S>::epsilon() *
                           std::max({std::abs(p0.x), std::abs(p0.y), std::abs(polygon.Vertices()[i].x),
                                     std::abs(polygon.Vertices()[i].y), r});
        if (separation < -rounding || rate >= -still)
        {
            continue;
        }
        const S t = std::max(S(0), separation / -rate);
        const Vec2T<S> along = p0 + t * v - polygon.Vertices()[i];
        const S u = Dot(along, polygon.Edge(i));
        if (t < best && u >= S(0) && u <= LengthSquared(polygon.Edge(i)))
        {
            best = t;
            normal = n;
            axis = {AxisKind::FaceNormal, side, i};
        }
    }
    for (int k = 0; k < polygon.Count(); ++k)
    {
        const S t = EnterDisc(p0, v, polygon.Vertices()[k], r);
        if (t < best)
        {
            best = t;
            normal = Normalize(p0 + t * v - polygon.Vertices()[k]);
            axis = {AxisKind::VertexToCenter, side, k};
        }
    }
    return best;
}

} // namespace
} // namespace detail

namespace
{
// The untraced polygon sweep as one function: everything it calls is inlined into it, which keeps the fast path's
// code together.
template <bool kContacts, typename S>
[[gnu::flatten]] SweepResultT<S> SweepPolygonsUntraced(const PolygonT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA,
                                                       const PolygonT<S>& b, const TransformT<S>& xfB, Vec2T<S> vB)
{
    detail::NullSweepTracer tracer;
    return detail::SweepPolygons<kContacts>(a, xfA, vA, b, xfB, vB, tracer);
}

#if SATVIZ_WIDE
// The same, compiled for AVX2 with the wide scans.
template <bool kContacts, typename S>
[[gnu::target("avx2"), gnu::flatten]] SweepResultT<S> SweepPolygonsWide(const PolygonT<S>& a, const TransformT<S>& xfA,
                                                                        Vec2T<S> vA, const PolygonT<S>& b,
                                                                        const TransformT<S>& xfB, Vec2T<S> vB)
{
    detail::WideNullSweepTracer tracer;
    return detail::SweepPolygons<kContacts>(a, xfA, vA, b, xfB, vB, tracer);
}

// The same for polygons of up to 8 vertices, whose face loops also take 512-bit vectors (AVX-512).
template <bool kContacts>
[[gnu::target("avx2,avx512f"), gnu::flatten]] SweepResultT<double>
SweepPolygonsWide512(const PolygonT<double>& a, const TransformT<double>& xfA, Vec2T<double> vA,
                     const PolygonT<double>& b, const TransformT<double>& xfB, Vec2T<double> vB)
{
    detail::Wide512NullSweepTracer tracer;
    return detail::SweepPolygons<kContacts>(a, xfA, vA, b, xfB, vB, tracer);
}
#endif

// Sweep (kContacts) and SweepTime: one body, the contact points of a hit computed or not.
template <bool kContacts, typename S>
SweepResultT<S> SweepShapes(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                            const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    using detail::Initial;
    if (trace != nullptr)
    {
        trace->Clear();
    }
    const Vec2T<S> velocity = vB - vA;
    if (velocity.x == S(0) && velocity.y == S(0))
    {
        // Nothing moves relative to the other: the static test decides, and no sweep is run.
        if (trace != nullptr)
        {
            trace->exit = SweepExit::NotMoving;
        }
        return Initial<kContacts>(Collide(a, xfA, b, xfB));
    }

    if (a.type == ShapeType::Polygon && b.type == ShapeType::Polygon)
    {
        if (trace == nullptr)
        {
#if SATVIZ_WIDE
            if constexpr (std::is_same_v<S, double>)
            {
                if (detail::HasWide512() && a.polygon.Count() <= 8 && b.polygon.Count() <= 8)
                {
                    return SweepPolygonsWide512<kContacts>(a.polygon, xfA, vA, b.polygon, xfB, vB);
                }
            }
            if (detail::HasWideVectors())
            {
                return SweepPolygonsWide<kContacts>(a.polygon, xfA, vA, b.polygon, xfB, vB);
            }
#endif
            return SweepPolygonsUntraced<kContacts>(a.polygon, xfA, vA, b.polygon, xfB, vB);
        }
        detail::SweepRecorder<S> tracer(*trace, {&a.polygon, nullptr}, xfA, {&b.polygon, nullptr}, xfB, velocity);
        return detail::SweepPolygons<kContacts>(a.polygon, xfA, vA, b.polygon, xfB, vB, tracer);
    }

    // Circle pairs: the static test first (interpenetrating at t = 0), then the centre's path against the rounded
    // outline of the other shape, in that shape's frame.
    const ManifoldT<S> initial = Collide(a, xfA, b, xfB);
    if (initial.overlap && initial.depth > S(0))
    {
        if (trace != nullptr)
        {
            trace->exit = SweepExit::AllAxesOverlap;
        }
        return Initial<kContacts>(initial);
    }
    const bool circleA = a.type == ShapeType::Circle;
    const CircleT<S>& circle = circleA ? a.circle : b.circle;
    const ShapeT<S>& other = circleA ? b : a;
    const TransformT<S>& xfCircle = circleA ? xfA : xfB;
    const TransformT<S>& xfOther = circleA ? xfB : xfA;
    const Vec2T<S> vCircle = circleA ? vA : vB;
    const Vec2T<S> vOther = circleA ? vB : vA;
    const int otherSide = circleA ? 1 : 0;

    // The circle's centre and motion relative to the other shape, in its frame.
    const Vec2T<S> p0 = InvRotate(xfOther.q, (xfCircle.p - xfOther.p) + Rotate(xfCircle.q, circle.center));
    const Vec2T<S> v = InvRotate(xfOther.q, vCircle - vOther);
    Vec2T<S> normal{};
    AxisRef axis{};
    S t;
    if (other.type == ShapeType::Polygon)
    {
        t = detail::CastRounded(other.polygon, p0, v, circle.radius, normal, axis, otherSide);
    }
    else
    {
        t = detail::EnterDisc(p0, v, other.circle.center, circle.radius + other.circle.radius);
        normal = Normalize(p0 + t * v - other.circle.center);
        axis = {AxisKind::CenterToCenter, -1, -1};
    }
    if (trace != nullptr)
    {
        // The axes of the rounded outline: the polygon's face normals (or the line of centres), oriented from A to
        // B, then the vertex axis that decided a hit on a rounded corner. The decision itself is the cast.
        auto ref = [](const ShapeT<S>& shape) {
            return shape.type == ShapeType::Polygon ? detail::ShapeRef<S>{&shape.polygon, nullptr}
                                                    : detail::ShapeRef<S>{nullptr, &shape.circle};
        };
        detail::SweepRecorder<S> tracer(*trace, ref(a), xfA, ref(b), xfB, velocity);
        const S orient = circleA ? S(-1) : S(1);
        if (other.type == ShapeType::Polygon)
        {
            for (int i = 0; i < other.polygon.Count(); ++i)
            {
                tracer.AxisFromShapes({AxisKind::FaceNormal, otherSide, i},
                                      orient * Rotate(xfOther.q, other.polygon.Normal(i)));
            }
        }
        else
        {
            const Vec2T<S> centers = TransformPoint(xfB, b.circle.center) - TransformPoint(xfA, a.circle.center);
            tracer.AxisFromShapes({AxisKind::CenterToCenter, -1, -1}, Normalize(centers));
        }
        if (axis.kind == AxisKind::VertexToCenter && t <= S(1))
        {
            tracer.AxisFromShapes(axis, orient * Rotate(xfOther.q, normal));
        }
        tracer.Finish(SweepExit::RoundedOutline);
    }
    SweepResultT<S> result;
    if (!(t <= S(1)))
    {
        return result;
    }
    result.status = SweepStatus::Hit;
    result.toi = t;
    result.axis = axis;
    // The normal points out of the other shape towards the circle; from A to B it is reversed when A is the circle.
    const Vec2T<S> worldNormal = Rotate(xfOther.q, normal);
    result.normal = circleA ? -worldNormal : worldNormal;
    if constexpr (kContacts)
    {
        result.contactCount = 1;
        result.contacts[0].point =
            TransformPoint(detail::Moved(xfOther, vOther, t), p0 + t * v - circle.radius * normal);
    }
    return result;
}
} // namespace

template <typename S>
SweepResultT<S> Sweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                      const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    return SweepShapes<true>(a, xfA, vA, b, xfB, vB, trace);
}

template <typename S>
SweepResultT<S> SweepTime(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                          const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    return SweepShapes<false>(a, xfA, vA, b, xfB, vB, trace);
}

template SweepResultT<double> Sweep(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                    const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                    SweepTraceT<double>*);
template SweepResultT<float> Sweep(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>, const ShapeT<float>&,
                                   const TransformT<float>&, Vec2T<float>, SweepTraceT<float>*);
template SweepResultT<double> SweepTime(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                        const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                        SweepTraceT<double>*);
template SweepResultT<float> SweepTime(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                       const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                       SweepTraceT<float>*);

} // namespace satviz
