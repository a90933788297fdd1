// SPDX-License-Identifier: MIT
// satviz (private), chapter 6: polygon against polygon. Overlap answers yes or no: the face queries of both polygons,
// stopping at the first separating face (Ericson 5.2.1). Collide also finds the reference face, the face of least
// penetration over both polygons, and the contact points by clipping (clip.h).
//
// References:
//   C. Ericson, Real-Time Collision Detection (2005), 5.2.1 (separating-axis test).
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (face queries with support points,
//     reference face and incident edge, clipping).
//   E. Catto, "Contact Manifolds", GDC 2007 (clipping the incident edge against the reference face's side planes).
#pragma once

#include "clip.h"
#include "collide512.h"
#include "cpu_dispatch.h"
#include "face_blocks.h"
#include "face_query_dispatch.h"
#include "incident_polygon.h"
#include "overlap512.h"
#include "select.h"
#include "support.h"
#include "tracer.h"

#include <satviz/manifold.h>
#include <satviz/polygon.h>
#include <satviz/trace.h>

#include <algorithm>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

/// Overlap of two polygons (Ericson 5.2.1; Gregorius).
/// Outline:
///   0. Both polygons of at most 8 vertices: A's faces against B mapped into A's frame, four faces at a time in
///      lanes (SmallFacesSeparate); a separating face ends the test; otherwise B's faces against A mapped into B's
///      frame, anti-parallel faces skipped. One branch per polygon instead of one per face, which measured faster
///      than steps 1 to 3 on small polygons (satviz-bench). With AVX-512 (Tracer::kWide512,
///      SmallPolygonsOverlap512) each polygon's faces fit one register and cost so little that both polygons are
///      tested and decided by one branch: the branch between them, mispredicted on about half of the pairs near
///      contact, costs more than B's faces.
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
    if constexpr (Tracer::kWide512 && !Tracer::kEnabled && Tracer::kScanLimit >= 8 && std::is_same_v<S, double>)
    {
        if (a.Count() > 0 && a.Count() <= 8 && b.Count() > 0 && b.Count() <= 8)
        {
            return SmallPolygonsOverlap512(a, xfA, b, xfB, Tracer::kSkipParallel);
        }
    }
#endif
    const IncidentPolygon<S> incB(b, xfA, xfB, Tracer::kScanLimit, MapInLanes<Tracer::kWide>{});
    if (incB.scan && a.Count() <= 8 && b.Count() <= 8)
    {
        bool separated = SmallFacesSeparate(a, incB, 0, false, tracer);
        if (!separated || !Tracer::kEarlyExit)
        {
            const IncidentPolygon<S> incA(a, xfB, xfA, Tracer::kScanLimit, MapInLanes<Tracer::kWide>{});
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
    alignas(32) S inside[IncidentPolygon<S>::kCapacity];
    std::fill(inside, inside + incB.padded, -std::numeric_limits<S>::infinity());
    const FaceQuery<S> queryA = QueryFaces<false, true>(a, incB, 0, false, S(0), tracer, inside);
    bool overlap = !queryA.separated;
    if (overlap)
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
        const IncidentPolygon<S> incA(a, xfB, xfA, Tracer::kScanLimit, MapInLanes<Tracer::kWide>{});
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
                Dot(normal, TransformPoint(incInRef, inc.Vertices()[support]) - ref.Vertices()[cached.index]);
            cachedSupport = support;
            if (separation > S(0))
            {
                return false;
            }
        }
    }
    NullTracer tracer;
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, MapInLanes<false>{});
    FaceQuery<S> query = QueryFaces<false>(a, incB, 0, false, S(0), tracer);
    if (query.separated)
    {
        cached = {AxisKind::FaceNormal, 0, query.face};
        cachedSupport = query.support;
        return false;
    }
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, MapInLanes<false>{});
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

/// The manifold of two polygons (Gregorius; Catto).
/// Outline:
///   0. Both polygons of at most 8 vertices, untraced, on a processor with AVX-512: steps 2 to 4 with every face of
///      both polygons in one register each (SmallPolygonsCollide512), both face queries before one branch: the
///      same separations, reference face and contacts to the bit.
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
#if SATVIZ_WIDE
    if constexpr (Tracer::kWide512 && !Tracer::kEnabled && Tracer::kScanLimit >= 8 && std::is_same_v<S, double>)
    {
        if (a.Count() > 0 && a.Count() <= 8 && b.Count() > 0 && b.Count() <= 8)
        {
            return SmallPolygonsCollide512(a, xfA, b, xfB, Tracer::kSkipParallel);
        }
    }
#endif
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, MapInLanes<Tracer::kWide>{});
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
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, MapInLanes<Tracer::kWide>{});
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

    // Reference face (a skipped duplicate of A's face keeps A's).
    const ReferenceFace<S> ref =
        ChooseReferenceFace(a, xfA, queryA.face, queryA.separation, b, xfB, queryB.face, queryB.separation);
    const IncidentPolygon<S>& inc = SelectRef(ref.flip, incA, incB);
    const int support = Select(ref.flip, queryB.support, queryA.support);

    const ClipResult<S> clip =
        ClipIncidentEdge<Tracer::kWide>(ref.polygon, ref.face, inc, inc.scan ? -1 : support, S(0));
    const ManifoldT<S> manifold = ReferenceFaceManifold(ref, clip);

    if constexpr (Tracer::kEnabled)
    {
        tracer.Clip(ClipTraceOf(clip, manifold.axis, ref.polygon, ref.xf, inc.polygon, ref.flip ? xfA : xfB,
                                ref.flip ? 0 : 1));
        tracer.Finish(TraceExit::AllAxesOverlap, manifold);
    }
    return manifold;
}

} // namespace satviz::detail
