// SPDX-License-Identifier: MIT
// satviz: the public entry points of the SAT queries. Each one picks the tracer once per call (null, or the
// recorder when a trace is requested) and runs the single template implementation in sat_impl.h.

#include "sat_impl.h"

#include <satviz/cache.h>
#include <satviz/collide.h>

namespace satviz
{
namespace
{

template <typename S>
detail::ShapeRef<S> Ref(const PolygonT<S>& polygon)
{
    return {&polygon, nullptr};
}

template <typename S>
detail::ShapeRef<S> Ref(const CircleT<S>& circle)
{
    return {nullptr, &circle};
}

// Runs `query` with a recorder filling `trace`. Kept out of line and cold, so that the untraced path of the
// caller carries neither the recorder's stack frame nor its code.
template <typename S, typename A, typename B, typename Query>
[[gnu::noinline, gnu::cold]] auto Traced(TraceT<S>& trace, const A& a, const TransformT<S>& xfA, const B& b,
                                         const TransformT<S>& xfB, Query& query)
{
    detail::TraceRecorder<S> tracer(trace, Ref(a), xfA, Ref(b), xfB);
    return query(tracer);
}

// Runs `query(tracer)` with the null tracer, or with a recorder filling `trace` when it is non-null.
template <typename S, typename A, typename B, typename Query>
auto WithTracer(TraceT<S>* trace, const A& a, const TransformT<S>& xfA, const B& b, const TransformT<S>& xfB,
                Query&& query)
{
    if (trace == nullptr)
    {
        detail::NullTracer tracer;
        return query(tracer);
    }
    return Traced(*trace, a, xfA, b, xfB, query);
}

// Calls query(shapeA, shapeB) with the polygon or circle each shape holds.
template <typename S, typename Query>
auto DispatchShapes(const ShapeT<S>& a, const ShapeT<S>& b, Query&& query)
{
    const bool polygonA = a.type == ShapeType::Polygon;
    const bool polygonB = b.type == ShapeType::Polygon;
    if (polygonA && polygonB)
    {
        return query(a.polygon, b.polygon);
    }
    if (polygonA)
    {
        return query(a.polygon, b.circle);
    }
    if (polygonB)
    {
        return query(a.circle, b.polygon);
    }
    return query(a.circle, b.circle);
}

} // namespace

template <typename S>
bool Overlap(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB,
                      [&](auto& tracer) { return detail::OverlapPolygons(a, xfA, b, xfB, tracer); });
}

template <typename S>
bool Overlap(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
             SatCache& cache)
{
    return detail::OverlapPolygonsCached(a, xfA, b, xfB, cache.axis, cache.support);
}

template <typename S>
bool Overlap(const PolygonT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB, [&](auto& tracer) {
        return detail::CollidePolygonCircle<false>(a, xfA, b, xfB, 0, tracer).overlap;
    });
}

template <typename S>
bool Overlap(const CircleT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB, [&](auto& tracer) {
        return detail::CollidePolygonCircle<false>(b, xfB, a, xfA, 1, tracer).overlap;
    });
}

template <typename S>
bool Overlap(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB,
                      [&](auto& tracer) { return detail::CollideCircles<false>(a, xfA, b, xfB, tracer).overlap; });
}

template <typename S>
bool Overlap(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace)
{
    return DispatchShapes(a, b, [&](const auto& sa, const auto& sb) { return Overlap(sa, xfA, sb, xfB, trace); });
}

template <typename S>
ManifoldT<S> Collide(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace)
{
    return WithTracer(trace, a, xfA, b, xfB,
                      [&](auto& tracer) { return detail::CollidePolygons(a, xfA, b, xfB, tracer); });
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
    template bool Overlap(const PolygonT<S>&, const TransformT<S>&, const PolygonT<S>&, const TransformT<S>&,          \
                          SatCache&);                                                                                  \
    template bool Overlap(const PolygonT<S>&, const TransformT<S>&, const PolygonT<S>&, const TransformT<S>&,          \
                          TraceT<S>*);                                                                                 \
    template bool Overlap(const PolygonT<S>&, const TransformT<S>&, const CircleT<S>&, const TransformT<S>&,           \
                          TraceT<S>*);                                                                                 \
    template bool Overlap(const CircleT<S>&, const TransformT<S>&, const PolygonT<S>&, const TransformT<S>&,           \
                          TraceT<S>*);                                                                                 \
    template bool Overlap(const CircleT<S>&, const TransformT<S>&, const CircleT<S>&, const TransformT<S>&,            \
                          TraceT<S>*);                                                                                 \
    template bool Overlap(const ShapeT<S>&, const TransformT<S>&, const ShapeT<S>&, const TransformT<S>&, TraceT<S>*); \
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
