// SPDX-License-Identifier: MIT
// Short builders for hand-made test cases.
#pragma once

#include <satviz/sat.h>

#include <catch2/catch.hpp>

namespace satviz::testing
{

/// A validated box shape with half-widths hx, hy.
inline Shape BoxShape(double hx, double hy)
{
    PolygonResult result = MakeBox(hx, hy);
    REQUIRE(result.Ok());
    return MakeShape(result.polygon);
}

/// A circle shape centred on the body origin.
inline Shape DiscShape(double radius)
{
    Circle circle;
    circle.radius = radius;
    return MakeShape(circle);
}

/// A transform from a position and an angle.
inline Transform At(double x, double y, double angle = 0.0)
{
    return MakeTransform(Vec2{x, y}, angle);
}

/// A shape in float: a circle converted, a polygon converted and validated again (an empty polygon when rounding
/// made it invalid).
inline ShapeT<float> ToFloat(const Shape& shape)
{
    if (shape.type == ShapeType::Circle)
    {
        return MakeShape(
            CircleT<float>{ConvertVec<float>(shape.circle.center), static_cast<float>(shape.circle.radius)});
    }
    const PolygonResultT<float> converted = ConvertPolygon<float>(shape.polygon);
    return converted.Ok() ? MakeShape(converted.polygon) : ShapeT<float>{};
}

/// A transform in float.
inline TransformT<float> ToFloat(const Transform& xf)
{
    return {ConvertVec<float>(xf.p), {static_cast<float>(xf.q.c), static_cast<float>(xf.q.s)}};
}

} // namespace satviz::testing
