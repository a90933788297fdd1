// SPDX-License-Identifier: MIT
#include "sat/support.h"

#include <satviz/raycast.h>

#include <cmath>
#include <limits>

namespace satviz
{

namespace
{

/// Polygons up to this many vertices are cast against every face: below it, the pass costs less than the four
/// bisections and their mispredicted branches (satviz-bench measures both sides of the limit).
constexpr int kRayScanLimit = 32;

/// The face of `polygon` where the line q + t d crosses the chain of vertices from `from` to `to` (counter-clockwise,
/// `side` the signed side Cross(d, v - q) of each: >= 0 at `from`, < 0 at `to`, or the other way with `falling`
/// false): the last vertex before the side changes, found by bisection along the chain, whose sides change once.
template <typename S>
int CrossingFace(const PolygonT<S>& polygon, int from, int to, bool falling, Vec2T<S> q, Vec2T<S> d)
{
    const int n = polygon.Count();
    const auto at = [n, from](int k) { return from + k < n ? from + k : from + k - n; };
    // Whether vertex `from + k` already lies on the far side.
    const auto past = [&](int k) {
        const S side = Cross(d, polygon.Vertices()[at(k)] - q);
        return falling ? side < S(0) : side >= S(0);
    };
    int lo = 0;
    int hi = to >= from ? to - from : to - from + n;
    while (hi - lo > 1)
    {
        const int mid = lo + (hi - lo) / 2;
        if (past(mid))
        {
            hi = mid;
        }
        else
        {
            lo = mid;
        }
    }
    return at(lo);
}

/// The hit of a segment whose line is inside the polygon over [enter, leave] (leave at most 1), entering through
/// `face`; or the start inside.
template <typename S>
RayHitT<S> Finish(RayHitT<S> out, bool inside, S enter, S leave, int face, const PolygonT<S>& polygon,
                  const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2)
{
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

} // namespace

/// Segment against polygon (Cyrus-Beck; Ericson, Real-Time Collision Detection, 5.3.8):
///   1. Map the segment into the polygon's frame: q = R^T (p1 - xf.p), d = R^T (p2 - p1).
///   2. For each face i (outward normal n, vertex v): the signed distance of q from the face's line is
///      s = Dot(n, q - v), and along the segment it changes by e = Dot(n, d) per unit fraction.
///      e < 0: the segment enters the face's half-plane at t = -s / e (latest such entry wins);
///      e > 0: it leaves at t = -s / e (earliest such exit wins); e = 0: parallel, outside when s > 0.
///   3. Starts inside when every s <= 0. Otherwise the line is inside over [enter, leave], which cannot contain
///      t = 0: a miss when that span is empty, behind the start (enter < 0) or beyond p2 (enter > 1).
///   4. Polygons above kRayScanLimit vertices: the line through the segment crosses the outline at most twice, and
///      where it does is found by bisection (CrossingFace) instead of a pass over every face: O(log n).
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
    if (polygon.Count() > kRayScanLimit)
    {
        // The sides of the line at the polygon's extreme points across it: all on one side, a miss; strictly on
        // both, the line crosses the outline once on the chain from the left extreme to the right one (the faces
        // it enters, facing against d) and once on the way back. Touching (a side exactly 0), a zero-length
        // segment or NaN: the pass over every face below decides.
        const Vec2T<S> across = LeftPerp(d);
        const int left = detail::BisectSupport(polygon, across);
        const int right = detail::BisectSupport(polygon, -across);
        const S leftSide = Cross(d, polygon.Vertices()[left] - q);
        const S rightSide = Cross(d, polygon.Vertices()[right] - q);
        if (leftSide < S(0) || rightSide > S(0))
        {
            return out;
        }
        if (leftSide > S(0) && rightSide < S(0))
        {
            const int in = CrossingFace(polygon, left, right, true, q, d);
            const int away = CrossingFace(polygon, right, left, false, q, d);
            const Vec2T<S> nIn = polygon.Normal(in);
            const Vec2T<S> nAway = polygon.Normal(away);
            const S sIn = Dot(nIn, q - polygon.Vertices()[in]);
            const S sAway = Dot(nAway, q - polygon.Vertices()[away]);
            inside = sIn <= S(0) && sAway <= S(0);
            const S eIn = Dot(nIn, d);
            const S eAway = Dot(nAway, d);
            if (!inside && eIn < S(0) && eAway > S(0))
            {
                enter = -sIn / eIn;
                face = in;
                leave = std::min(leave, -sAway / eAway);
            }
            return Finish(out, inside, enter, leave, face, polygon, xf, p1, p2);
        }
    }
    for (int i = 0; i < polygon.Count(); ++i)
    {
        const Vec2T<S> n = polygon.Normal(i);
        const S s = Dot(n, q - polygon.Vertices()[i]);
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
    return Finish(out, inside, enter, leave, face, polygon, xf, p1, p2);
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
