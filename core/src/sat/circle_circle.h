// SPDX-License-Identifier: MIT
// satviz (private), chapter 8: circle against circle, the separating axis test with a single axis.
#pragma once

#include <satviz/manifold.h>
#include <satviz/shape.h>
#include <satviz/trace.h>

#include <cmath>

namespace satviz::detail
{

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
