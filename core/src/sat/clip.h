// SPDX-License-Identifier: MIT
// satviz (private), chapter 5: the contact points of two overlapping polygons. The face query found the reference
// face, the face of least penetration; the incident edge is the other polygon's edge most anti-parallel to it. The
// incident edge is clipped against the two side planes of the reference face, and the clipped points on or below
// the face are kept as contacts, halfway between the point and the face (Sutherland-Hodgman clipping of one edge).
//
// References:
//   E. Catto, "Contact Manifolds", GDC 2007 (clipping the incident edge against the reference face's side planes).
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (reference face and incident edge,
//     clipping).
#pragma once

#include "incident_polygon.h"
#include "lanes.h"
#include "lanes2.h"
#include "select.h"
#include "support.h"

#include <satviz/manifold.h>
#include <satviz/polygon.h>
#include <satviz/trace.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

/// Whether the reference face is B's, from the largest separation of A's faces (`separationA`) and of B's
/// (`separationB`): only when B's is strictly larger. On a tie the reference face is A's, so the normal and the
/// contacts are those of A's face (manifold.h), and a NaN on either side keeps A's face too. Box2D's
/// b2CollidePolygons keeps A's face unless B's is larger by a tolerance, 0.1 b2_linearSlop, a length in metres that
/// keeps the reference face of a resting contact from switching between steps; satviz has no unit of length and
/// gives the textbook loop's answer to the bit, so its tolerance is zero: the face of largest separation, as Ericson
/// (Real-Time Collision Detection, 5.2.1) takes the axis of least penetration. Every query that picks a reference
/// face from both polygons' face queries picks it here.
template <typename S>
bool ReferenceFaceIsB(S separationA, S separationB)
{
    return separationB > separationA;
}

/// The reference face of a pair: the polygon that holds it (B's when `flip`), that polygon's transform, the face and
/// its separation.
template <typename S>
struct ReferenceFace
{
    bool flip;                  ///< B holds the reference face (ReferenceFaceIsB)
    const PolygonT<S>& polygon; ///< the polygon that holds it
    const TransformT<S>& xf;    ///< that polygon's transform
    int face;                   ///< the face, of `polygon`
    S separation;               ///< its separation, the largest of that polygon's faces
};

/// The reference face of a pair from each polygon's face of largest separation (A's `faceA` with `separationA`, B's
/// `faceB` with `separationB`), by ReferenceFaceIsB: every choice on it a mask, not a branch.
template <typename S>
ReferenceFace<S> ChooseReferenceFace(const PolygonT<S>& a, const TransformT<S>& xfA, int faceA, S separationA,
                                     const PolygonT<S>& b, const TransformT<S>& xfB, int faceB, S separationB)
{
    const bool flip = ReferenceFaceIsB(separationA, separationB);
    return {flip, SelectRef(flip, b, a), SelectRef(flip, xfB, xfA), Select(flip, faceB, faceA),
            Select(flip, separationB, separationA)};
}

/// Contact points from clipping, in the reference polygon's frame, with what the trace shows of the clipping.
/// The arrays are valid up to their counts and left uninitialised beyond: zeroing the whole struct costs a block
/// store (rep stos) per manifold, a large share of Collide's time for small polygons.
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

/// Incident edge `edge` of inc and its ends mapped into the reference frame one at a time (TransformPoint), into
/// `out`: the same bits as inc's mapped vertices, so a caller that knows the edge need not map the whole polygon.
template <typename S>
void IncidentEdgeEnds(const IncidentPolygon<S>& inc, int edge, ClipResult<S>& out)
{
    out.incidentEdge = edge;
    out.w1 = TransformPoint(inc.xf, inc.polygon.Vertices()[edge]);
    out.w2 = TransformPoint(inc.xf, inc.polygon.Vertices()[Next(edge, inc.polygon.Count())]);
}

/// Step 1 of the clipping, the incident edge: the edge of inc whose outward normal is most anti-parallel to the
/// reference face's unit `normal` (reference frame), one of the two edges at inc's support vertex in direction
/// -normal. A scanned inc compares all its normals (ScannedIncidentEdge) and reads the edge's ends from its mapped
/// vertices; a walked one compares the two edges at its `support` vertex (found here when -1). Writes the edge and
/// its ends (reference frame) into `out`; returns the support vertex it used, or -1 (a scanned inc without one).
template <bool kWide, typename S>
int IncidentEdge(const IncidentPolygon<S>& inc, Vec2T<S> normal, int support, ClipResult<S>& out)
{
    const int m = inc.polygon.Count();
    int s = support;
    if (inc.scan && support < 0)
    {
        out.incidentEdge = ScannedIncidentEdge<kWide>(inc, normal);
        out.w1 = {inc.x[out.incidentEdge], inc.y[out.incidentEdge]};
        out.w2 = {inc.x[out.incidentEdge + 1], inc.y[out.incidentEdge + 1]};
    }
    else
    {
        s = support >= 0 ? support : inc.Support(normal);
        const int before = Prev(s, m);
        const S dotLeaving = Dot(normal, Rotate(inc.xf.q, inc.polygon.Normal(s)));
        const S dotEntering = Dot(normal, Rotate(inc.xf.q, inc.polygon.Normal(before)));
        IncidentEdgeEnds(inc, Select(dotEntering < dotLeaving, before, s), out);
    }
    return s;
}

/// The two ends of an incident edge after the side planes, side by side in two lanes (lane 0: the end from w1, lane
/// 1: the end from w2), and which of them are left.
template <typename S>
struct ClippedEdge
{
    Lanes2<S> x;                   ///< the ends' x (reference frame)
    Lanes2<S> y;                   ///< the ends' y
    typename Lanes2<S>::Mask kept; ///< the ends left inside both side planes
};

/// Step 2 of the clipping, the side planes: the incident edge w1 w2 clipped against the two side planes of the
/// reference face v1 v2 (`tangent`: its unit direction from v1 towards v2), Sutherland-Hodgman on one edge, without
/// branches. Both ends of the edge go side by side in two lanes, so that each step is one operation for both ends
/// and each choice a mask: where an edge lies against the side planes varies from pair to pair, and branches on it
/// were mispredicted often enough to cost more than the clipping itself. An end outside a side plane moves to the
/// plane's crossing when the other end lies strictly inside; an end on a plane stays, and an edge that only touches
/// a plane keeps that one point. Writes the trace's view of both planes into `out` (count1, clip1, count2, clip2).
template <typename S>
ClippedEdge<S> ClipSidePlanes(Vec2T<S> w1, Vec2T<S> w2, Vec2T<S> v1, Vec2T<S> v2, Vec2T<S> tangent, ClipResult<S>& out)
{
    using P = Lanes2<S>;
    using M = typename P::Mask;
    const P x = P::Set(w1.x, w2.x);
    const P y = P::Set(w1.y, w2.y);
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
    // What the trace shows: the points after each plane, listed from w1's end.
    const int kept1 = keep1.Bits();
    const int kept2 = keep2.Bits();
    out.count1 = (kept1 & 1) + (kept1 >> 1);
    out.clip1[0] = (kept1 & 1) != 0 ? Vec2T<S>{x1.Get(0), y1.Get(0)} : Vec2T<S>{x1.Get(1), y1.Get(1)};
    out.clip1[1] = {x1.Get(1), y1.Get(1)};
    out.count2 = (kept2 & 1) + (kept2 >> 1);
    out.clip2[0] = (kept2 & 1) != 0 ? Vec2T<S>{x2.Get(0), y2.Get(0)} : Vec2T<S>{x2.Get(1), y2.Get(1)};
    out.clip2[1] = {x2.Get(1), y2.Get(1)};
    return {x2, y2, keep2};
}

/// Step 3 of the clipping, keep the deep points: the ends left by the side planes whose separation from the
/// reference face (unit `normal`, through v1) is at most `keepBelow` (0 for resting contact; a little more at a time
/// of impact, where touching points carry rounding of either sign). Each contact point lies halfway between its end
/// and the face. Writes the contacts into `out`, and the trace's view: each end's separation, and whether it is kept.
template <typename S>
void KeepDeepPoints(const ClippedEdge<S>& clipped, Vec2T<S> v1, Vec2T<S> normal, S keepBelow, ClipResult<S>& out)
{
    using P = Lanes2<S>;
    // Each clipped end's separation from the face, and whether it is kept as a contact.
    const P separation =
        P::Fill(normal.x) * (clipped.x - P::Fill(v1.x)) + P::Fill(normal.y) * (clipped.y - P::Fill(v1.y));
    const int valid = (clipped.kept & (separation <= P::Fill(keepBelow))).Bits();
    // The contact points, halfway between the kept ends and the face; the first one is the first valid end.
    const P half = P::Fill(S(0.5)) * separation;
    const P cx = clipped.x - half * P::Fill(normal.x);
    const P cy = clipped.y - half * P::Fill(normal.y);
    const bool firstEnd = (valid & 1) != 0;
    out.contactCount = (valid & 1) + (valid >> 1);
    out.contacts[0].point = Select(firstEnd, Vec2T<S>{cx.Get(0), cy.Get(0)}, Vec2T<S>{cx.Get(1), cy.Get(1)});
    out.contacts[0].separation = Select(firstEnd, separation.Get(0), separation.Get(1));
    out.contacts[1].point = {cx.Get(1), cy.Get(1)};
    out.contacts[1].separation = separation.Get(1);
    // What the trace shows: which of the points after both planes, listed from w1's end, are kept.
    const int kept2 = clipped.kept.Bits();
    out.separations[0] = (kept2 & 1) != 0 ? separation.Get(0) : separation.Get(1);
    out.separations[1] = separation.Get(1);
    out.kept[0] = ((kept2 & 1) != 0 ? valid & 1 : valid >> 1) != 0;
    out.kept[1] = (kept2 & 1) != 0 && (valid >> 1) != 0;
}

/// Step 4 of the clipping, when it keeps nothing (a rounding artefact at a vertex-vertex contact): the deepest vertex
/// of inc alone as the contact, the support vertex `support`, or (-1, a scanned inc) the deeper end of the incident
/// edge in `out`, which is that vertex. `shift` as in ClipIncidentEdge.
template <typename S>
void KeepDeepestVertex(const IncidentPolygon<S>& inc, int support, Vec2T<S> v1, Vec2T<S> normal, const Vec2T<S>* shift,
                       ClipResult<S>& out)
{
    Vec2T<S> deepest = Dot(normal, out.w2 - out.w1) < S(0) ? out.w2 : out.w1;
    if (support >= 0)
    {
        deepest = TransformPoint(inc.xf, inc.polygon.Vertices()[support]);
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

/// Steps 2 to 4 of ClipIncidentEdge, on the incident edge `out` holds (IncidentEdge, or IncidentEdgeEnds where the
/// edge is known): `s` is the incident support vertex step 1 used, or -1. Writes the contacts into `out`.
template <typename S>
void ClipIncidentEdgeFound(const PolygonT<S>& ref, int face, const IncidentPolygon<S>& inc, int s, S keepBelow,
                           const Vec2T<S>* shift, ClipResult<S>& out)
{
    const Vec2T<S> v1 = ref.Vertices()[face];
    const Vec2T<S> v2 = ref.Vertices()[Next(face, ref.Count())];
    const Vec2T<S> normal = ref.Normal(face);
    if (shift != nullptr)
    {
        out.w1 = out.w1 + *shift;
        out.w2 = out.w2 + *shift;
    }
    const ClippedEdge<S> clipped = ClipSidePlanes(out.w1, out.w2, v1, v2, LeftPerp(normal), out);
    KeepDeepPoints(clipped, v1, normal, keepBelow, out);
    out.fallback = out.contactCount == 0;
    if (out.fallback)
    {
        KeepDeepestVertex(inc, s, v1, normal, shift, out);
    }
}

/// Contact points of a reference face (Catto; Gregorius).
/// Outline:
///   1. Incident edge: the edge of the incident polygon whose normal is most anti-parallel to the reference normal
///      (IncidentEdge).
///   2. Clip it against the two side planes of the reference face (ClipSidePlanes, Sutherland-Hodgman).
///   3. Keep the clipped points whose separation from the face is at most `keepBelow` (KeepDeepPoints). The contact
///      point is halfway between the kept point and the reference face.
///   4. If clipping keeps nothing (a rounding artefact at a vertex-vertex contact), use the deepest vertex: the
///      support vertex, or the deeper end of the incident edge, which is that vertex (KeepDeepestVertex).
/// `support` is the incident support vertex if known, else -1. `shift`, if given, moves the incident polygon by that
/// much (reference frame) before clipping: a sweep clips at the time of impact with the polygon mapped at t = 0.
template <bool kWide = false, typename S>
ClipResult<S> ClipIncidentEdge(const PolygonT<S>& ref, int face, const IncidentPolygon<S>& inc, int support,
                               S keepBelow, const Vec2T<S>* shift = nullptr)
{
    ClipResult<S> out;
    const int s = IncidentEdge<kWide>(inc, ref.Normal(face), support, out);
    ClipIncidentEdgeFound(ref, face, inc, s, keepBelow, shift, out);
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

/// The manifold of two overlapping polygons from their reference face `ref`, whose separation is <= 0: the depth and
/// the MTV's direction along the face's normal, from A to B; no contact points and no incident edge.
template <typename S>
ManifoldT<S> ReferenceFaceManifold(const ReferenceFace<S>& ref)
{
    const Vec2T<S> worldNormal = Rotate(ref.xf.q, ref.polygon.Normal(ref.face));
    return {true,
            -ref.separation,
            S(0),
            Select(ref.flip, -worldNormal, worldNormal),
            {},
            0,
            {AxisKind::FaceNormal, Select(ref.flip, 1, 0), ref.face},
            -1};
}

/// Puts the contacts of `clip` (reference frame, whose transform is xfRef) in world space into `manifold`, with
/// their count and the incident edge.
template <typename S>
void TakeContacts(ManifoldT<S>& manifold, const ClipResult<S>& clip, const TransformT<S>& xfRef)
{
    manifold.contacts[0] = WorldContact(clip, 0, xfRef);
    manifold.contacts[1] = WorldContact(clip, 1, xfRef);
    manifold.contactCount = clip.contactCount;
    manifold.incidentEdge = clip.incidentEdge;
}

/// The same with the contacts of `clip` (reference frame) in world space and its incident edge.
template <typename S>
ManifoldT<S> ReferenceFaceManifold(const ReferenceFace<S>& ref, const ClipResult<S>& clip)
{
    ManifoldT<S> manifold = ReferenceFaceManifold(ref);
    TakeContacts(manifold, clip, ref.xf);
    return manifold;
}

/// The trace's view of a clipping, in world space.
template <typename S>
ClipTraceT<S> ClipTraceOf(const ClipResult<S>& r, const AxisRef& reference, const PolygonT<S>& ref,
                          const TransformT<S>& xfRef, const PolygonT<S>& inc, const TransformT<S>& xfInc,
                          int incidentShape)
{
    ClipTraceT<S> clip;
    clip.reference = reference;
    clip.referenceV1 = TransformPoint(xfRef, ref.Vertices()[reference.index]);
    clip.referenceV2 = TransformPoint(xfRef, ref.Vertices()[Next(reference.index, ref.Count())]);
    clip.referenceNormal = Rotate(xfRef.q, ref.Normal(reference.index));
    clip.incidentShape = incidentShape;
    clip.incidentEdge = r.incidentEdge;
    clip.incidentV1 = TransformPoint(xfInc, inc.Vertices()[r.incidentEdge]);
    clip.incidentV2 = TransformPoint(xfInc, inc.Vertices()[Next(r.incidentEdge, inc.Count())]);
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

} // namespace satviz::detail
