// SPDX-License-Identifier: MIT
// satviz (private), chapter 13: the face loop of the sweep of a polygon too large to pass over. Only the faces beside
// the two places where the line of the motion crosses the Minkowski difference, and those along the motion, can
// decide; bisection finds them.
#pragma once

#include "incident_polygon.h"
#include "support.h"
#include "sweep_axis.h"
#include "sweep_faces.h"
#include "sweep_walked.h"

#include <satviz/polygon.h>

#include <algorithm>
#include <type_traits>
#include <utility>
#include <vector>

namespace satviz::detail
{

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
            return EndPass(tracer, view, false);
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
            return EndPass(tracer, view, false);
        }
    }
    for (int f = Next(backLast, n), k = 0; f != frontFirst && k < n; f = Next(f, n), ++k)
    {
        if (evaluation.Add(f, backLastSupport, backLastSupport))
        {
            return EndPass(tracer, view, false);
        }
    }
    return EndPass(tracer, view, !evaluation.Flush() && !(lanes.first.MaxLane() >= lanes.last.MinLane()));
}

} // namespace satviz::detail
