// SPDX-License-Identifier: MIT
// satviz (private), chapter 12: the face loop of the sweep against a large polygon. A point of the walked polygon
// bounds every face's separation, so only the faces that can decide are walked to, in two passes: the entries, then
// the exits that could come before the latest entry.
#pragma once

#include "incident_polygon.h"
#include "lanes.h"
#include "support.h"
#include "sweep_axis.h"
#include "sweep_faces.h"

#include <satviz/polygon.h>

#include <algorithm>
#include <limits>

namespace satviz::detail
{

// For the trace only: face i of `ref` as the face loops would evaluate it, for a face they decided without
// evaluating it: its exact separation (inc's support point searched for alone), its rate, and its entry and exit as
// the lanes compute them (AxisLanes; the trace shows an overlapping axis as entering at 0, as the recorder does).
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
    return EndPass(tracer, view, !ends && !(lanes.first.MaxLane() >= lanes.last.MinLane()));
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
        return EndPass(tracer, view, false);
    }
    return EndPass(tracer, view, !(first >= lanes.last.MinLane()));
}

} // namespace satviz::detail
