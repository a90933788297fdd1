// SPDX-License-Identifier: MIT
// satviz: the public entry point of the swept test for translating shapes that finds the time of impact alone, without
// the contact points of a hit (the same test as Sweep in sweep.cpp, through sweep_shapes.h).

#include "sweep_shapes.h"

namespace satviz
{

template <typename S>
SweepResultT<S> SweepTime(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                          const TransformT<S>& xfB, Vec2T<S> vB, SweepTraceT<S>* trace)
{
    return detail::SweepShapes<false>(a, xfA, vA, b, xfB, vB, trace);
}

template SweepResultT<double> SweepTime(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                        const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                        SweepTraceT<double>*);
template SweepResultT<float> SweepTime(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                       const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                       SweepTraceT<float>*);

} // namespace satviz
