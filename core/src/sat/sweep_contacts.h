// SPDX-License-Identifier: MIT
// satviz (private), chapter 14: the contacts at the time of impact. A hit's reference face is the axis of the latest
// entry; the other polygon, moved up to the time of impact, touches that face's line and nowhere else. A start where
// the shapes interpenetrate has the static manifold instead, found from the separations the face loops computed.
#pragma once

#include "clip.h"
#include "face_blocks.h"
#include "face_query.h"
#include "incident_polygon.h"
#include "lanes.h"
#include "select.h"
#include "sweep_faces.h"
#include "tracer.h"

#include <satviz/manifold.h>
#include <satviz/polygon.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

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
        const int support = inc.Support(normal);
        vertex = TransformPoint(xfRef, Vec2T<S>{inc.x[support], inc.y[support]});
    }
    // The face in the world at t = 0 from its first vertex along its direction, and moved by ref's velocity.
    const Vec2T<S> faceStart = TransformPoint(xfRef, v1) + toi * vRef;
    const Vec2T<S> faceDirection = Rotate(xfRef.q, tangent);
    contacts[0] = {Select(edge, faceStart + low * faceDirection, vertex + toi * vInc), S(0)};
    contacts[1] = {Select(edge, faceStart + high * faceDirection, Vec2T<S>{}), S(0)};
    return edge ? 2 : 1;
}

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
        return LargestSeparation(n, face, block0, block1);
    };
    const uint64_t skip = SecondPassSkips<AlgorithmChoices::kSkipParallel>(b, incA, true);
    int faceA = 0;
    int faceB = 0;
    const S largestA = largest(keptA, 0, a.Count(), faceA);
    const S largestB = largest(keptB, skip, b.Count(), faceB);
    const ReferenceFace<S> ref = ChooseReferenceFace(a, xfA, faceA, largestA, b, xfB, faceB, largestB);
    if constexpr (!kContacts)
    {
        return ReferenceFaceManifold(ref);
    }
    const IncidentPolygon<S>& inc = SelectRef(ref.flip, incA, incB);
    const ClipResult<S> clip = ClipIncidentEdge<kWide>(ref.polygon, ref.face, inc, -1, S(0));
    return ReferenceFaceManifold(ref, clip);
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

} // namespace satviz::detail
