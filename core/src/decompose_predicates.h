// SPDX-License-Identifier: MIT
// satviz, private: the exact predicates of the convex decomposition, shared by its two methods.
#pragma once

#include <satviz/math.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz::decompose_detail
{

// MakePolygon's turn test: a turn whose cross product is within a few ulps of |e1| |e2| has no reliable sign and
// counts as straight; a piece whose every corner turns left by more passes MakePolygon.
template <typename S>
constexpr S kStraightTolerance = S(8) * std::numeric_limits<S>::epsilon();

template <typename S>
bool TurnsLeft(Vec2T<S> a, Vec2T<S> b, Vec2T<S> c)
{
    const Vec2T<S> e1 = b - a;
    const Vec2T<S> e2 = c - b;
    return Cross(e1, e2) > kStraightTolerance<S> * Length(e1) * Length(e2);
}

template <typename S>
bool IsStraight(Vec2T<S> a, Vec2T<S> b, Vec2T<S> c)
{
    const Vec2T<S> e1 = b - a;
    const Vec2T<S> e2 = c - b;
    return std::abs(Cross(e1, e2)) <= kStraightTolerance<S> * Length(e1) * Length(e2);
}

template <typename S>
int Orientation(Vec2T<S> a, Vec2T<S> b, Vec2T<S> c)
{
    const S cross = Cross(b - a, c - a);
    return cross > S(0) ? 1 : (cross < S(0) ? -1 : 0);
}

// p on the closed segment ab, given that the three are collinear.
template <typename S>
bool WithinBox(Vec2T<S> a, Vec2T<S> b, Vec2T<S> p)
{
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// The closed segments ab and cd meet (touching counts).
template <typename S>
bool SegmentsMeet(Vec2T<S> a, Vec2T<S> b, Vec2T<S> c, Vec2T<S> d)
{
    const int o1 = Orientation(a, b, c);
    const int o2 = Orientation(a, b, d);
    const int o3 = Orientation(c, d, a);
    const int o4 = Orientation(c, d, b);
    if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0)
    {
        if (o1 != 0 || o2 != 0)
        {
            return true;
        }
    }
    return (o1 == 0 && WithinBox(a, b, c)) || (o2 == 0 && WithinBox(a, b, d)) || (o3 == 0 && WithinBox(c, d, a)) ||
           (o4 == 0 && WithinBox(c, d, b));
}

} // namespace satviz::decompose_detail
