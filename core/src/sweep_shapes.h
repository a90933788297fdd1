// SPDX-License-Identifier: MIT
// satviz (private): the swept test's one implementation behind Sweep and SweepTime (Ericson, Real-Time Collision
// Detection, 5.5.2 for polygons; 5.3.2 and 5.5.7 for the ray against a sphere and the rounded shapes of circles).
// Each entry point is compiled in a file of its own (sweep.cpp, sweep_time.cpp): each flattens every tracer and
// processor path of the polygon sweep, and two files build in parallel.
#pragma once

#include "entry.h"
#include "sat/sweep_circle.h"
#include "sat/sweep_contacts.h"
#include "sat/sweep_polygons.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

namespace satviz::detail
{
// Sweep (kContacts) and SweepTime: one body, the contact points of a hit computed or not.
template <bool kContacts, typename S>
inline SweepResultT<S> SweepShapes(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                                   const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    if (trace != nullptr)
    {
        trace->Clear();
    }
    const Vec2T<S> velocity = vB - vA;
    if (velocity.x == S(0) && velocity.y == S(0))
    {
        // Nothing moves relative to the other: the static test decides, and no sweep is run.
        if (trace != nullptr)
        {
            trace->exit = SweepExit::NotMoving;
        }
        return Initial<kContacts>(satviz::Collide(a, xfA, b, xfB));
    }
    if (a.type == ShapeType::Polygon && b.type == ShapeType::Polygon)
    {
        // The 512-bit face loops serve polygons of up to 8 vertices.
        const bool small = a.polygon.Count() <= 8 && b.polygon.Count() <= 8;
        return WithSweepTracer(trace, a.polygon, xfA, b.polygon, xfB, velocity, small, [&](auto& tracer) {
            return SweepPolygons<kContacts>(a.polygon, xfA, vA, b.polygon, xfB, vB, tracer);
        });
    }
    return SweepCircle<kContacts>(a, xfA, vA, b, xfB, vB, trace);
}

} // namespace satviz::detail
