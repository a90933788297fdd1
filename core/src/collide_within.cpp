// SPDX-License-Identifier: MIT
// satviz: the public entry point of speculative contacts (sat/speculative.h): Collide first, and the contacts of a
// pair not yet touching only when it is within the margin.

#include "entry.h"
#include "sat/speculative.h"

#include <satviz/collide.h>

namespace satviz
{

template <typename S>
ManifoldT<S> CollideWithin(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
                           S margin)
{
    const ManifoldT<S> m = Collide(a, xfA, b, xfB);
    const bool polygonA = a.type == ShapeType::Polygon;
    const bool polygonB = b.type == ShapeType::Polygon;
    // Collide's gap is the separation of the first separating axis it met, at most the largest one: beyond the
    // margin it already proves the pair apart by more. An overlapping pair with two contacts kept both ends of its
    // clipped incident edge, and a circle has one contact: nothing is left to add.
    if (m.gap > margin || (m.overlap && (m.contactCount == 2 || !(polygonA && polygonB))))
    {
        return m;
    }
    if (polygonA && polygonB)
    {
        return m.overlap ? detail::ReclippedWithin(a.polygon, xfA, b.polygon, xfB, m, margin)
                         : detail::SpeculativePolygons(a.polygon, xfA, b.polygon, xfB, margin);
    }
    if (polygonA)
    {
        return detail::SpeculativePolygonCircle(a.polygon, xfA, b.circle, xfB, 0, margin);
    }
    if (polygonB)
    {
        return detail::SpeculativePolygonCircle(b.polygon, xfB, a.circle, xfA, 1, margin);
    }
    return detail::SpeculativeCircles(a.circle, xfA, b.circle, xfB, margin);
}

template ManifoldT<double> CollideWithin(const ShapeT<double>&, const TransformT<double>&, const ShapeT<double>&,
                                         const TransformT<double>&, double);
template ManifoldT<float> CollideWithin(const ShapeT<float>&, const TransformT<float>&, const ShapeT<float>&,
                                        const TransformT<float>&, float);

} // namespace satviz
