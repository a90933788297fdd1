// SPDX-License-Identifier: MIT
// satviz: segment casts against shapes, for bullets, lasers, mouse picking and line-of-sight.
#pragma once

#include <satviz/shape.h>

namespace satviz
{

/// Where a segment first meets a shape.
template <typename S>
struct RayHitT
{
    bool hit = false;          ///< the segment meets the shape (touching counts)
    bool startsInside = false; ///< the segment starts inside the shape (or on its boundary): fraction 0, normal 0
    S fraction{};              ///< where along the segment: point = p1 + fraction * (p2 - p1), in [0, 1]
    Vec2T<S> point{};          ///< world point of first contact
    Vec2T<S> normal{};         ///< unit outward normal of the surface there (zero when startsInside)
    int edge = -1;             ///< polygons: the edge hit first; -1 for circles and when startsInside
};

/// Double-precision hit.
using RayHit = RayHitT<double>;

/// The first point where the segment from p1 to p2 (world) meets the polygon placed by xf. Cyrus-Beck clipping of
/// the segment against the polygon's faces, in the polygon's frame (p1 - xf.p is formed before any rotation, so a
/// cast far from the origin is as precise as near it): the segment enters through the face with the latest
/// entry and leaves through the one with the earliest exit, and misses when it leaves before it enters. A segment
/// that starts inside reports startsInside at fraction 0 (Box2D reports no hit there). Polygons above 32 vertices
/// find the two faces where the segment's line crosses the outline by bisection: O(log n). No allocation.
template <typename S>
RayHitT<S> RayCast(const PolygonT<S>& polygon, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2);

/// The first point where the segment meets the circle: the smaller root of |p1 + t (p2 - p1) - c| = r, computed
/// without cancellation (Ericson, Real-Time Collision Detection, 5.3.2).
template <typename S>
RayHitT<S> RayCast(const CircleT<S>& circle, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2);

/// Either kind of shape.
template <typename S>
RayHitT<S> RayCast(const ShapeT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2);

} // namespace satviz
