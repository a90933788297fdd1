// SPDX-License-Identifier: MIT
// satviz: the public entry points of the manifold query. Each one picks the tracer once per call (null, or the
// recorder when a trace is requested) and runs the single template implementation in core/src/sat/.

#include "entry.h"
#include "sat/circle_circle.h"
#include "sat/polygon_circle.h"
#include "sat/polygon_polygon.h"

#include <satviz/collide.h>

namespace satviz
{
using detail::DispatchShapes;
using detail::WithTracer;

template <typename S>
[[gnu::flatten]] ManifoldT<S> Collide(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                                      const TransformT<S>& xfB, TraceT<S>* trace)
{
    const auto query = [&](auto& tracer) { return detail::CollidePolygons(a, xfA, b, xfB, tracer); };
    // The 512-bit face queries serve polygons of up to 8 vertices.
    if (a.Count() <= PolygonT<S>::kInlineVertices && b.Count() <= PolygonT<S>::kInlineVertices)
    {
        return WithTracer<true, true>(trace, a, xfA, b, xfB, query);
    }
    return WithTracer(trace, a, xfA, b, xfB, query);
}

template <typename S>
ManifoldT<S> Collide(const PolygonT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB,
                      [&](auto& tracer) { return detail::CollidePolygonCircle<true>(a, xfA, b, xfB, 0, tracer); });
}

template <typename S>
ManifoldT<S> Collide(const CircleT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB,
                      [&](auto& tracer) { return detail::CollidePolygonCircle<true>(b, xfB, a, xfA, 1, tracer); });
}

template <typename S>
ManifoldT<S> Collide(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB,
                      [&](auto& tracer) { return detail::CollideCircles<true>(a, xfA, b, xfB, tracer); });
}

template <typename S>
ManifoldT<S> Collide(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace)
{
    return DispatchShapes(a, b, [&](const auto& sa, const auto& sb) { return Collide(sa, xfA, sb, xfB, trace); });
}

#define SATVIZ_INSTANTIATE(S)                                                                                          \
    template ManifoldT<S> Collide(const PolygonT<S>&, const TransformT<S>&, const PolygonT<S>&, const TransformT<S>&,  \
                                  TraceT<S>*);                                                                         \
    template ManifoldT<S> Collide(const PolygonT<S>&, const TransformT<S>&, const CircleT<S>&, const TransformT<S>&,   \
                                  TraceT<S>*);                                                                         \
    template ManifoldT<S> Collide(const CircleT<S>&, const TransformT<S>&, const PolygonT<S>&, const TransformT<S>&,   \
                                  TraceT<S>*);                                                                         \
    template ManifoldT<S> Collide(const CircleT<S>&, const TransformT<S>&, const CircleT<S>&, const TransformT<S>&,    \
                                  TraceT<S>*);                                                                         \
    template ManifoldT<S> Collide(const ShapeT<S>&, const TransformT<S>&, const ShapeT<S>&, const TransformT<S>&,      \
                                  TraceT<S>*);

SATVIZ_INSTANTIATE(double)
SATVIZ_INSTANTIATE(float)

#undef SATVIZ_INSTANTIATE

} // namespace satviz
