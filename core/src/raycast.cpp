// SPDX-License-Identifier: MIT
#include <satviz/raycast.h>

#include <cmath>
#include <limits>

namespace satviz
{

/// Segment against polygon (Cyrus-Beck; Ericson, Real-Time Collision Detection, 5.3.8):
///   1. Map the segment into the polygon's frame: q = R^T (p1 - xf.p), d = R^T (p2 - p1).
///   2. For each face i (outward normal n, vertex v): the signed distance of q from the face's line is
///      s = Dot(n, q - v), and along the segment it changes by e = Dot(n, d) per unit fraction.
///      e < 0: the segment enters the face's half-plane at t = -s / e (latest such entry wins);
///      e > 0: it leaves at t = -s / e (earliest such exit wins); e = 0: parallel, outside when s > 0.
///   3. Starts inside when every s <= 0. Otherwise the line is inside over [enter, leave], which cannot contain
///      t = 0: a miss when that span is empty, behind the start (enter < 0) or beyond p2 (enter > 1).
template <typename S>
RayHitT<S> RayCast(const PolygonT<S>& polygon, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2)
{
    RayHitT<S> out;
    const Vec2T<S> q = InvRotate(xf.q, p1 - xf.p);
    const Vec2T<S> d = InvRotate(xf.q, p2 - p1);
    S enter = -std::numeric_limits<S>::infinity();
    S leave = S(1); // only the part of the line up to p2 matters
    int face = -1;
    bool inside = true;
    for (int i = 0; i < polygon.Count(); ++i)
    {
        const Vec2T<S> n = polygon.Normal(i);
        const S s = Dot(n, q - polygon.vertices[i]);
        const S e = Dot(n, d);
        inside = inside && s <= S(0);
        if (e == S(0))
        {
            if (s > S(0))
            {
                return out; // parallel to the face and outside it
            }
            continue;
        }
        const S t = -s / e;
        if (e < S(0))
        {
            if (t > enter)
            {
                enter = t;
                face = i;
            }
        }
        else
        {
            leave = std::min(leave, t);
        }
        if (enter > leave)
        {
            return out; // leaves one half-plane before entering another: the line misses
        }
    }
    if (inside)
    {
        out.hit = true;
        out.startsInside = true;
        out.point = p1;
        return out;
    }
    // Outside: the line is inside the polygon over [enter, leave], which excludes t = 0; a hit needs it ahead.
    if (face < 0 || !(enter <= leave) || !(enter >= S(0)))
    {
        return out; // behind the start, or NaN input
    }
    out.hit = true;
    out.fraction = enter;
    out.edge = face;
    out.point = p1 + enter * (p2 - p1);
    out.normal = Rotate(xf.q, polygon.Normal(face));
    return out;
}

/// Segment against circle: with m = p1 - c and d = p2 - p1, solve |m + t d|^2 = r^2, i.e.
/// a t^2 + 2 b t + c = 0 with a = Dot(d, d), b = Dot(m, d), c = Dot(m, m) - r^2. c <= 0: starts inside. b > 0 (moving
/// away) or a negative discriminant b^2 - a c: miss. Otherwise the smaller root t = c / (-b + sqrt(b^2 - a c)),
/// the form without cancellation.
template <typename S>
RayHitT<S> RayCast(const CircleT<S>& circle, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2)
{
    RayHitT<S> out;
    const Vec2T<S> center = TransformPoint(xf, circle.center);
    const Vec2T<S> m = p1 - center;
    const Vec2T<S> d = p2 - p1;
    const S c = Dot(m, m) - circle.radius * circle.radius;
    if (c <= S(0))
    {
        out.hit = true;
        out.startsInside = true;
        out.point = p1;
        return out;
    }
    const S a = Dot(d, d);
    const S b = Dot(m, d);
    const S discriminant = b * b - a * c;
    if (!(b < S(0)) || !(discriminant >= S(0)) || a == S(0))
    {
        return out;
    }
    const S t = c / (-b + std::sqrt(discriminant));
    if (!(t <= S(1)))
    {
        return out;
    }
    out.hit = true;
    out.fraction = t;
    out.point = p1 + t * d;
    out.normal = Normalize(out.point - center);
    return out;
}

template <typename S>
RayHitT<S> RayCast(const ShapeT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2)
{
    return shape.type == ShapeType::Polygon ? RayCast(shape.polygon, xf, p1, p2) : RayCast(shape.circle, xf, p1, p2);
}

#define SATVIZ_INSTANTIATE(S)                                                                                          \
    template RayHitT<S> RayCast(const PolygonT<S>&, const TransformT<S>&, Vec2T<S>, Vec2T<S>);                         \
    template RayHitT<S> RayCast(const CircleT<S>&, const TransformT<S>&, Vec2T<S>, Vec2T<S>);                          \
    template RayHitT<S> RayCast(const ShapeT<S>&, const TransformT<S>&, Vec2T<S>, Vec2T<S>);

SATVIZ_INSTANTIATE(double)
SATVIZ_INSTANTIATE(float)

#undef SATVIZ_INSTANTIATE

} // namespace satviz
