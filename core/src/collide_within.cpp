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
bool WidenWithin(ManifoldT<S>& m, const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                 const TransformT<S>& xfB, S margin)
{
    const bool polygonA = a.type == ShapeType::Polygon;
    const bool polygonB = b.type == ShapeType::Polygon;
    // Collide's gap is the separation of the first separating axis it met, at most the largest one: beyond the
    // margin it already proves the pair apart by more. An overlapping pair with two contacts kept both ends of its
    // clipped incident edge, and a circle has one contact: nothing is left to add.
    if (m.gap > margin || (m.overlap && (m.contactCount == 2 || !(polygonA && polygonB))))
    {
        return false;
    }
    if (polygonA && polygonB)
    {
        m = m.overlap ? ReclippedWithin(a.polygon, xfA, b.polygon, xfB, m, margin)
                      : SpeculativePolygons(a.polygon, xfA, b.polygon, xfB, margin);
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
    return true;
}

template bool WidenWithin(ManifoldT<double>&, const ShapeT<double>&, const TransformT<double>&, const ShapeT<double>&,
                          const TransformT<double>&, double);
template bool WidenWithin(ManifoldT<float>&, const ShapeT<float>&, const TransformT<float>&, const ShapeT<float>&,
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
