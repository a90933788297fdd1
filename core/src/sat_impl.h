// SPDX-License-Identifier: MIT
// satviz (private): the Separating Axis Theorem, written once as templates over the scalar type and a tracer.
//
// References:
//   C. Ericson, Real-Time Collision Detection (2005), 5.2.1 (separating-axis test), 5.2.6 (circle against
//     polygon, Voronoi regions), 5.1.1 (closest point).
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (face queries with support points,
//     reference face and incident edge, clipping).
//   E. Catto, "Contact Manifolds", GDC 2007 (clipping the incident edge against the reference face's side planes).
#pragma once

#include "sat/cpu_dispatch.h"
#include "sat/face_blocks.h"
#include "sat/face_query_dispatch.h"
#include "sat/incident_polygon.h"
#include "sat/lanes.h"
#include "sat/lanes2.h"
#include "sat/overlap512.h"
#include "sat/select.h"
#include "sat/support.h"
#include "sat/tracer.h"

#include <satviz/manifold.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

// ---------------------------------------------------------------------------------------------------------------
// Polygon against polygon
// ---------------------------------------------------------------------------------------------------------------

/// Overlap of two polygons (Ericson 5.2.1; Gregorius).
/// Outline:
///   0. Both polygons of at most 8 vertices: A's faces against B mapped into A's frame, four faces at a time in
///      lanes (SmallFacesSeparate); a separating face ends the test; otherwise B's faces against A mapped into B's
///      frame, anti-parallel faces skipped. One branch per polygon instead of one per face: on random pairs this
///      took 0.78 of the time of steps 1 to 3 for 8-gons (satviz-bench), vertex shortcut included. With AVX-512
///      (Tracer::kWide512, SmallPolygonsOverlap512) each polygon's faces fit one register and cost so little that
///      both polygons are tested and decided by one branch: the branch between them, mispredicted on about half of
///      the pairs, cost more than B's faces (8-gons without it: 0.87 to 0.94 of the time, on random contact pairs).
///      Larger polygons:
///   1. Face query of A's faces against B mapped into A's frame, stopping at the first separating face. A walked A
///      tests only the run of faces that see the witness (B's support point for A's first face): every other face
///      has the witness on its inner side, so its separation is <= 0. The wedge of A's fan that holds the witness,
///      found by bisection (WedgeOf), tells whether the run is empty and where it is: O(log n) plus the run,
///      instead of a pass over every face.
///   2. A scanned B (kScanLimit vertices or fewer) also yields, per vertex of B, its largest separation from A's
///      faces, from the same projections. A vertex of B whose largest separation is <= 0 lies inside A: the
///      polygons share a point, so they overlap, and B's faces need no test. For polygons above 8 vertices this is
///      the usual way out of an overlapping pair (a corner of B pushed into A). A walked B offers one candidate,
///      the witness: it lies inside A when the run is empty (step 1 found that out anyway).
///   3. Otherwise the face query of B's faces against A, stopping at the first separating face; no separating face
///      on either polygon means overlap.
template <typename S, typename Tracer>
bool OverlapPolygons(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                     Tracer& tracer)
{
#if SATVIZ_WIDE
    if constexpr (Tracer::kWide512 && !Tracer::kEnabled && !Tracer::kPrune && Tracer::kScanLimit >= 8 &&
                  std::is_same_v<S, double>)
    {
        if (a.Count() > 0 && a.Count() <= 8 && b.Count() > 0 && b.Count() <= 8)
        {
            return SmallPolygonsOverlap512(a, xfA, b, xfB, Tracer::kSkipParallel);
        }
    }
#endif
    const IncidentPolygon<S> incB(b, xfA, xfB, Tracer::kScanLimit, std::bool_constant<Tracer::kWide>{});
    if constexpr (!Tracer::kPrune)
    {
        if (incB.scan && a.Count() <= 8 && b.Count() <= 8)
        {
            bool separated = SmallFacesSeparate(a, incB, 0, false, tracer);
            if (!separated || !Tracer::kEarlyExit)
            {
                const IncidentPolygon<S> incA(a, xfB, xfA, Tracer::kScanLimit, std::bool_constant<Tracer::kWide>{});
                separated = SmallFacesSeparate(b, incA, 1, true, tracer) || separated;
            }
            if constexpr (Tracer::kEnabled)
            {
                ManifoldT<S> result;
                result.overlap = !separated;
                tracer.Finish(separated ? TraceExit::SeparatingAxis : TraceExit::AllAxesOverlap, result);
            }
            return !separated;
        }
    }
    // Pruned faces would leave gaps in the vertices' largest separations, so pruning turns the shortcut off.
    constexpr bool kInside = !Tracer::kPrune;
    alignas(32) S inside[IncidentPolygon<S>::kCapacity];
    if constexpr (kInside)
    {
        std::fill(inside, inside + incB.padded, -std::numeric_limits<S>::infinity());
    }
    const FaceQuery<S> queryA = QueryFaces<false, kInside>(a, incB, 0, false, S(0), tracer, inside);
    bool overlap = !queryA.separated;
    if (kInside && overlap)
    {
        int contained = -1;
        if (incB.scan)
        {
            for (int j = b.Count() - 1; j >= 0; --j)
            {
                contained = Select(inside[j] <= S(0), j, contained);
            }
        }
        else if (queryA.witnessInside)
        {
            // Walked: the witness, B's support point for A's first face, lay on or inside every face of A.
            contained = queryA.witness;
        }
        if (contained >= 0)
        {
            if constexpr (Tracer::kEnabled)
            {
                ManifoldT<S> result;
                result.overlap = true;
                tracer.ContainedVertex(1, contained);
                tracer.Finish(TraceExit::VertexInside, result);
            }
            return true;
        }
    }
    if (overlap || !Tracer::kEarlyExit)
    {
        const IncidentPolygon<S> incA(a, xfB, xfA, Tracer::kScanLimit, std::bool_constant<Tracer::kWide>{});
        overlap = !QueryFaces<false>(b, incA, 1, true, S(0), tracer).separated && overlap;
    }
    if constexpr (Tracer::kEnabled)
    {
        ManifoldT<S> result;
        result.overlap = overlap;
        tracer.Finish(overlap ? TraceExit::AllAxesOverlap : TraceExit::SeparatingAxis, result);
    }
    return overlap;
}

/// Overlap with frame coherence (SatCache): the cached separating face alone first; if it no longer separates,
/// the full query, remembering the face that separates this time (or nothing when the polygons overlap).
///   1. Cached face i of polygon s, raw normal n (only the sign matters): the other polygon's support point in
///      direction -n, climbed from the cached support (ClimbFrom), and its separation Dot(n, w - v_i) in s's
///      frame. Positive: separated, done in O(1) steps when the pair moved a little.
///   2. Otherwise the face queries of A, then B (OverlapPolygons), keeping the separating face they stop at and
///      its support point.
template <typename S>
bool OverlapPolygonsCached(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                           const TransformT<S>& xfB, AxisRef& cached, int& cachedSupport)
{
    if (cached.kind == AxisKind::FaceNormal && (cached.shape == 0 || cached.shape == 1))
    {
        const PolygonT<S>& ref = cached.shape == 0 ? a : b;
        const PolygonT<S>& inc = cached.shape == 0 ? b : a;
        if (cached.index >= 0 && cached.index < ref.Count())
        {
            const TransformT<S> incInRef = cached.shape == 0 ? InvMulTransforms(xfA, xfB) : InvMulTransforms(xfB, xfA);
            const Vec2T<S> normal = RightPerp(ref.Edge(cached.index));
            const int start = cachedSupport >= 0 && cachedSupport < inc.Count() ? cachedSupport : 0;
            const int support = ClimbFrom(inc, InvRotate(incInRef.q, -normal), start);
            const S separation =
                Dot(normal, TransformPoint(incInRef, inc.vertices[support]) - ref.vertices[cached.index]);
            cachedSupport = support;
            if (separation > S(0))
            {
                return false;
            }
        }
    }
    NullTracer tracer;
    const IncidentPolygon<S> incB(b, xfA, xfB);
    FaceQuery<S> query = QueryFaces<false>(a, incB, 0, false, S(0), tracer);
    if (query.separated)
    {
        cached = {AxisKind::FaceNormal, 0, query.face};
        cachedSupport = query.support;
        return false;
    }
    const IncidentPolygon<S> incA(a, xfB, xfA);
    query = QueryFaces<false>(b, incA, 1, true, S(0), tracer);
    if (query.separated)
    {
        cached = {AxisKind::FaceNormal, 1, query.face};
        cachedSupport = query.support;
        return false;
    }
    cached = {};
    cachedSupport = -1;
    return true;
}

/// The incident edge of a scanned inc against a reference face of unit normal `normal` (reference frame): the edge
/// whose outward normal is most anti-parallel to it, the first on a tie. Along a convex outline the normals turn
/// one way, so the two closest in angle to -normal are those of the edges at the support vertex in direction
/// -normal, and this is the better of those two. One scan of all the normals (in inc's frame, four per step) and
/// no support point first: a shorter chain of dependent steps than finding the support vertex, then comparing.
template <bool kWide = false, typename S>
int ScannedIncidentEdge(const IncidentPolygon<S>& inc, Vec2T<S> normal)
{
    using L = Lanes<S, kWide && std::is_same_v<S, double>>;
    const Vec2T<S> d = InvRotate(inc.xf.q, normal);
    const L dx = L::Fill(d.x);
    const L dy = L::Fill(d.y);
    const int count = inc.polygon.Count();
    const Vec2T<S>* normals = &inc.polygon.Normal(0);
    // Four normals from j as lanes, the last normal repeated past the end (which moves no first minimum).
    const auto dots = [&](int j) {
        L nx;
        L ny;
        if (j + 4 <= count)
        {
            L::LoadPoints(&normals[j].x, nx, ny);
        }
        else
        {
            const int j0 = std::min(j, count - 1);
            const int j1 = std::min(j + 1, count - 1);
            const int j2 = std::min(j + 2, count - 1);
            const int j3 = std::min(j + 3, count - 1);
            nx = L::Set(normals[j0].x, normals[j1].x, normals[j2].x, normals[j3].x);
            ny = L::Set(normals[j0].y, normals[j1].y, normals[j2].y, normals[j3].y);
        }
        return dx * nx + dy * ny;
    };
    uint32_t hits = 0;
    if (count <= 8)
    {
        // Up to eight normals, held in registers: the shortest chain from the face to the edge.
        const L dots0 = dots(0);
        const L dots1 = dots(4);
        const L least = L::Fill(Min(dots0, dots1).MinLane());
        hits = static_cast<uint32_t>((dots0 == least).Bits()) | static_cast<uint32_t>((dots1 == least).Bits()) << 4;
    }
    else
    {
        alignas(32) S stored[IncidentPolygon<S>::kCapacity];
        L low = L::Fill(std::numeric_limits<S>::infinity());
        for (int j = 0; j < count; j += 4)
        {
            const L block = dots(j);
            block.Store(stored + j);
            low = Min(low, block);
        }
        const L least = L::Fill(low.MinLane());
        for (int j = 0; j < count; j += 4)
        {
            hits |= static_cast<uint32_t>((L::Load(stored + j) == least).Bits()) << j;
        }
    }
    return hits != 0 ? __builtin_ctz(hits) : 0; // no hit only for NaN input
}

/// Contact points from clipping, in the reference polygon's frame, with what the trace shows of the clipping.
/// The arrays are valid up to their counts and left uninitialised beyond: zeroing the whole struct cost a block
/// store (rep stos) per manifold, about a tenth of Collide's time for 8-gons.
template <typename S>
struct ClipResult
{
    ContactPointT<S> contacts[2]; ///< halfway between the kept points and the reference face
    int contactCount = 0;         ///< 1 or 2
    int incidentEdge = -1;        ///< the incident edge
    Vec2T<S> w1, w2;              ///< incident edge, reference frame
    Vec2T<S> clip1[2];            ///< after the side plane through the face's first vertex
    int count1 = 0;               ///< points in clip1
    Vec2T<S> clip2[2];            ///< then after the side plane through its second vertex
    int count2 = 0;               ///< points in clip2
    S separations[2];             ///< of the clip2 points to the reference face
    bool kept[2];                 ///< clip2 points kept as contacts
    bool fallback = false;        ///< no point kept: the deepest incident vertex was used
};

/// Contact points of a reference face (Catto; Gregorius):
///   1. Incident edge: the edge of the incident polygon whose normal is most anti-parallel to the reference normal.
///      One of the two edges at the support vertex against the face: a scanned polygon compares all its normals
///      (ScannedIncidentEdge) and reads the edge's ends from its mapped vertices; a walked one compares the two
///      edges at `support`.
///   2. Clip it against the two side planes of the reference face (Sutherland-Hodgman), without branches.
///   3. Keep the clipped points whose separation from the face is at most `keepBelow` (0 for resting contact; a
///      little more at a time of impact, where touching points carry rounding of either sign). The contact point
///      is halfway between the kept point and the reference face.
///   4. If clipping keeps nothing (a rounding artefact at a vertex-vertex contact), use the deepest vertex: the
///      support vertex, or the deeper end of the incident edge, which is that vertex.
/// `support` is the incident support vertex if known, else -1. `shift`, if given, moves the incident polygon by that
/// much (reference frame) before clipping: a sweep clips at the time of impact with the polygon mapped at t = 0.
template <bool kWide = false, typename S>
ClipResult<S> ClipIncidentEdge(const PolygonT<S>& ref, int face, const IncidentPolygon<S>& inc, int support,
                               S keepBelow, const Vec2T<S>* shift = nullptr)
{
    ClipResult<S> out;
    const int m = inc.polygon.Count();
    const Vec2T<S> v1 = ref.vertices[face];
    const Vec2T<S> v2 = ref.vertices[Next(face, ref.Count())];
    const Vec2T<S> normal = ref.Normal(face);
    const Vec2T<S> tangent = LeftPerp(normal);

    int s = support;
    if (inc.scan && support < 0)
    {
        out.incidentEdge = ScannedIncidentEdge<kWide>(inc, normal);
        out.w1 = {inc.x[out.incidentEdge], inc.y[out.incidentEdge]};
        out.w2 = {inc.x[out.incidentEdge + 1], inc.y[out.incidentEdge + 1]};
    }
    else
    {
        s = support >= 0 ? support : inc.template Support<kWide>(normal);
        const int before = Prev(s, m);
        const S dotLeaving = Dot(normal, Rotate(inc.xf.q, inc.polygon.Normal(s)));
        const S dotEntering = Dot(normal, Rotate(inc.xf.q, inc.polygon.Normal(before)));
        out.incidentEdge = Select(dotEntering < dotLeaving, before, s);
        out.w1 = TransformPoint(inc.xf, inc.polygon.vertices[out.incidentEdge]);
        out.w2 = TransformPoint(inc.xf, inc.polygon.vertices[Next(out.incidentEdge, m)]);
    }
    if (shift != nullptr)
    {
        out.w1 = out.w1 + *shift;
        out.w2 = out.w2 + *shift;
    }
    // Clipping, both ends of the incident edge side by side in two lanes (lane 0: w1, lane 1: w2), so that each step
    // is one operation for both ends and each choice a mask: where an edge lies against the side planes varies from
    // pair to pair, and branches on it were mispredicted often enough to cost more than the clipping itself. An end
    // outside a side plane moves to the plane's crossing when the other end lies strictly inside; an end on a plane
    // stays, and an edge that only touches a plane keeps that one point.
    using P = Lanes2<S>;
    using M = typename P::Mask;
    const P x = P::Set(out.w1.x, out.w2.x);
    const P y = P::Set(out.w1.y, out.w2.y);
    const P zero = P::Fill(S(0));
    // How far each end lies outside side plane 1 (outward -tangent, through v1) and side plane 2 (outward tangent,
    // through v2); > 0 outside.
    const P d1 = P::Fill(-tangent.x) * (x - P::Fill(v1.x)) + P::Fill(-tangent.y) * (y - P::Fill(v1.y));
    const P d2 = P::Fill(tangent.x) * (x - P::Fill(v2.x)) + P::Fill(tangent.y) * (y - P::Fill(v2.y));
    // A plane is crossed strictly when one end lies inside it and the other outside (the same in both lanes).
    const auto crossed = [zero](const P& d) {
        const M below = d < zero;
        const M above = d > zero;
        return (below & above.Swap()) | (above & below.Swap());
    };
    const M cross1 = crossed(d1);
    const M cross2 = crossed(d2);
    const M inside1 = d1 <= zero;
    const M inside2 = d2 <= zero;
    // The crossing, from each end towards the other: at d / (d - d_other) of the way where the plane is crossed
    // strictly (so d - d_other is not 0); elsewhere the divisor is 1, so no infinity or NaN is ever formed, and the
    // number, though computed, is kept only in entries past the counts.
    const P towardX = x.Swap() - x;
    const P towardY = y.Swap() - y;
    const P one = P::Fill(S(1));
    const P t1 = d1 / Select(cross1, d1 - d1.Swap(), one);
    const P t2 = d2 / Select(cross2, d2 - d2.Swap(), one);
    // The first plane alone (the trace's first clip), then both: an end moves when it lies outside either plane
    // (they face opposite ways, so not both), to that plane's crossing.
    const P x1 = Select(inside1, x, x + t1 * towardX);
    const P y1 = Select(inside1, y, y + t1 * towardY);
    const M moves = ~(inside1 & inside2);
    const P t = Select(inside2, t1, t2);
    const P x2 = Select(moves, x + t * towardX, x);
    const P y2 = Select(moves, y + t * towardY, y);
    const M keep1 = inside1 | cross1;
    const M keep2 = keep1 & (inside2 | (cross2 & (d2 < zero).Swap()));
    // Each clipped end's separation from the face, and whether it is kept as a contact.
    const P separation = P::Fill(normal.x) * (x2 - P::Fill(v1.x)) + P::Fill(normal.y) * (y2 - P::Fill(v1.y));
    const int valid = (keep2 & (separation <= P::Fill(keepBelow))).Bits();
    // The contact points, halfway between the kept ends and the face; the first one is the first valid end.
    const P half = P::Fill(S(0.5)) * separation;
    const P cx = x2 - half * P::Fill(normal.x);
    const P cy = y2 - half * P::Fill(normal.y);
    const bool firstEnd = (valid & 1) != 0;
    out.contactCount = (valid & 1) + (valid >> 1);
    out.contacts[0].point = Select(firstEnd, Vec2T<S>{cx.Get(0), cy.Get(0)}, Vec2T<S>{cx.Get(1), cy.Get(1)});
    out.contacts[0].separation = Select(firstEnd, separation.Get(0), separation.Get(1));
    out.contacts[1].point = {cx.Get(1), cy.Get(1)};
    out.contacts[1].separation = separation.Get(1);
    // What the trace shows: the points after each plane, listed from w1's end, and which of the second are kept.
    const int kept1 = keep1.Bits();
    const int kept2 = keep2.Bits();
    out.count1 = (kept1 & 1) + (kept1 >> 1);
    out.clip1[0] = (kept1 & 1) != 0 ? Vec2T<S>{x1.Get(0), y1.Get(0)} : Vec2T<S>{x1.Get(1), y1.Get(1)};
    out.clip1[1] = {x1.Get(1), y1.Get(1)};
    out.count2 = (kept2 & 1) + (kept2 >> 1);
    out.clip2[0] = (kept2 & 1) != 0 ? Vec2T<S>{x2.Get(0), y2.Get(0)} : Vec2T<S>{x2.Get(1), y2.Get(1)};
    out.clip2[1] = {x2.Get(1), y2.Get(1)};
    out.separations[0] = (kept2 & 1) != 0 ? separation.Get(0) : separation.Get(1);
    out.separations[1] = separation.Get(1);
    out.kept[0] = ((kept2 & 1) != 0 ? valid & 1 : valid >> 1) != 0;
    out.kept[1] = (kept2 & 1) != 0 && (valid >> 1) != 0;
    out.fallback = out.contactCount == 0;
    if (out.fallback)
    {
        // The support vertex; for a scanned inc, the deeper end of the incident edge, which is that vertex.
        Vec2T<S> deepest = Dot(normal, out.w2 - out.w1) < S(0) ? out.w2 : out.w1;
        if (s >= 0)
        {
            deepest = TransformPoint(inc.xf, inc.polygon.vertices[s]);
            if (shift != nullptr)
            {
                deepest = deepest + *shift;
            }
        }
        const S separation = Dot(normal, deepest - v1);
        out.contacts[0].point = deepest - (S(0.5) * separation) * normal;
        out.contacts[0].separation = separation;
        out.contactCount = 1;
    }
    return out;
}

/// Contact k of a clipping in world space (`xfRef`: the reference polygon's transform), or zero past the count.
template <typename S>
ContactPointT<S> WorldContact(const ClipResult<S>& clip, int k, const TransformT<S>& xfRef)
{
    const bool real = k < clip.contactCount;
    return {Select(real, TransformPoint(xfRef, clip.contacts[k].point), Vec2T<S>{}),
            Select(real, clip.contacts[k].separation, S(0))};
}

/// The trace's view of a clipping, in world space.
template <typename S>
ClipTraceT<S> ClipTraceOf(const ClipResult<S>& r, const AxisRef& reference, const PolygonT<S>& ref,
                          const TransformT<S>& xfRef, const PolygonT<S>& inc, const TransformT<S>& xfInc,
                          int incidentShape)
{
    ClipTraceT<S> clip;
    clip.reference = reference;
    clip.referenceV1 = TransformPoint(xfRef, ref.vertices[reference.index]);
    clip.referenceV2 = TransformPoint(xfRef, ref.vertices[Next(reference.index, ref.Count())]);
    clip.referenceNormal = Rotate(xfRef.q, ref.Normal(reference.index));
    clip.incidentShape = incidentShape;
    clip.incidentEdge = r.incidentEdge;
    clip.incidentV1 = TransformPoint(xfInc, inc.vertices[r.incidentEdge]);
    clip.incidentV2 = TransformPoint(xfInc, inc.vertices[Next(r.incidentEdge, inc.Count())]);
    clip.sideClip1Count = r.count1;
    clip.sideClip2Count = r.count2;
    for (int k = 0; k < r.count1; ++k)
    {
        clip.sideClip1[k] = TransformPoint(xfRef, r.clip1[k]);
    }
    for (int k = 0; k < r.count2; ++k)
    {
        clip.sideClip2[k] = TransformPoint(xfRef, r.clip2[k]);
        clip.clippedSeparation[k] = r.separations[k];
        clip.kept[k] = r.kept[k];
    }
    clip.usedFallback = r.fallback;
    return clip;
}

/// The manifold of two polygons (Gregorius; Catto).
/// Outline:
///   1. Work in A's frame: B relative to A, so far-away pairs keep their relative precision.
///   2. Face query of A's faces, then of B's faces (in B's frame); stop at the first separating face.
///   3. Reference face: the face of largest separation (least penetration), A's on a tie. Its unit normal is the
///      minimum translation direction and -separation the depth, also when one polygon contains the other.
///   4. Contacts (ClipIncidentEdge): clip the incident edge against the side planes of the reference face and keep
///      the points on or below it.
template <typename S, typename Tracer>
ManifoldT<S> CollidePolygons(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                             const TransformT<S>& xfB, Tracer& tracer)
{
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, std::bool_constant<Tracer::kWide>{});
    const FaceQuery<S> queryA = QueryFaces<true>(a, incB, 0, false, -std::numeric_limits<S>::infinity(), tracer);
    if (queryA.separated)
    {
        // Every member written once, so the result is not first cleared whole.
        const ManifoldT<S> manifold{false,
                                    S(0),
                                    queryA.separation,
                                    Rotate(xfA.q, a.Normal(queryA.face)),
                                    {},
                                    0,
                                    {AxisKind::FaceNormal, 0, queryA.face},
                                    -1};
        if constexpr (Tracer::kEnabled)
        {
            tracer.Finish(TraceExit::SeparatingAxis, manifold);
        }
        return manifold;
    }
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, std::bool_constant<Tracer::kWide>{});
    const FaceQuery<S> queryB = QueryFaces<true>(b, incA, 1, true, queryA.separation, tracer);
    if (queryB.separated)
    {
        const ManifoldT<S> manifold{false,
                                    S(0),
                                    queryB.separation,
                                    -Rotate(xfB.q, b.Normal(queryB.face)),
                                    {},
                                    0,
                                    {AxisKind::FaceNormal, 1, queryB.face},
                                    -1};
        if constexpr (Tracer::kEnabled)
        {
            tracer.Finish(TraceExit::SeparatingAxis, manifold);
        }
        return manifold;
    }

    // Reference face: B's only when strictly better, so ties (and skipped duplicates) keep A's face.
    const bool flip = queryB.separation > queryA.separation;
    const PolygonT<S>& ref = SelectRef(flip, b, a);
    const IncidentPolygon<S>& inc = SelectRef(flip, incA, incB);
    const TransformT<S>& xfRef = SelectRef(flip, xfB, xfA);
    const FaceQuery<S>& query = SelectRef(flip, queryB, queryA);

    const ClipResult<S> clip =
        ClipIncidentEdge<Tracer::kWide>(ref, query.face, inc, inc.scan ? -1 : query.support, S(0));
    const Vec2T<S> worldNormal = Rotate(xfRef.q, ref.Normal(query.face));
    const ManifoldT<S> manifold{true,
                                -query.separation,
                                S(0),
                                Select(flip, -worldNormal, worldNormal),
                                {WorldContact(clip, 0, xfRef), WorldContact(clip, 1, xfRef)},
                                clip.contactCount,
                                {AxisKind::FaceNormal, Select(flip, 1, 0), query.face},
                                clip.incidentEdge};

    if constexpr (Tracer::kEnabled)
    {
        tracer.Clip(ClipTraceOf(clip, manifold.axis, ref, xfRef, inc.polygon, flip ? xfA : xfB, flip ? 0 : 1));
        tracer.Finish(TraceExit::AllAxesOverlap, manifold);
    }
    return manifold;
}

// ---------------------------------------------------------------------------------------------------------------
// Polygon against circle
// ---------------------------------------------------------------------------------------------------------------

/// Polygon (side `polySide`) against circle (Ericson 5.2.6 and 5.1.1; the Voronoi regions of the polygon).
/// Outline:
///   1. Work in the polygon's frame: the circle's centre c relative to the polygon.
///   2. For each face: separation s_i = Dot(n_i, c - v_i) - r. s_i > 0 separates: stop (early exit).
///      Keep the face of largest separation.
///   3. If c lies inside the polygon, that face's normal is the axis of least penetration.
///   4. Otherwise c is in the Voronoi region of that face or of one of its two vertices. In a vertex region the
///      axis runs from the vertex to c (the closest point of the polygon is the vertex); in the face region the
///      face normal is the axis.
/// The face tests use the precomputed unit normals: the Voronoi step needs the face of largest true distance,
/// which raw normals would not give. kManifold = false answers only yes or no and compares squared distances, so
/// it takes no square root.
template <bool kManifold, typename S, typename Tracer>
ManifoldT<S> CollidePolygonCircle(const PolygonT<S>& polygon, const TransformT<S>& xfP, const CircleT<S>& circle,
                                  const TransformT<S>& xfC, int polySide, Tracer& tracer)
{
    ManifoldT<S> manifold;
    const S r = circle.radius;
    const Vec2T<S> c = InvRotate(xfP.q, (xfC.p - xfP.p) + Rotate(xfC.q, circle.center));
    // Normals point out of the polygon; the manifold's normal points from A to B.
    const S orient = polySide == 0 ? S(1) : S(-1);
    const int n = polygon.Count();

    S bestSeparation = -std::numeric_limits<S>::infinity(); // Dot(n, c - v) over the faces, before subtracting r
    int bestFace = 0;
    for (int i = 0; i < n; ++i)
    {
        const S s = Dot(polygon.Normal(i), c - polygon.vertices[i]);
        const bool separating = s > r;
        if (s > bestSeparation)
        {
            bestSeparation = s;
            bestFace = i;
        }
        if constexpr (Tracer::kEnabled)
        {
            tracer.FaceAxis(polySide, i, polygon.Normal(i), s - r, -1, separating);
        }
        if (separating)
        {
            if constexpr (kManifold)
            {
                manifold.gap = s - r;
                manifold.normal = orient * Rotate(xfP.q, polygon.Normal(i));
                manifold.axis = {AxisKind::FaceNormal, polySide, i};
            }
            if constexpr (Tracer::kEnabled)
            {
                tracer.Finish(TraceExit::SeparatingAxis, manifold);
            }
            return manifold;
        }
    }

    const Vec2T<S> v1 = polygon.vertices[bestFace];
    const Vec2T<S> v2 = polygon.vertices[Next(bestFace, n)];
    int vertex = -1;
    if (bestSeparation > S(0))
    {
        if (Dot(c - v1, v2 - v1) <= S(0))
        {
            vertex = bestFace;
        }
        else if (Dot(c - v2, v1 - v2) <= S(0))
        {
            vertex = Next(bestFace, n);
        }
    }

    if (vertex >= 0)
    {
        const Vec2T<S> v = polygon.vertices[vertex];
        const Vec2T<S> offset = c - v;
        const S distanceSquared = LengthSquared(offset);
        const bool separating = distanceSquared > r * r;
        if constexpr (Tracer::kEnabled)
        {
            const S distance = std::sqrt(distanceSquared);
            tracer.VertexAxis(polySide, vertex, Rotate(xfP.q, Normalize(offset)), distance - r, separating);
        }
        if constexpr (kManifold)
        {
            const S distance = std::sqrt(distanceSquared);
            // The centre is outside the polygon here, so the distance is positive.
            const Vec2T<S> direction = (S(1) / distance) * offset;
            manifold.normal = orient * Rotate(xfP.q, direction);
            manifold.axis = {AxisKind::VertexToCenter, polySide, vertex};
            if (separating)
            {
                manifold.gap = distance - r;
            }
            else
            {
                manifold.overlap = true;
                manifold.depth = r - distance;
                manifold.contactCount = 1;
                manifold.contacts[0].separation = distance - r;
                manifold.contacts[0].point = TransformPoint(xfP, v + (S(0.5) * (distance - r)) * direction);
            }
        }
        else
        {
            manifold.overlap = !separating;
        }
    }
    else
    {
        manifold.overlap = true;
        if constexpr (kManifold)
        {
            const Vec2T<S> normal = polygon.Normal(bestFace);
            manifold.depth = r - bestSeparation;
            manifold.normal = orient * Rotate(xfP.q, normal);
            manifold.axis = {AxisKind::FaceNormal, polySide, bestFace};
            manifold.contactCount = 1;
            manifold.contacts[0].separation = bestSeparation - r;
            // Halfway between the circle's deepest point c - r n and the face.
            manifold.contacts[0].point = TransformPoint(xfP, c - (S(0.5) * (r + bestSeparation)) * normal);
        }
    }
    if constexpr (Tracer::kEnabled)
    {
        tracer.Finish(manifold.overlap ? TraceExit::AllAxesOverlap : TraceExit::SeparatingAxis, manifold);
    }
    return manifold;
}

// ---------------------------------------------------------------------------------------------------------------
// Circle against circle
// ---------------------------------------------------------------------------------------------------------------

/// Two circles: the only axis is the line through their centres. Concentric circles use the normal (0, 1).
template <bool kManifold, typename S, typename Tracer>
ManifoldT<S> CollideCircles(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b,
                            const TransformT<S>& xfB, Tracer& tracer)
{
    ManifoldT<S> manifold;
    const Vec2T<S> ca = Rotate(xfA.q, a.center);
    const Vec2T<S> d = (xfB.p - xfA.p) + Rotate(xfB.q, b.center) - ca;
    const S radii = a.radius + b.radius;
    const S distanceSquared = LengthSquared(d);
    const bool separating = distanceSquared > radii * radii;
    if constexpr (kManifold || Tracer::kEnabled)
    {
        const S distance = std::sqrt(distanceSquared);
        const Vec2T<S> normal = distance > S(0) ? (S(1) / distance) * d : Vec2T<S>{S(0), S(1)};
        if constexpr (kManifold)
        {
            manifold.normal = normal;
            manifold.axis = {AxisKind::CenterToCenter, -1, -1};
            if (separating)
            {
                manifold.gap = distance - radii;
            }
            else
            {
                manifold.depth = radii - distance;
                manifold.contactCount = 1;
                manifold.contacts[0].separation = distance - radii;
                const Vec2T<S> surfaceA = ca + a.radius * normal;
                manifold.contacts[0].point = xfA.p + (surfaceA + (S(0.5) * (distance - radii)) * normal);
            }
        }
        if constexpr (Tracer::kEnabled)
        {
            tracer.CenterAxis(normal, distance - radii, separating);
        }
    }
    manifold.overlap = !separating;
    if constexpr (Tracer::kEnabled)
    {
        tracer.Finish(separating ? TraceExit::SeparatingAxis : TraceExit::AllAxesOverlap, manifold);
    }
    return manifold;
}

} // namespace satviz::detail
