// SPDX-License-Identifier: MIT
// satviz: a segment cast against a concave shape: the least fraction over the pieces whose boxes the segment's box
// overlaps.
#include "concave_sides.h"

#include <satviz/concave.h>
#include <satviz/raycast.h>

namespace satviz
{

using namespace concave_detail;

template <typename S>
ConcaveRayHitT<S> RayCast(const ConcaveT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2)
{
    ConcaveRayHitT<S> out;
    const Side<S> side = SideOf(shape, xf, 0);
    const BoundsT<S> segment = Grow(Grow(Empty<S>(), p1), p2);
    bool bestOnSeam = false;
    for (int i = 0; i < side.Count(); ++i)
    {
        if (!BoxesOverlap(WorldBox(side, i), segment))
        {
            continue;
        }
        const RayHitT<S> hit = RayCast(side.Part(i), xf, p1, p2);
        if (!hit.hit)
        {
            continue;
        }
        if (hit.startsInside)
        {
            out.hit = hit;
            out.piece = i;
            return out;
        }
        const bool onSeam = hit.edge >= 0 && shape.parts[i].internal[hit.edge];
        if (!out.hit.hit || hit.fraction < out.hit.fraction ||
            (hit.fraction == out.hit.fraction && bestOnSeam && !onSeam))
        {
            out.hit = hit;
            out.piece = i;
            bestOnSeam = onSeam;
        }
    }
    return out;
}

template ConcaveRayHitT<double> RayCast(const ConcaveT<double>&, const TransformT<double>&, Vec2T<double>,
                                        Vec2T<double>);
template ConcaveRayHitT<float> RayCast(const ConcaveT<float>&, const TransformT<float>&, Vec2T<float>, Vec2T<float>);

} // namespace satviz
