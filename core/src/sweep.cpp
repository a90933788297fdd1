// SPDX-License-Identifier: MIT
// satviz: the public entry point of the swept test for translating shapes with the contact points of a hit. It picks
// the tracer once per call (null, or the recorder when a trace is requested) and runs the single template
// implementation in core/src/sat/ (sweep_shapes.h); SweepTime, the same test without contact points, is in
// sweep_time.cpp.

#include "sweep_shapes.h"

namespace satviz
{

template <typename S>
SweepResultT<S> Sweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                      const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    return detail::SweepShapes<true>(a, xfA, vA, b, xfB, vB, trace);
}

template SweepResultT<double> Sweep(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                    const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                    SweepTraceT<double>*);
template SweepResultT<float> Sweep(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>, const ShapeT<float>&,
                                   const TransformT<float>&, Vec2T<float>, SweepTraceT<float>*);

} // namespace satviz
