// SPDX-License-Identifier: MIT
// satviz: collide and slide over the swept test.

#include <satviz/collide.h>
#include <satviz/slide.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{

template <typename S>
S DefaultSkin(const ShapeT<S>& mover, const TransformT<S>& xf)
{
    S size = S(0);
    if (mover.type == ShapeType::Circle)
    {
        size = mover.circle.radius + Length(mover.circle.center);
    }
    else
    {
        for (const Vec2T<S>& v : mover.polygon.Vertices())
        {
            size = std::max(size, Length(v));
        }
    }
    const S position = std::max(std::abs(xf.p.x), std::abs(xf.p.y));
    return std::max(S(1e-7) * size, S(64) * std::numeric_limits<S>::epsilon() * position);
}

template <typename S>
SlideResultT<S> MoveAndSlide(const ShapeT<S>& mover, const TransformT<S>& xf, Vec2T<S> displacement,
                             const ObstacleT<S>* obstacles, int obstacleCount, S skin, int maxContacts)
{
    SlideResultT<S> result;
    result.xf = xf;
    const int budget = std::clamp(maxContacts, 0, kMaxSlideContacts);
    auto record = [&](Vec2T<S> normal, int obstacle) {
        result.normals[result.contactCount] = normal;
        result.obstacles[result.contactCount] = obstacle;
        ++result.contactCount;
    };
    const S gap = skin >= S(0) ? skin : DefaultSkin(mover, xf);

    // Out of anything the mover starts inside (a contact), and up to the skin from anything it starts touching or
    // closer than the skin to (no contact: it is where the last step left it, or placed there). A sweep from
    // zero distance would stop at once against a surface that is flush with the one it rests on only up to
    // rounding (the next tile of a floor).
    for (int k = 0; k < obstacleCount && result.contactCount < budget; ++k)
    {
        const ManifoldT<S> m = Collide(mover, result.xf, *obstacles[k].shape, obstacles[k].xf);
        if (m.overlap && m.depth > S(0))
        {
            result.xf.p = result.xf.p - (m.depth + gap) * m.normal;
            record(m.normal, k);
        }
        else if (m.overlap || m.gap < gap)
        {
            result.xf.p = result.xf.p - ((m.overlap ? S(0) : -m.gap) + gap) * m.normal;
        }
    }

    Vec2T<S> remaining = displacement;
    while (result.contactCount < budget && (remaining.x != S(0) || remaining.y != S(0)))
    {
        S first = std::numeric_limits<S>::infinity();
        int hitObstacle = -1;
        Vec2T<S> normal{};
        for (int k = 0; k < obstacleCount; ++k)
        {
            const SweepResultT<S> sweep =
                SweepTime(mover, result.xf, remaining, *obstacles[k].shape, obstacles[k].xf, Vec2T<S>{});
            if (sweep.status == SweepStatus::Hit && sweep.toi < first)
            {
                first = sweep.toi;
                hitObstacle = k;
                normal = sweep.normal;
            }
        }
        if (hitObstacle < 0)
        {
            result.xf.p = result.xf.p + remaining;
            remaining = Vec2T<S>{};
            break;
        }
        // Stop `gap` short of the surface along its normal: the closing speed along it is Dot(remaining, normal).
        // A hit implies closing > 0; should rounding say otherwise, stay put rather than step through.
        const S closing = Dot(remaining, normal);
        const S stop = closing > S(0) ? std::max(S(0), first - gap / closing) : S(0);
        result.xf.p = result.xf.p + stop * remaining;
        // A hit closer than the skin (stop clamped at 0): back off along the normal to the skin.
        const S shortfall = closing > S(0) ? gap - (first - stop) * closing : S(0);
        if (shortfall > S(0))
        {
            result.xf.p = result.xf.p - shortfall * normal;
        }
        Vec2T<S> rest = (S(1) - stop) * remaining;
        const S into = Dot(rest, normal);
        if (into > S(0))
        {
            rest = rest - into * normal;
        }
        remaining = rest;
        record(normal, hitObstacle);
    }
    result.remaining = remaining;
    return result;
}

template double DefaultSkin(const ShapeT<double>&, const TransformT<double>&);
template float DefaultSkin(const ShapeT<float>&, const TransformT<float>&);
template SlideResultT<double> MoveAndSlide(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                           const ObstacleT<double>*, int, double, int);
template SlideResultT<float> MoveAndSlide(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                          const ObstacleT<float>*, int, float, int);

} // namespace satviz
