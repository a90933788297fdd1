// SPDX-License-Identifier: MIT
// satviz (private), chapter 9: speculative contacts. Shapes that do not touch yet, but are closer than a margin, get
// the contact points they would have if they touched, each with its separation (> 0: the gap still open). A
// physics step gives such points to its solver, which lets each approach by at most its gap within the step, so a
// body that would have sunk into another during the step stops at its surface instead.
//
// References:
//   E. Catto, "Contact Manifolds", GDC 2007, and Box2D v3 (speculative contacts within a margin).
//   P. Firth, "Speculative Contacts: a continuous collision engine approach", 2011.
#pragma once

#include "circle_circle.h"
#include "clip.h"
#include "face_query_dispatch.h"
#include "incident_polygon.h"
#include "polygon_circle.h"
#include "select.h"
#include "tracer.h"

#include <satviz/manifold.h>
#include <satviz/polygon.h>
#include <satviz/shape.h>

#include <limits>

namespace satviz::detail
{

/// The null tracer whose face queries test every face: the largest separation, positive or not.
struct EveryFaceTracer : NullTracer
{
    static constexpr bool kEarlyExit = false; ///< every face is tested
};

/// The manifold of two polygons separated by at most `margin` (the separation of the reference face), with the
/// contacts of that face (Catto; Gregorius).
/// Outline:
///   1. Face queries of A's faces and of B's faces, every face: the largest separation of each polygon. Above the
///      margin the pair gets no contacts (returned as Collide returns a separated pair).
///   2. Reference face: the face of largest separation, A's on a tie, as in CollidePolygons.
///   3. Contacts (ClipIncidentEdge): the incident edge clipped to the side planes of the reference face, keeping
///      the points whose separation is at most the margin.
/// The pair need not be separated: overlapping, it gets CollidePolygons' manifold.
template <typename S>
ManifoldT<S> SpeculativePolygons(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                                 const TransformT<S>& xfB, S margin)
{
    EveryFaceTracer tracer;
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, MapInLanes<false>{});
    const FaceQuery<S> queryA = QueryFaces<true>(a, incB, 0, false, -std::numeric_limits<S>::infinity(), tracer);
    ManifoldT<S> manifold;
    if (queryA.separation > margin)
    {
        manifold.gap = queryA.separation;
        manifold.normal = Rotate(xfA.q, a.Normal(queryA.face));
        manifold.axis = {AxisKind::FaceNormal, 0, queryA.face};
        return manifold;
    }
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, MapInLanes<false>{});
    const FaceQuery<S> queryB = QueryFaces<true>(b, incA, 1, true, queryA.separation, tracer);
    if (queryB.separation > margin)
    {
        manifold.gap = queryB.separation;
        manifold.normal = -Rotate(xfB.q, b.Normal(queryB.face));
        manifold.axis = {AxisKind::FaceNormal, 1, queryB.face};
        return manifold;
    }
    // Reference face (a skipped duplicate of A's face keeps A's).
    const ReferenceFace<S> ref =
        ChooseReferenceFace(a, xfA, queryA.face, queryA.separation, b, xfB, queryB.face, queryB.separation);
    const IncidentPolygon<S>& inc = SelectRef(ref.flip, incA, incB);
    const int support = Select(ref.flip, queryB.support, queryA.support);
    ClipResult<S> clip = ClipIncidentEdge(ref.polygon, ref.face, inc, inc.scan ? -1 : support, margin);
    if (clip.fallback && clip.contacts[0].separation > margin)
    {
        clip.contactCount = 0; // the deepest vertex is beyond the margin too
    }
    const Vec2T<S> worldNormal = Rotate(ref.xf.q, ref.polygon.Normal(ref.face));
    manifold.overlap = ref.separation <= S(0);
    manifold.depth = manifold.overlap ? -ref.separation : S(0);
    manifold.gap = manifold.overlap ? S(0) : ref.separation;
    manifold.normal = Select(ref.flip, -worldNormal, worldNormal);
    manifold.axis = {AxisKind::FaceNormal, Select(ref.flip, 1, 0), ref.face};
    TakeContacts(manifold, clip, ref.xf);
    return manifold;
}

/// Turns the manifold of two overlapping polygons (Collide's `m`) into the same with its clipping redone to keep the
/// points of the incident edge up to `margin` above the reference face (ClipIncidentEdge), not only those below it: an
/// edge that touches at one end and is turning onto the face gets its other end as a speculative contact. A scanned
/// incident polygon is not mapped again: Collide found its incident edge (`m.incidentEdge`) by ScannedIncidentEdge from
/// the same relative transform and reference normal, which is what the clipping would find again, so only the edge's
/// two ends are mapped, to the bits the whole mapping gives them. In place, as only the contacts change.
template <typename S>
void ReclipWithin(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                  ManifoldT<S>& m, S margin)
{
    const bool flip = m.axis.shape == 1;
    const PolygonT<S>& ref = SelectRef(flip, b, a);
    const TransformT<S>& xfRef = SelectRef(flip, xfB, xfA);
    const PolygonT<S>& incident = SelectRef(flip, a, b);
    const TransformT<S>& xfInc = SelectRef(flip, xfA, xfB);
    const int count = incident.Count();
    if (count > 0 && count <= kScanLimit && m.incidentEdge >= 0 && m.incidentEdge < count)
    {
        const IncidentPolygon<S> inc(incident, xfRef, xfInc, 0); // a scan limit of 0: not mapped
        ClipResult<S> clip;
        IncidentEdgeEnds(inc, m.incidentEdge, clip);
        ClipIncidentEdgeFound(ref, m.axis.index, inc, -1, margin, static_cast<const Vec2T<S>*>(nullptr), clip);
        TakeContacts(m, clip, xfRef);
        return;
    }
    const IncidentPolygon<S> inc(incident, xfRef, xfInc, kScanLimit, MapInLanes<false>{});
    TakeContacts(m, ClipIncidentEdge(ref, m.axis.index, inc, -1, margin), xfRef);
}

/// Moves a manifold of A against an inflated B (B's surface pushed out by `margin` along the normal) back to the
/// real B: every separation grows by the margin and every contact point, halfway between the surfaces, moves by
/// half of it; the pair overlaps only if a contact still does. `inflatedA` when it was A that was inflated.
template <typename S>
ManifoldT<S> Deflated(ManifoldT<S> m, S margin, bool inflatedA)
{
    if (!m.overlap)
    {
        m.gap = m.gap + margin;
        return m;
    }
    const S separation = margin - m.depth;
    m.overlap = separation <= S(0);
    m.depth = m.overlap ? -separation : S(0);
    m.gap = m.overlap ? S(0) : separation;
    const Vec2T<S> shift = (inflatedA ? -S(0.5) : S(0.5)) * margin * m.normal;
    for (int k = 0; k < m.contactCount; ++k)
    {
        m.contacts[k].separation = m.contacts[k].separation + margin;
        m.contacts[k].point = m.contacts[k].point + shift;
    }
    return m;
}

/// Polygon against circle within `margin`: Collide with the circle's radius grown by the margin, which keeps its
/// centre, so the same Voronoi region and axis; then the separations and points of the real circle (Deflated).
/// `polySide` as in CollidePolygonCircle.
template <typename S>
ManifoldT<S> SpeculativePolygonCircle(const PolygonT<S>& polygon, const TransformT<S>& xfP, const CircleT<S>& circle,
                                      const TransformT<S>& xfC, int polySide, S margin)
{
    CircleT<S> grown = circle;
    grown.radius = circle.radius + margin;
    NullTracer tracer;
    return Deflated(CollidePolygonCircle<true>(polygon, xfP, grown, xfC, polySide, tracer), margin, polySide == 1);
}

/// Circle against circle within `margin`: B's radius grown by the margin, then Deflated.
template <typename S>
ManifoldT<S> SpeculativeCircles(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b,
                                const TransformT<S>& xfB, S margin)
{
    CircleT<S> grown = b;
    grown.radius = b.radius + margin;
    NullTracer tracer;
    return Deflated(CollideCircles<true>(a, xfA, grown, xfB, tracer), margin, false);
}

} // namespace satviz::detail
