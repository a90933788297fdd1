// SPDX-License-Identifier: MIT
// satviz (private), chapter 16: the sweep of a circle, against a polygon or a circle (Ericson 5.3.2 and 5.5.7). The
// centre's path against the rounded outline of the other shape: its faces pushed out by the radius and arcs around
// its vertices, or a disc of both radii.
#pragma once

#include "sweep_axis.h"
#include "sweep_contacts.h"
#include "tracer.h"

#include <satviz/collide.h>
#include <satviz/shape.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz::detail
{

// First time the point p0 + t v enters the disc of radius r around c, if it crosses the circle (a tangent path
// only touches it): the stable root of |p0 + t v - c|^2 = r^2 (Ericson 5.3.2). A point on the circle, or inside it
// by rounding (the caller has ruled out a real overlap), that heads inwards enters at 0; heading along the circle
// as far as the rounding of b = Dot(p0 - c, v) can tell (StillRate), or on a path tangent to it as far as the
// rounding of the discriminant can tell (a circle sliding along a face passes over the vertex at its end so), it
// does not enter.
template <typename S>
S EnterDisc(Vec2T<S> p0, Vec2T<S> v, Vec2T<S> c, S r)
{
    const Vec2T<S> f = p0 - c;
    const S b = Dot(f, v);
    const S outside = Dot(f, f) - r * r;
    const S scale = std::max({std::abs(f.x), std::abs(f.y), r});
    if (b >= -scale * StillRate(v))
    {
        return kInfinity<S>;
    }
    if (outside <= S(0))
    {
        return S(0);
    }
    // A path tangent to the circle, as far as the rounding of the discriminant can tell, only touches it.
    const S speed2 = Dot(v, v);
    const S discriminant = b * b - speed2 * outside;
    if (discriminant <= S(16) * std::numeric_limits<S>::epsilon() * (Dot(f, f) + r * r) * speed2)
    {
        return kInfinity<S>;
    }
    return outside / (-b + std::sqrt(discriminant));
}

/// A circle of radius r, centre p0 moving by v, against a polygon (both in the polygon's frame): the first time
/// the centre enters the polygon rounded by r (the Minkowski sum of the polygon and the disc). Its boundary is
/// the faces pushed out by r and arcs of radius r around the vertices, so the first entry is the earliest of: a
/// crossing of a pushed-out face within the face's extent, or an entry into a vertex's disc. Returns the time
/// (infinity for none) and the unit normal out of the polygon at the contact.
template <typename S>
S CastRounded(const PolygonT<S>& polygon, Vec2T<S> p0, Vec2T<S> v, S r, Vec2T<S>& normal, AxisRef& axis, int side)
{
    S best = kInfinity<S>;
    const S still = StillRate(v);
    for (int i = 0; i < polygon.Count(); ++i)
    {
        const Vec2T<S> n = polygon.Normal(i);
        const S separation = Dot(n, p0 - polygon.Vertices()[i]) - r;
        const S rate = Dot(n, v);
        // A centre behind the pushed-out face by no more than rounding (touching) that heads in crosses it at 0,
        // if within the face's extent; one moving along the face (StillRate) never crosses it.
        const S rounding = S(16) * std::numeric_limits<S>::epsilon() *
                           std::max({std::abs(p0.x), std::abs(p0.y), std::abs(polygon.Vertices()[i].x),
                                     std::abs(polygon.Vertices()[i].y), r});
        if (separation < -rounding || rate >= -still)
        {
            continue;
        }
        const S t = std::max(S(0), separation / -rate);
        const Vec2T<S> along = p0 + t * v - polygon.Vertices()[i];
        const S u = Dot(along, polygon.Edge(i));
        if (t < best && u >= S(0) && u <= LengthSquared(polygon.Edge(i)))
        {
            best = t;
            normal = n;
            axis = {AxisKind::FaceNormal, side, i};
        }
    }
    for (int k = 0; k < polygon.Count(); ++k)
    {
        const S t = EnterDisc(p0, v, polygon.Vertices()[k], r);
        if (t < best)
        {
            best = t;
            normal = Normalize(p0 + t * v - polygon.Vertices()[k]);
            axis = {AxisKind::VertexToCenter, side, k};
        }
    }
    return best;
}

/// The sweep of a pair with a circle in it (kContacts: with the contact point of a hit): the static test first
/// (the shapes interpenetrate at t = 0), then the centre's path against the rounded outline of the other shape, in
/// that shape's frame. `trace` is cleared, or null.
template <bool kContacts, typename S>
SweepResultT<S> SweepCircle(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                            const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    const Vec2T<S> velocity = vB - vA;
    const ManifoldT<S> initial = Collide(a, xfA, b, xfB);
    if (initial.overlap && initial.depth > S(0))
    {
        if (trace != nullptr)
        {
            trace->exit = SweepExit::AllAxesOverlap;
        }
        return Initial<kContacts>(initial);
    }
    const bool circleA = a.type == ShapeType::Circle;
    const CircleT<S>& circle = circleA ? a.circle : b.circle;
    const ShapeT<S>& other = circleA ? b : a;
    const TransformT<S>& xfCircle = circleA ? xfA : xfB;
    const TransformT<S>& xfOther = circleA ? xfB : xfA;
    const Vec2T<S> vCircle = circleA ? vA : vB;
    const Vec2T<S> vOther = circleA ? vB : vA;
    const int otherSide = circleA ? 1 : 0;

    // The circle's centre and motion relative to the other shape, in its frame.
    const Vec2T<S> p0 = InvRotate(xfOther.q, (xfCircle.p - xfOther.p) + Rotate(xfCircle.q, circle.center));
    const Vec2T<S> v = InvRotate(xfOther.q, vCircle - vOther);
    Vec2T<S> normal{};
    AxisRef axis{};
    S t;
    if (other.type == ShapeType::Polygon)
    {
        t = CastRounded(other.polygon, p0, v, circle.radius, normal, axis, otherSide);
    }
    else
    {
        t = EnterDisc(p0, v, other.circle.center, circle.radius + other.circle.radius);
        normal = Normalize(p0 + t * v - other.circle.center);
        axis = {AxisKind::CenterToCenter, -1, -1};
    }
    if (trace != nullptr)
    {
        // The axes of the rounded outline: the polygon's face normals (or the line of centres), oriented from A to
        // B, then the vertex axis that decided a hit on a rounded corner. The decision itself is the cast.
        auto ref = [](const ShapeT<S>& shape) {
            return shape.type == ShapeType::Polygon ? ShapeRef<S>{&shape.polygon, nullptr}
                                                    : ShapeRef<S>{nullptr, &shape.circle};
        };
        SweepRecorder<S> tracer(*trace, ref(a), xfA, ref(b), xfB, velocity);
        const S orient = circleA ? S(-1) : S(1);
        if (other.type == ShapeType::Polygon)
        {
            for (int i = 0; i < other.polygon.Count(); ++i)
            {
                tracer.AxisFromShapes({AxisKind::FaceNormal, otherSide, i},
                                      orient * Rotate(xfOther.q, other.polygon.Normal(i)));
            }
        }
        else
        {
            const Vec2T<S> centers = TransformPoint(xfB, b.circle.center) - TransformPoint(xfA, a.circle.center);
            tracer.AxisFromShapes({AxisKind::CenterToCenter, -1, -1}, Normalize(centers));
        }
        if (axis.kind == AxisKind::VertexToCenter && t <= S(1))
        {
            tracer.AxisFromShapes(axis, orient * Rotate(xfOther.q, normal));
        }
        tracer.Finish(SweepExit::RoundedOutline);
    }
    SweepResultT<S> result;
    if (!(t <= S(1)))
    {
        return result;
    }
    result.status = SweepStatus::Hit;
    result.toi = t;
    result.axis = axis;
    // The normal points out of the other shape towards the circle; from A to B it is reversed when A is the circle.
    const Vec2T<S> worldNormal = Rotate(xfOther.q, normal);
    result.normal = circleA ? -worldNormal : worldNormal;
    if constexpr (kContacts)
    {
        result.contactCount = 1;
        result.contacts[0].point =
            TransformPoint(Moved(xfOther, vOther, t), p0 + t * v - circle.radius * normal);
    }
    return result;
}

} // namespace satviz::detail
