// SPDX-License-Identifier: MIT
// satviz: the public entry point of speculative contacts (sat/speculative.h): Collide first, and the contacts of a
// pair not yet touching only when it is within the margin.

#include "entry.h"
#include "sat/speculative.h"
#include "widen_within.h"

#include <satviz/collide.h>

namespace satviz
{

namespace detail
{

template <typename S>
void Widen(ManifoldT<S>& m, const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
           S margin)
{
    const bool polygonA = a.type == ShapeType::Polygon;
    const bool polygonB = b.type == ShapeType::Polygon;
    if (polygonA && polygonB && m.overlap)
    {
        ReclipWithin(a.polygon, xfA, b.polygon, xfB, m, margin);
    }
    else if (polygonA && polygonB)
    {
        m = SpeculativePolygons(a.polygon, xfA, b.polygon, xfB, margin);
    }
    else if (polygonA)
    {
        m = SpeculativePolygonCircle(a.polygon, xfA, b.circle, xfB, 0, margin);
    }
    else if (polygonB)
    {
        m = SpeculativePolygonCircle(b.polygon, xfB, a.circle, xfA, 1, margin);
    }
    else
    {
        m = SpeculativeCircles(a.circle, xfA, b.circle, xfB, margin);
    }
}

template void Widen(ManifoldT<double>&, const ShapeT<double>&, const TransformT<double>&, const ShapeT<double>&,
                    const TransformT<double>&, double);
template void Widen(ManifoldT<float>&, const ShapeT<float>&, const TransformT<float>&, const ShapeT<float>&,
                    const TransformT<float>&, float);

} // namespace detail

template <typename S>
ManifoldT<S> CollideWithin(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
                           S margin)
{
    ManifoldT<S> m = Collide(a, xfA, b, xfB);
    detail::WidenWithin(m, a, xfA, b, xfB, margin);
    return m;
}

template ManifoldT<double> CollideWithin(const ShapeT<double>&, const TransformT<double>&, const ShapeT<double>&,
                                         const TransformT<double>&, double);
template ManifoldT<float> CollideWithin(const ShapeT<float>&, const TransformT<float>&, const ShapeT<float>&,
                                        const TransformT<float>&, float);

} // namespace satviz
