// SPDX-License-Identifier: MIT
// satviz: circles, and a shape that is either a polygon or a circle.
#pragma once

#include <satviz/math.h>
#include <satviz/polygon.h>

namespace satviz
{

/// A circle in its body frame.
template <typename S>
struct CircleT
{
    Vec2T<S> center{}; ///< centre in the body frame
    S radius{};        ///< radius, > 0
};

/// Double-precision circle.
using Circle = CircleT<double>;

/// The kind of a shape.
enum class ShapeType
{
    Polygon, ///< a convex polygon
    Circle,  ///< a circle
};

/// A polygon or a circle: what a body of a scene carries. Only the member named by `type` is meaningful.
template <typename S>
struct ShapeT
{
    ShapeType type = ShapeType::Circle; ///< which member holds the shape
    PolygonT<S> polygon;                ///< the polygon, when type == Polygon
    CircleT<S> circle;                  ///< the circle, when type == Circle
};

/// Double-precision shape.
using Shape = ShapeT<double>;

/// A shape holding a polygon.
template <typename S>
ShapeT<S> MakeShape(PolygonT<S> polygon)
{
    ShapeT<S> shape;
    shape.type = ShapeType::Polygon;
    shape.polygon = std::move(polygon);
    return shape;
}

/// A shape holding a circle.
template <typename S>
ShapeT<S> MakeShape(CircleT<S> circle)
{
    ShapeT<S> shape;
    shape.type = ShapeType::Circle;
    shape.circle = circle;
    return shape;
}

} // namespace satviz
