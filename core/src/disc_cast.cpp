// SPDX-License-Identifier: MIT
// satviz: thick bullets, a disc cast along a segment, by the swept test of a circle against the still shape.

#include <satviz/disc_cast.h>

namespace satviz
{
namespace
{

template <typename S>
DiscHitT<S> FromSweep(const SweepResultT<S>& sweep, Vec2T<S> p1, Vec2T<S> p2, S radius, int piece)
{
    DiscHitT<S> out;
    if (sweep.status == SweepStatus::Miss)
    {
        return out;
    }
    out.hit = true;
    out.piece = piece;
    if (sweep.status == SweepStatus::Overlapping)
    {
        out.startsInside = true;
        out.center = p1;
        out.normal = sweep.initial.normal;
        out.point = p1 - radius * out.normal;
        return out;
    }
    out.fraction = sweep.toi;
    out.center = p1 + sweep.toi * (p2 - p1);
    out.normal = sweep.normal;
    // The disc touches the surface at the point of its outline facing the shape.
    out.point = out.center - radius * sweep.normal;
    return out;
}

template <typename S>
ShapeT<S> Disc(S radius)
{
    return MakeShape(CircleT<S>{{}, radius});
}

} // namespace

template <typename S>
DiscHitT<S> CastDisc(const ShapeT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2, S radius)
{
    const SweepResultT<S> sweep = Sweep(shape, xf, Vec2T<S>{}, Disc(radius), TransformT<S>{p1, {}}, p2 - p1);
    return FromSweep(sweep, p1, p2, radius, -1);
}

template <typename S>
DiscHitT<S> CastDisc(const ConcaveT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2, S radius)
{
    const ConcaveSweepResultT<S> sweep = Sweep(shape, xf, Vec2T<S>{}, Disc(radius), TransformT<S>{p1, {}}, p2 - p1);
    return FromSweep(sweep.result, p1, p2, radius, sweep.pieceA);
}

template DiscHitT<double> CastDisc(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>, Vec2T<double>,
                                   double);
template DiscHitT<float> CastDisc(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>, Vec2T<float>, float);
template DiscHitT<double> CastDisc(const ConcaveT<double>&, const TransformT<double>&, Vec2T<double>, Vec2T<double>,
                                   double);
template DiscHitT<float> CastDisc(const ConcaveT<float>&, const TransformT<float>&, Vec2T<float>, Vec2T<float>, float);

} // namespace satviz
