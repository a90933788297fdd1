// SPDX-License-Identifier: MIT
// satviz (private): what the public entry points share: choosing the tracer once per call and dispatching shapes.
#pragma once

#include "sat/cpu_dispatch.h"
#include "sat/tracer.h"

#include <satviz/shape.h>
#include <satviz/sweep.h>
#include <satviz/trace.h>

#include <type_traits>

namespace satviz::detail
{

template <typename S>
ShapeRef<S> Ref(const PolygonT<S>& polygon)
{
    return {&polygon, nullptr};
}

template <typename S>
ShapeRef<S> Ref(const CircleT<S>& circle)
{
    return {nullptr, &circle};
}

// Runs `query` with a recorder filling `trace`. Kept out of line and cold, so that the untraced path of the
// caller carries neither the recorder's stack frame nor its code.
template <typename S, typename A, typename B, typename Query>
[[gnu::noinline, gnu::cold]] auto Traced(TraceT<S>& trace, const A& a, const TransformT<S>& xfA, const B& b,
                                         const TransformT<S>& xfB, Query& query)
{
    TraceRecorder<S> tracer(trace, Ref(a), xfA, Ref(b), xfB);
    return query(tracer);
}

// Runs `query` with the null tracer, compiled as one function: everything it calls is inlined into it, which keeps
// the fast path's code together.
template <typename Query>
[[gnu::flatten]] auto RunScalar(Query& query)
{
    NullTracer tracer;
    return query(tracer);
}

#if SATVIZ_WIDE
// Runs `query` with the null tracer of the wide scans, compiled for AVX2 as one function: everything it calls is
// inlined into it, so the whole query is in the instruction set the scans need.
template <typename Query>
[[gnu::target("avx2"), gnu::flatten]] auto RunWide(Query& query)
{
    WideNullTracer tracer;
    return query(tracer);
}

// RunWide for the queries whose face loops take 512-bit vectors, compiled for AVX-512 as well.
template <typename Query>
[[gnu::target("avx2,avx512f"), gnu::flatten]] auto RunWide512(Query& query)
{
    Wide512NullTracer tracer;
    return query(tracer);
}
#endif

// The instructions an untraced query runs on: 512-bit face loops for double where `wide512` and the processor has
// them, the wide scans where it has those and `wide`, else the baseline, which a traced call says in its trace.
// The untraced branches of WithTracer and WithSweepTracer take the same decision inline, on their fast path (an
// enum chosen here and switched on there would add that switch to every untraced query); a property test holds
// the two together (tests/test_wide.cpp).
template <typename S>
InstructionPath UntracedPath(bool wide, bool wide512)
{
#if SATVIZ_WIDE
    if (std::is_same_v<S, double> && wide512 && HasWide512())
    {
        return InstructionPath::Avx512;
    }
    if (wide && HasWideVectors())
    {
        return InstructionPath::Avx2;
    }
#else
    (void)wide;
    (void)wide512;
#endif
    return InstructionPath::Baseline;
}

// Runs `query(tracer)` with the null tracer (on the wide scans where the processor has them, unless kWide is
// false; for double, with 512-bit face loops where it has those too and kWide512 is set), or with a recorder
// filling `trace` when it is non-null.
template <bool kWide = true, bool kWide512 = false, typename S, typename A, typename B, typename Query>
auto WithTracer(TraceT<S>* trace, const A& a, const TransformT<S>& xfA, const B& b, const TransformT<S>& xfB,
                Query&& query)
{
    if (trace == nullptr)
    {
#if SATVIZ_WIDE
        if constexpr (kWide512 && std::is_same_v<S, double>)
        {
            if (HasWide512())
            {
                return RunWide512(query);
            }
        }
        if (kWide && HasWideVectors())
        {
            return RunWide(query);
        }
#endif
        NullTracer tracer;
        return query(tracer);
    }
    auto result = Traced(*trace, a, xfA, b, xfB, query);
    trace->untracedPath = UntracedPath<S>(kWide, kWide512);
    return result;
}

// WithTracer for the sweep: `query(tracer)` with the null tracer, each instruction set's path one function (on
// 512-bit face loops for double where `wide512` and the processor has them, on the wide scans where it has those),
// or with a recorder filling `trace` when it is non-null; `velocity` is B's motion relative to A.
template <typename S, typename A, typename B, typename Query>
auto WithSweepTracer(SweepTraceT<S>* trace, const A& a, const TransformT<S>& xfA, const B& b, const TransformT<S>& xfB,
                     Vec2T<S> velocity, bool wide512, Query&& query)
{
    if (trace == nullptr)
    {
#if SATVIZ_WIDE
        if constexpr (std::is_same_v<S, double>)
        {
            if (wide512 && HasWide512())
            {
                return RunWide512(query);
            }
        }
        if (HasWideVectors())
        {
            return RunWide(query);
        }
#endif
        return RunScalar(query);
    }
    SweepRecorder<S> tracer(*trace, Ref(a), xfA, Ref(b), xfB, velocity);
    auto result = query(tracer);
    trace->untracedPath = UntracedPath<S>(true, wide512);
    return result;
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

} // namespace satviz::detail
