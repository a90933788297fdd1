// SPDX-License-Identifier: MIT
// satviz, private: a side of a query on concave shapes (one convex shape, or the pieces of a concave one, placed),
// and the boxes of its parts that the queries' broadphase compares.
#pragma once

#include <satviz/concave.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz::concave_detail
{

// A side of a query: one convex shape, or the pieces of a concave one, placed by xf.
template <typename S>
struct Side
{
    const ShapeT<S>* single = nullptr;
    const ConcaveT<S>* concave = nullptr;
    TransformT<S> xf{};
    int index = 0; // 0 for A, 1 for B (AxisRef::shape)

    int Count() const { return concave != nullptr ? static_cast<int>(concave->parts.size()) : 1; }
    const ShapeT<S>& Part(int i) const { return concave != nullptr ? concave->parts[i].shape : *single; }
    const std::vector<bool>* Internal(int i) const
    {
        return concave != nullptr ? &concave->parts[i].internal : nullptr;
    }
    int Piece(int i) const { return concave != nullptr ? i : -1; }
};

template <typename S>
BoundsT<S> Grow(BoundsT<S> box, Vec2T<S> p)
{
    box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y)};
    box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y)};
    return box;
}

template <typename S>
BoundsT<S> Empty()
{
    const S inf = std::numeric_limits<S>::infinity();
    return {{inf, inf}, {-inf, -inf}};
}

// The box of part i in world coordinates: the box of its corners as placed, widened by a few ulps of its magnitude
// so that rounding in the corners' transform cannot part boxes of shapes that touch. Each piece's own box, however
// the body is turned: the box of its box in the body frame, turned, grows past the piece by up to half its size (a
// pair the broadphase should part was tested, and the pieces figure drew boxes that did not hug the pieces).
template <typename S>
BoundsT<S> WorldBox(const Side<S>& side, int i)
{
    BoundsT<S> box = Empty<S>();
    const ShapeT<S>& part = side.Part(i);
    if (part.type == ShapeType::Polygon)
    {
        for (const Vec2T<S>& v : part.polygon.Vertices())
        {
            box = Grow(box, TransformPoint(side.xf, v));
        }
    }
    else
    {
        const Vec2T<S> c = TransformPoint(side.xf, part.circle.center);
        const S r = part.circle.radius;
        box = {{c.x - r, c.y - r}, {c.x + r, c.y + r}};
    }
    const S magnitude = std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.max.x), std::abs(box.max.y)});
    const S pad = S(16) * std::numeric_limits<S>::epsilon() * magnitude;
    box.min = box.min - Vec2T<S>{pad, pad};
    box.max = box.max + Vec2T<S>{pad, pad};
    return box;
}

template <typename S>
bool BoxesOverlap(const BoundsT<S>& a, const BoundsT<S>& b)
{
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

template <typename S>
Side<S> SideOf(const ShapeT<S>& shape, const TransformT<S>& xf, int index)
{
    Side<S> side;
    side.single = &shape;
    side.xf = xf;
    side.index = index;
    return side;
}

template <typename S>
Side<S> SideOf(const ConcaveT<S>& concave, const TransformT<S>& xf, int index)
{
    Side<S> side;
    side.concave = &concave;
    side.xf = xf;
    side.index = index;
    return side;
}

} // namespace satviz::concave_detail
