// SPDX-License-Identifier: MIT
// satviz: the public entry points of the swept test for translating shapes (Ericson, Real-Time Collision Detection,
// 5.5.2 for polygons; 5.3.2 and 5.5.7 for the ray against a sphere and the rounded shapes of circles). Each one picks
// the tracer once per call (null, or the recorder when a trace is requested) and runs the single template
// implementation in core/src/sat/.

#include "entry.h"
#include "sat/sweep_circle.h"
#include "sat/sweep_contacts.h"
#include "sat/sweep_polygons.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

namespace satviz
{
namespace
{
// Sweep (kContacts) and SweepTime: one body, the contact points of a hit computed or not.
template <bool kContacts, typename S>
SweepResultT<S> SweepShapes(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
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
        return detail::Initial<kContacts>(Collide(a, xfA, b, xfB));
    }
    if (a.type == ShapeType::Polygon && b.type == ShapeType::Polygon)
    {
        // The 512-bit face loops serve polygons of up to 8 vertices.
        const bool small = a.polygon.Count() <= 8 && b.polygon.Count() <= 8;
        return detail::WithSweepTracer(trace, a.polygon, xfA, b.polygon, xfB, velocity, small, [&](auto& tracer) {
            return detail::SweepPolygons<kContacts>(a.polygon, xfA, vA, b.polygon, xfB, vB, tracer);
        });
    }
    return detail::SweepCircle<kContacts>(a, xfA, vA, b, xfB, vB, trace);
}
} // namespace


template <typename S>
SweepResultT<S> Sweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                      const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    return SweepShapes<true>(a, xfA, vA, b, xfB, vB, trace);
}

template <typename S>
SweepResultT<S> SweepTime(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                          const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    return SweepShapes<false>(a, xfA, vA, b, xfB, vB, trace);
}

template SweepResultT<double> Sweep(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                    const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                    SweepTraceT<double>*);
template SweepResultT<float> Sweep(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>, const ShapeT<float>&,
                                   const TransformT<float>&, Vec2T<float>, SweepTraceT<float>*);
template SweepResultT<double> SweepTime(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                        const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                        SweepTraceT<double>*);
template SweepResultT<float> SweepTime(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                       const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                       SweepTraceT<float>*);

} // namespace satviz

