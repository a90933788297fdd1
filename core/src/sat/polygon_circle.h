// SPDX-License-Identifier: MIT
// satviz (private), chapter 7: polygon against circle. A circle has no faces, so besides the polygon's face normals
// the separating axis test needs one more axis: from the polygon's closest feature to the circle's centre, found
// from the Voronoi regions of the polygon's faces and vertices (Ericson 5.2.6).
//
// References:
//   C. Ericson, Real-Time Collision Detection (2005), 5.2.6 (circle against polygon, Voronoi regions), 5.1.1
//     (closest point).
#pragma once

#include "support.h"

#include <satviz/manifold.h>
#include <satviz/polygon.h>
#include <satviz/shape.h>
#include <satviz/trace.h>

#include <cmath>
#include <limits>

namespace satviz::detail
{

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
        const S s = Dot(polygon.Normal(i), c - polygon.Vertices()[i]);
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

    const Vec2T<S> v1 = polygon.Vertices()[bestFace];
    const Vec2T<S> v2 = polygon.Vertices()[Next(bestFace, n)];
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
        const Vec2T<S> v = polygon.Vertices()[vertex];
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

} // namespace satviz::detail
