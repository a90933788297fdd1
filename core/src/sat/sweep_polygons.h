// SPDX-License-Identifier: MIT
// satviz (private), chapter 15: the sweep of two translating polygons (Ericson 5.5.2): the face loops of both
// polygons, which loop runs for a pair of sizes, and the verdict: a miss, a start where the shapes interpenetrate,
// or a hit at the time of impact with its contacts.
#pragma once

#include "cpu_dispatch.h"
#include "face_query.h"
#include "incident_polygon.h"
#include "lanes.h"
#include "select.h"
#include "sweep512.h"
#include "sweep_bisected.h"
#include "sweep_contacts.h"
#include "sweep_faces.h"
#include "sweep_walked.h"
#include "tracer.h"

#include <satviz/collide.h>
#include <satviz/polygon.h>
#include <satviz/sweep.h>

#include <cstdint>
#include <type_traits>

namespace satviz::detail
{

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
// before, while a pass over the faces reads ahead: the bisection pays only on polygons of some hundreds of faces,
// sooner when they are in the cache than when they come from memory; this lies between the two (SweepTime of
// same-sized pairs, tests/bench/README.md).
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
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, MapInLanes<Tracer::kWide>{});
    SweepLanes<Lanes<S, Tracer::kWide && std::is_same_v<S, double>>, S> lanes;
    SweepState<S> view; // for the recorder: why the test ended
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
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, MapInLanes<Tracer::kWide>{});
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

} // namespace satviz::detail
